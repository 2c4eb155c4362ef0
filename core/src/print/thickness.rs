//! Local thickness of a region and of the space around it, as the
//! shrinking-ball method defines it: for a point on the outline, the largest
//! disc that touches the outline there and stays inside the material (or
//! inside the empty space) has the local width as its diameter. The disc is
//! found in one pass over the edges near it, in closed form per edge
//! (`EdgeGrid::largest_empty_disc`), rather than by shrinking a ball
//! query after query.

use glam::DVec2;
use rayon::prelude::*;

use super::edge_grid::EdgeGrid;
use crate::geom::Region;

/// Which side of the outline is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Inside the material: how thick a feature is.
    Material,
    /// Outside it: how wide a gap is.
    Gap,
}

/// A place narrower than the width asked for: the disc that fits there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Narrow {
    /// Where the disc touches the outline at the sampled point, mm.
    pub from_mm: DVec2,
    /// Where it touches the outline across, mm.
    pub to_mm: DVec2,
    /// The disc's centre, mm.
    pub centre_mm: DVec2,
    /// Its diameter: the local width, mm.
    pub width_mm: f64,
    /// How far apart the two contacts are along the outline, mm (infinite
    /// when they lie on different rings): small at a sharp tip or notch,
    /// large across a neck or a long strip.
    pub apart_along_outline_mm: f64,
}

/// A contact closer than this many disc radii along the same ring is the
/// outline turning (a corner, a rounded end), not material across.
const LOCAL_ARC_RADII: f64 = 3.0;

/// Every place on `side` of the outline of `region` narrower than
/// `width_mm`: the outline is sampled every `spacing_mm`, and at each sample
/// the largest disc tangent there that holds no outline point is found.
/// Discs stopped by the outline's own turn close by (a corner, the rounded
/// end of a stroke) are not narrow places; discs stopped by material
/// across are.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::print::{Side, narrow_places};
/// // A 10 × 0.2 mm bar.
/// let bar = vec![DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0), DVec2::new(10.0, 0.2), DVec2::new(0.0, 0.2)];
/// let region = Region::new(vec![Polygon { outer: bar, holes: vec![] }]);
/// let narrow = narrow_places(&region, Side::Material, 0.4, 0.05);
/// assert!(!narrow.is_empty());
/// assert!(narrow.iter().all(|n| (n.width_mm - 0.2).abs() < 1e-6));
/// assert!(narrow_places(&region, Side::Material, 0.15, 0.05).is_empty());
/// ```
pub fn narrow_places(region: &Region, side: Side, width_mm: f64, spacing_mm: f64) -> Vec<Narrow> {
    if region.is_empty() || width_mm <= 0.0 || spacing_mm <= 0.0 {
        return Vec::new();
    }
    let grid = EdgeGrid::new(region, width_mm.max(spacing_mm));
    let max_radius = width_mm / 2.0;
    // Samples: (edge, point, normal into the measured side).
    let mut samples = Vec::new();
    for (i, e) in grid.edges.iter().enumerate() {
        let length = e.a.distance(e.b);
        if length == 0.0 {
            continue;
        }
        let along = (e.b - e.a) / length;
        // Material lies left of every ring (outer rings counter-clockwise, holes clockwise).
        let normal = match side {
            Side::Material => along.perp(),
            Side::Gap => -along.perp(),
        };
        let n = (length / spacing_mm).ceil().max(1.0) as usize;
        for k in 0..n {
            samples.push((i, e.a + (e.b - e.a) * ((k as f64 + 0.5) / n as f64), normal));
        }
    }
    samples
        .par_iter()
        .filter_map(|&(edge, p, normal)| {
            let (radius, e, q) = grid.largest_empty_disc(p, normal, max_radius, edge)?;
            let apart = grid.arc_between(edge, p, e, q);
            if apart < LOCAL_ARC_RADII * radius {
                return None;
            }
            Some(Narrow {
                from_mm: p,
                to_mm: q,
                centre_mm: p + normal * radius,
                width_mm: 2.0 * radius,
                apart_along_outline_mm: apart,
            })
        })
        .collect()
}
