//! Triangle meshes: the [`Mesh`] type, extrusion of planar regions into
//! watertight solids, and the mesh invariants.

mod extrude;
mod sanity;
mod triangle_mesh;

pub use extrude::{MeshError, extrude};
pub use sanity::MeshDefect;
pub use triangle_mesh::Mesh;
