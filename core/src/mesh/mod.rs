//! Triangle meshes: the [`Mesh`] type, extrusion of planar regions into
//! watertight solids (with their repairs), refinement before a mesh is
//! bent onto a surface, solids from bent sheets, booleans and the short edges
//! they leave, meshes read from STL and OBJ files, and the mesh invariants.

mod boolean;
mod boundary;
mod by_vertex;
mod extrude;
mod import;
mod refine;
mod rings;
mod sanity;
mod short_edges;
mod slabs;
mod swept_faces;
mod thicken;
mod triangle_mesh;

pub use boolean::{BooleanError, difference_solids, intersect_solids, is_boolean_solid, union_solids};
pub use boundary::boundary_loops;
pub(crate) use extrude::checked_thickness;
pub use extrude::{MeshError, compact, extrude, triangulate_fine};
pub use import::{ImportError, MAX_IMPORTED_TRIANGLES, read_mesh_file, read_obj, read_stl};
pub use refine::{split_edges, split_edges_tracked};
pub use rings::vertex_rings;
pub use sanity::MeshDefect;
pub use short_edges::{MIN_EDGE_MM, collapse_short_edges};
pub use thicken::thicken;
pub use triangle_mesh::Mesh;
