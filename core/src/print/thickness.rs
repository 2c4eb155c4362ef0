//! Local thickness of a region and of the space around it, measured with
//! the shrinking-ball method: for a point on the outline, the largest disc
//! that touches the outline there and stays inside the material (or inside
//! the empty space) has the local width as its diameter.

use std::collections::HashMap;

use glam::DVec2;
use rayon::prelude::*;

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
/// Shrinking-ball iterations; it converges in a handful.
const MAX_ITERATIONS: usize = 40;

struct Edge {
    a: DVec2,
    b: DVec2,
    ring: usize,
    /// Arc length along the ring at `a`, mm.
    arc_a: f64,
}

/// The outline's edges in a uniform grid, for nearest-point queries.
struct EdgeGrid {
    edges: Vec<Edge>,
    ring_lengths: Vec<f64>,
    cell_mm: f64,
    cells: HashMap<(i64, i64), Vec<u32>>,
}

impl EdgeGrid {
    fn new(region: &Region, cell_mm: f64) -> Self {
        let mut edges = Vec::new();
        let mut ring_lengths = Vec::new();
        for (ring_index, ring) in region.rings().enumerate() {
            let mut arc = 0.0;
            for k in 0..ring.len() {
                let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                edges.push(Edge { a, b, ring: ring_index, arc_a: arc });
                arc += a.distance(b);
            }
            ring_lengths.push(arc);
        }
        let mut cells: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
        let cell_of = |p: DVec2| ((p.x / cell_mm).floor() as i64, (p.y / cell_mm).floor() as i64);
        for (i, e) in edges.iter().enumerate() {
            let (lo, hi) = (cell_of(e.a.min(e.b)), cell_of(e.a.max(e.b)));
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    cells.entry((x, y)).or_default().push(i as u32);
                }
            }
        }
        EdgeGrid { edges, ring_lengths, cell_mm, cells }
    }

    /// The nearest outline point to `c` closer than `radius`, if any,
    /// ignoring `skip` (the edge the disc is tangent to), as (edge, point).
    fn nearest_within(&self, c: DVec2, radius: f64, skip: usize) -> Option<(usize, DVec2)> {
        let cell_of = |p: DVec2| ((p.x / self.cell_mm).floor() as i64, (p.y / self.cell_mm).floor() as i64);
        let (lo, hi) = (cell_of(c - DVec2::splat(radius)), cell_of(c + DVec2::splat(radius)));
        let mut best: Option<(f64, usize, DVec2)> = None;
        for x in lo.0..=hi.0 {
            for y in lo.1..=hi.1 {
                for &i in self.cells.get(&(x, y)).into_iter().flatten() {
                    let i = i as usize;
                    if i == skip {
                        continue;
                    }
                    let e = &self.edges[i];
                    let q = closest_on_segment(c, e.a, e.b);
                    let d = q.distance_squared(c);
                    if d < radius * radius && best.is_none_or(|(bd, _, _)| d < bd) {
                        best = Some((d, i, q));
                    }
                }
            }
        }
        best.map(|(_, i, q)| (i, q))
    }

    /// Distance along the ring between two outline points (the shorter way),
    /// or infinity when they are on different rings.
    fn arc_between(&self, e1: usize, p1: DVec2, e2: usize, p2: DVec2) -> f64 {
        let (a, b) = (&self.edges[e1], &self.edges[e2]);
        if a.ring != b.ring {
            return f64::INFINITY;
        }
        let s1 = a.arc_a + a.a.distance(p1);
        let s2 = b.arc_a + b.a.distance(p2);
        let d = (s1 - s2).abs();
        d.min(self.ring_lengths[a.ring] - d)
    }
}

fn closest_on_segment(p: DVec2, a: DVec2, b: DVec2) -> DVec2 {
    let ab = b - a;
    let len2 = ab.length_squared();
    if len2 == 0.0 {
        return a;
    }
    a + ab * ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
}

/// Every place on `side` of the outline of `region` narrower than
/// `width_mm`: the outline is sampled every `spacing_mm`, and at each sample
/// the largest disc tangent there is shrunk until it holds no outline point.
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
            let mut radius = max_radius;
            let mut contact = None;
            for _ in 0..MAX_ITERATIONS {
                let c = p + normal * radius;
                // A point on the disc's own boundary is not inside it.
                let Some((e, q)) = grid.nearest_within(c, radius * (1.0 - 1e-9), edge) else { break };
                let pq = q - p;
                let towards = normal.dot(pq);
                if towards <= 1e-12 {
                    break;
                }
                // The disc tangent at p through q.
                let shrunk = pq.length_squared() / (2.0 * towards);
                if shrunk >= radius {
                    break;
                }
                radius = shrunk;
                contact = Some((e, q));
            }
            let (e, q) = contact?;
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
