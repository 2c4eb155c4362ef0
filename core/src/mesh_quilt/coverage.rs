//! [`bare_share`] and [`swatch_bare_share`]: how much of a model a quilt
//! leaves bare, against how much the swatch leaves bare by its own design
//! (chain mail's rings are open, a weave is dense), so that a quilt too
//! sparse for its model is told apart from an open swatch.

use glam::{DVec2, DVec3, IVec3};
use rustc_hash::FxHashMap;

use super::patch::triangle_area_3d;
use super::{Element, Swatch};
use crate::surface::SurfaceMesh;

/// Faces looking further down than this (`z` of their normal) are left out
/// of the measure: a model stands on them, and they are left bare.
const STANDING_NORMAL_Z: f64 = -0.9;

/// A face is cut into at most this many rows of pieces to be measured.
const MAX_SPLITS: f64 = 64.0;

/// Points within `reach_mm` of one another share or neighbour a cell.
struct Grid {
    reach_mm: f64,
    cells: FxHashMap<IVec3, Vec<DVec3>>,
}

impl Grid {
    fn new(points: impl Iterator<Item = DVec3>, reach_mm: f64) -> Grid {
        let mut cells: FxHashMap<IVec3, Vec<DVec3>> = FxHashMap::default();
        for p in points {
            cells.entry((p / reach_mm).floor().as_ivec3()).or_default().push(p);
        }
        Grid { reach_mm, cells }
    }

    fn reaches(&self, q: DVec3) -> bool {
        let home = (q / self.reach_mm).floor().as_ivec3();
        (-1..=1).any(|x| {
            (-1..=1).any(|y| {
                (-1..=1).any(|z| {
                    self.cells
                        .get(&(home + IVec3::new(x, y, z)))
                        .is_some_and(|ps| ps.iter().any(|p| p.distance(q) <= self.reach_mm))
                })
            })
        })
    }
}

/// The share of `surface`'s area (but the faces looking down, which it
/// stands on) farther than `reach_mm` from every vertex of `elements`,
/// judged at the middles of pieces of each face no wider than the reach.
///
/// ```
/// use tracery_core::mesh_quilt::bare_share;
/// use tracery_core::surface::{SurfaceMesh, builtin_base};
/// let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
/// assert_eq!(bare_share(&cylinder, &[], 1.0), 1.0);
/// ```
pub fn bare_share(surface: &SurfaceMesh, elements: &[Element], reach_mm: f64) -> f64 {
    let grid = Grid::new(elements.iter().flat_map(|e| e.vertices.iter().copied()), reach_mm);
    let (mut bare, mut total) = (0.0, 0.0);
    for (f, t) in surface.triangles().iter().enumerate() {
        if surface.face_normal(f as u32).z < STANDING_NORMAL_Z {
            continue;
        }
        let [a, b, c] = t.map(|v| surface.positions()[v as usize]);
        let area = triangle_area_3d([a, b, c]);
        // The face cut into n × n alike triangles, each judged at its
        // middle: a model from CAD has faces far wider than the reach.
        let longest = a.distance(b).max(b.distance(c)).max(c.distance(a));
        let n = (longest / reach_mm).ceil().clamp(1.0, MAX_SPLITS) as usize;
        let at = |u: f64, v: f64| a + (b - a) * (u / n as f64) + (c - a) * (v / n as f64);
        let piece = area / (n * n) as f64;
        for i in 0..n {
            for j in 0..n - i {
                let upright = at(i as f64 + 1.0 / 3.0, j as f64 + 1.0 / 3.0);
                let turned = (i + j + 1 < n).then(|| at(i as f64 + 2.0 / 3.0, j as f64 + 2.0 / 3.0));
                for p in std::iter::once(upright).chain(turned) {
                    total += piece;
                    if !grid.reaches(p) {
                        bare += piece;
                    }
                }
            }
        }
    }
    if total > 0.0 { bare / total } else { 0.0 }
}

/// [`bare_share`] of the swatch itself: over the middle half of its
/// rectangle (clear of its edges, where a tiling's neighbours would
/// cover), on a grid of points `reach_mm / 2` apart at the height a
/// model's surface lies in it (`sink_mm` above its bottom).
///
/// ```
/// use tracery_core::mesh_quilt::{builtin_swatch, swatch_bare_share};
/// let weave = swatch_bare_share(&builtin_swatch("weave").unwrap(), 0.3, 1.0);
/// let chain_mail = swatch_bare_share(&builtin_swatch("chainmail").unwrap(), 0.3, 1.0);
/// // A weave covers most of its plane; chain mail's rings leave gaps.
/// assert!(weave < chain_mail);
/// ```
pub fn swatch_bare_share(swatch: &Swatch, sink_mm: f64, reach_mm: f64) -> f64 {
    let (lo, hi) = swatch
        .elements
        .iter()
        .map(Element::bounds)
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), (a, b)| (lo.min(a), hi.max(b)));
    let grid = Grid::new(swatch.elements.iter().flat_map(|e| e.vertices.iter().copied()), reach_mm);
    let (from, size) = (lo.truncate() + 0.25 * (hi - lo).truncate(), 0.5 * (hi - lo).truncate());
    let steps = (size / (0.5 * reach_mm)).ceil().as_uvec2().max(glam::UVec2::ONE);
    let (mut bare, mut total) = (0usize, 0usize);
    for j in 0..steps.y {
        for i in 0..steps.x {
            let at = from + size * (DVec2::new(i as f64, j as f64) + 0.5) / steps.as_dvec2();
            total += 1;
            if !grid.reaches(at.extend(lo.z + sink_mm)) {
                bare += 1;
            }
        }
    }
    bare as f64 / total as f64
}
