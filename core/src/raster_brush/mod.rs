//! The raster brush: bitmap exemplars synthesized along curves without
//! distortion, after "By-example synthesis of curvilinear structured
//! patterns" (`docs/raster-brush.md` says where it departs from the paper).
//!
//! Data flows one way, one module per stage:
//!
//! 1. [`RasterExemplar`]: a PNG with a transparent background (or a
//!    [`builtin`] painted here).
//! 2. [`lay_ribbon`]: the band around the curve cut into [`RibbonPiece`]s,
//!    each with the pixels it must leave transparent (fold-overs, avoided areas).
//! 3. [`valid_positions`]: where each piece may lie in the exemplar ([`Placements`]).
//! 4. [`search`]: the positions with the least seam mismatch ([`Path`]).
//! 5. [`align_seam`]: each seam's remapping ([`SeamMap`]).
//! 6. [`textured_mesh`], then [`make_product`]: the textured result, its
//!    outline traced from a render, the solid and the report's figures.
//!
//! [`Settings`] holds everything a person chooses; the app and the command
//! line share it.

mod builtin;
mod error;
mod exemplar;
mod pipeline;
mod placement;
mod ribbon;
mod search;
mod settings;
mod stitch;
mod textured_mesh;

pub use builtin::{BUILTIN_NAMES, builtin};
pub use error::{ExemplarError, RasterError};
pub use exemplar::{MAX_HEIGHT_PX, MAX_WIDTH_PX, MIN_SIDE_PX, OPAQUE_FROM, RasterExemplar};
pub use pipeline::{RasterSynthesis, TRACE_OVERSAMPLING, make_product, synthesize, traced_region};
pub use placement::{PieceSamples, Placements, Position, valid_positions, variety_bias};
pub use ribbon::{MAX_CELLS, Ribbon, RibbonPiece, lay_ribbon};
pub use search::{
    Closure, EdgeTable, GAMMA, JUMP_COST, MAX_FIXED_STARTS, Path, edge_cost, is_continuation, pixel_cost, search,
};
pub use settings::{InvalidSetting, MAX_SCALE, Settings, VARIETY_COST};
pub use stitch::{STRETCH_PENALTY, SeamMap, align_seam};
pub use textured_mesh::textured_mesh;
