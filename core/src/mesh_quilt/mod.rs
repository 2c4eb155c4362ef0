//! Mesh quilting (the mesh-quilting paper): a surface covered with 3D
//! geometric texture grown from a small mesh swatch. This first stage
//! quilts the plane: swatches ([`Swatch`], [`builtin_swatch`]), seeds on a
//! grid, geometry matching over translations, element correspondences,
//! Laplacian deformation ([`deform`]), merging along a graph cut
//! ([`min_cut_keep`]) and stitching ([`quilt_plane`]).

mod builtin;
mod coverage;
mod curved;
mod cut;
mod deform;
mod edge;
mod element;
mod error;
mod faces;
mod field;
mod flat_cap;
mod foot;
mod give_way;
mod matching;
mod merge;
mod patch;
mod planar;
mod product;
mod resting;
mod self_crossing;
mod settings;
mod shapes;
mod shell;
mod stitch;
mod swatch;
mod tear;
mod zones;

pub use builtin::{SWATCH_NAMES, builtin_swatch};
pub use coverage::{bare_share, swatch_bare_share};
pub use curved::{ShellReport, quilt_surface};
pub use cut::{FORCED, min_cut_keep};
pub use deform::{Constraint, deform};
pub use edge::{EDGE_TOLERANCE_MM, EdgeTrimmed, THREAD_ASPECT, trim_to_area};
pub use element::Element;
pub use error::QuiltError;
pub use faces::{Closest, Faces};
pub use field::{CAP_FACING_DEG, CAP_SMOOTH_DEG, GuidanceField, MAX_FIELD_POINTS, parse_strokes};
pub use flat_cap::{FLAT_CAP_DEG, FLAT_CAP_TOLERANCE_MM, RIM_INSET_MM};
pub use foot::{FLOOR_TOLERANCE_MM, Trimmed, floor_of, trim_below};
pub use merge::MergeCounts;
pub use patch::MAX_AREA_DISTORTION;
pub use planar::{MAX_QUILT_TRIANGLES, Quilt, QuiltCounts, quilt_plane};
pub use product::{Base, make_product, make_surface_product, parse_base, unite_with_base};
pub use self_crossing::{crosses_itself, crossing_pairs};
pub use settings::{Direction, MAX_CELLS_ACROSS, MAX_SINK_MM, MIN_CELLS_ACROSS, Settings};
pub use shapes::{lathe, lathe_ring, torus, tube};
pub use shell::{Shell, ShellStretch};
pub use stitch::stitch;
pub use swatch::{MAX_SWATCH_TRIANGLES, Swatch};
pub use tear::{MAX_FOLD_DEG, MAX_STRETCH_SPREAD, largest_fold_deg, stretch_spread};
