//! File writers: SVG for regions, binary STL for meshes.

mod stl;
mod svg;

pub use stl::write_stl;
pub use svg::region_to_svg;
