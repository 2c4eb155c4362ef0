//! A model hollowed into a shell of even wall, for carving a pattern out of
//! it: the surface as it is, and a copy moved in along the smooth normals
//! by the wall, facing in.

use glam::DVec3;

use super::SurfaceMesh;
use crate::mesh::Mesh;

/// Why a model could not be hollowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum HollowError {
    /// The wall is not a positive number.
    #[error("the wall {0} mm must be a positive number")]
    Wall(f64),
    /// Moving the surface in by the wall folds it somewhere.
    #[error(
        "the model is too thin or too sharply curved near ({:.1}, {:.1}, {:.1}) mm for a {wall_mm} mm wall; try a thinner wall",
        at_mm[0], at_mm[1], at_mm[2]
    )]
    TooThin {
        /// The wall asked for, mm.
        wall_mm: f64,
        /// Where the inner surface comes too close to the outer one.
        at_mm: [f64; 3],
    },
}

/// Share of the wall an inner vertex must keep from the outer surface:
/// below it the inner surface has folded over (a sharp crease, a part
/// thinner than twice the wall).
const KEPT_SHARE: f64 = 0.5;

/// `surface` as a shell `wall_mm` thick: two shells, the model facing out
/// and the inner surface facing in.
///
/// ```
/// use tracery_core::surface::{SurfaceMesh, builtin_base, hollow};
/// let egg = SurfaceMesh::new(builtin_base("egg").unwrap()).unwrap();
/// let shell = hollow(&egg, 2.0).unwrap();
/// assert!(shell.sanity_check().is_ok());
/// assert_eq!(shell.shell_count(), 2);
/// assert!(shell.signed_volume() < 0.25 * egg.mesh().signed_volume());
/// ```
pub fn hollow(surface: &SurfaceMesh, wall_mm: f64) -> Result<Mesh, HollowError> {
    if !(wall_mm.is_finite() && wall_mm > 0.0) {
        return Err(HollowError::Wall(wall_mm));
    }
    let outer = surface.mesh();
    let count = outer.vertices.len() as u32;
    let mut shell = outer.clone();
    for (v, &p) in surface.positions().iter().enumerate() {
        let normal = surface.vertex_normal(v as u32);
        let inner: DVec3 = p - normal * wall_mm;
        let kept = surface.closest_point(inner.to_array()).position_mm.distance(inner);
        if kept < KEPT_SHARE * wall_mm {
            return Err(HollowError::TooThin { wall_mm, at_mm: p.to_array() });
        }
        shell.vertices.push(inner.to_array());
    }
    shell.triangles.extend(outer.triangles.iter().map(|&[a, b, c]| [a + count, c + count, b + count]));
    Ok(shell)
}
