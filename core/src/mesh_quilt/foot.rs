//! [`trim_below`]: elements that reach below the plane a model stands on
//! are cut off flat there, so the textured model (or the texture alone)
//! still stands on the print bed. Elements grown round the foot's edge
//! would otherwise hang below it, and a slicer would lift the whole object
//! onto their tips.

use glam::DVec3;

use super::Element;
use crate::mesh::{BooleanError, Mesh, difference_solids, is_boolean_solid};
use crate::surface::SurfaceMesh;

/// How far below the floor a vertex must reach before its element is cut,
/// mm: rounding in the shell map leaves vertices a hair below it.
pub const FLOOR_TOLERANCE_MM: f64 = 1e-6;

/// The model may stand on a face whose normal's `z` is below this (the
/// face turned more than about 25° from looking straight up): a flat
/// bottom, a wall (an open tube's rim), an open cone's rim (0.29) stand; a
/// sheet or dish lying on its back, looking up, does not.
const STANDS_NORMAL_Z: f64 = 0.9;

/// The height of the plane `surface` stands on, mm: its lowest level, where
/// a face there does not look up ([`STANDS_NORMAL_Z`]). `None` where every
/// face at the lowest level looks up, as an open sheet lying on its back does (a relief, a
/// dish): its textured side faces up, and the elements sunk into it reach
/// below its lowest level, so a cut there took away every element's
/// footing and a flat sheet came out bare. A closed model's lowest faces
/// always look down or sideways, so it always has a floor.
///
/// ```
/// use tracery_core::mesh::Mesh;
/// use tracery_core::mesh_quilt::floor_of;
/// use tracery_core::surface::{SurfaceMesh, builtin_base};
/// let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
/// assert_eq!(floor_of(&cylinder), Some(0.0));
/// // A sheet 60 mm square on the bed, looking up.
/// let sheet = Mesh {
///     vertices: vec![[0.0, 0.0, 0.0], [60.0, 0.0, 0.0], [60.0, 60.0, 0.0], [0.0, 60.0, 0.0]],
///     triangles: vec![[0, 1, 2], [0, 2, 3]],
/// };
/// assert_eq!(floor_of(&SurfaceMesh::new(sheet).unwrap()), None);
/// ```
pub fn floor_of(surface: &SurfaceMesh) -> Option<f64> {
    let positions = surface.positions();
    let lowest_mm = positions.iter().map(|p| p.z).fold(f64::INFINITY, f64::min);
    let at_floor = |t: &[u32; 3]| t.iter().any(|&v| positions[v as usize].z <= lowest_mm + FLOOR_TOLERANCE_MM);
    let stands = (0..surface.triangles().len() as u32)
        .filter(|&f| at_floor(&surface.triangles()[f as usize]))
        .any(|f| surface.face_normal(f).z < STANDS_NORMAL_Z);
    stands.then_some(lowest_mm)
}

/// What [`trim_below`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Trimmed {
    /// Elements cut at the floor.
    pub cut: usize,
    /// Elements removed: wholly below it, or every piece refused.
    pub removed: usize,
    /// Pieces of cut elements refused, the rest of them kept.
    pub crumbs: usize,
}

/// A closed box from `lo` to `hi`, faces out.
pub(super) fn cuboid(lo: DVec3, hi: DVec3) -> Mesh {
    let vertices = (0..8)
        .map(|k| {
            [
                if k & 1 == 0 { lo.x } else { hi.x },
                if k & 2 == 0 { lo.y } else { hi.y },
                if k & 4 == 0 { lo.z } else { hi.z },
            ]
        })
        .collect();
    let triangles = vec![
        [0, 2, 3],
        [0, 3, 1],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [0, 4, 6],
        [0, 6, 2],
        [1, 3, 7],
        [1, 7, 5],
    ];
    Mesh { vertices, triangles }
}

/// Cuts every element that reaches below `floor_z_mm` off flat at it
/// (a boolean difference with a box under the floor, so each stays
/// closed), and removes those wholly below. Each piece of a cut element is
/// kept only where `keep_piece` says so, and the booleans still take it as
/// a solid: a rivet hanging below a model's foot leaves a sliver on the bed
/// that touches nothing, and would print as a loose crumb. An element cut
/// in two becomes two elements.
///
/// ```
/// use glam::DVec3;
/// use tracery_core::mesh_quilt::{trim_below, tube};
/// // A ring standing on edge, its lowest point at z = -1.
/// let ring = tube(&(0..48).map(|k| {
///     let a = k as f64 / 48.0 * std::f64::consts::TAU;
///     DVec3::new(3.0 * a.cos(), 0.0, 2.0 + 3.0 * a.sin())
/// }).collect::<Vec<_>>(), 0.5, 12, true);
/// let mut elements = vec![ring];
/// let trimmed = trim_below(&mut elements, 0.0, |_| true).unwrap();
/// assert_eq!(trimmed.cut, 1);
/// assert!(elements.iter().all(|e| e.is_closed() && e.bounds().0.z >= -1e-9));
/// ```
pub fn trim_below(
    elements: &mut Vec<Element>,
    floor_z_mm: f64,
    keep_piece: impl Fn(&Element) -> bool,
) -> Result<Trimmed, BooleanError> {
    let mut trimmed = Trimmed::default();
    let mut kept = Vec::with_capacity(elements.len());
    for e in elements.drain(..) {
        let (lo, hi) = e.bounds();
        if lo.z >= floor_z_mm - FLOOR_TOLERANCE_MM {
            kept.push(e);
            continue;
        }
        if hi.z <= floor_z_mm {
            trimmed.removed += 1;
            continue;
        }
        // Wider than the element on every side, so no face of the box
        // meets one of the element's but the floor.
        let margin = DVec3::splat(1.0 + (hi - lo).max_element());
        let under = cuboid(lo - margin, DVec3::new(hi.x + margin.x, hi.y + margin.y, floor_z_mm));
        let cut = Element::from_mesh(&difference_solids(&e.to_mesh(), &under)?);
        // A piece the booleans would refuse (a stitched element that passed
        // through itself can come out of the cut pinched) would stop the
        // texture from being united with the model: it goes with the crumbs.
        let (pieces, crumbs): (Vec<Element>, Vec<Element>) = cut
            .parts()
            .into_iter()
            .filter(|p| !p.triangles.is_empty())
            .partition(|p| keep_piece(p) && is_boolean_solid(&p.to_mesh()));
        if pieces.is_empty() {
            trimmed.removed += 1;
        } else {
            trimmed.cut += 1;
            trimmed.crumbs += crumbs.len();
        }
        kept.extend(pieces);
    }
    *elements = kept;
    Ok(trimmed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_box_is_closed_and_faces_out() {
        let b = cuboid(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0));
        assert!(b.sanity_check().is_ok());
        assert!((b.signed_volume() - 6.0).abs() < 1e-12);
    }
}
