//! Triangle meshes: the [`Mesh`] type, extrusion of planar regions into
//! watertight solids (with their repairs), refinement before a mesh is
//! bent onto a surface, and the mesh invariants.

mod extrude;
mod refine;
mod sanity;
mod t_junctions;
mod triangle_mesh;

pub use extrude::{MeshError, extrude};
pub use refine::split_edges;
pub use sanity::MeshDefect;
pub use t_junctions::split_t_junctions;
pub use triangle_mesh::Mesh;
