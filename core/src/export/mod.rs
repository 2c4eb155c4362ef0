//! File writers: SVG for regions (filled or laser cut paths), binary STL and
//! 3MF for meshes, and renders to PNG.

mod raster;
mod stl;
mod svg;
mod threemf;

pub use raster::{MAX_RENDER_PX, RenderError, encode_png, render_product, render_textured};
pub use stl::write_stl;
pub use svg::{CUT_COLOUR, HAIRLINE_MM, SvgFlavour, SvgOptions, region_to_svg, write_paths_svg, write_svg};
pub use threemf::{OBJECT_COLOURS, ThreeMfObject, object_colour, write_3mf};

/// Why a file could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ExportError {
    /// Nothing with triangles to write.
    #[error("nothing to export: no pattern has a solid yet")]
    Empty,
    /// Writing failed.
    #[error("could not write the file: {0}")]
    Io(#[from] std::io::Error),
    /// The zip container could not be made.
    #[error("could not write the 3MF package: {0}")]
    Zip(#[from] zip::result::ZipError),
}
