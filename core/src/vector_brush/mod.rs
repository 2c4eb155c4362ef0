//! The vector brush: topology-constrained synthesis of vector patterns along
//! curves, from an SVG exemplar to a printable mesh.
//!
//! Data flows one way, one module per stage:
//!
//! 1. [`Exemplar`]: an SVG ornament loaded as clean polygons with holes.
//! 2. [`PieceSet`]: the exemplar cut into pieces ([`cut_positions`]), each with
//!    [`Portal`]s and a [`TopologyDescriptor`], and the [`PairCost`] of every
//!    compatible pair.
//! 3. [`solve`]: the dynamic program that picks a piece sequence with exactly
//!    the requested topology ([`Solution`]); split into state, search and diagnosis.
//! 4. [`position_offsets`] and [`stitch`]: the pieces placed, deformed to meet
//!    exactly and merged into a [`BandPattern`] in band space.
//! 5. [`crate::curve::map_along`] a curve: the planar pattern in millimetres,
//!    whose topology [`crate::curve::planar_topology`] counts from the geometry alone.
//! 6. [`crate::mesh::extrude`] into a mesh, gathered with everything known
//!    about it into a [`crate::Product`] by [`make_product`].
//!
//! [`Settings`] holds everything a person chooses; the app and the command
//! line share it.

mod autocorrelation;
mod builtin;
mod descriptor;
mod distortion;
mod error;
pub mod exemplar;
mod growing;
mod matching;
mod on_surface;
mod piece;
mod pipeline;
mod portal;
mod positioning;
mod product;
mod settings;
mod shade;
mod slicing;
mod solver;
mod stitching;

pub use autocorrelation::{Autocorrelation, LAGS, Similarity};
pub use builtin::{BUILTIN_NAMES, builtin, builtin_svg};
pub use descriptor::{LoopTopology, PortalId, PortalIds, TopologyDescriptor};
pub use distortion::{Distortion, SAMPLES_PER_PIECE};
pub use error::{ExemplarError, SliceError, SolveError, Unmet};
pub use exemplar::{Exemplar, LoadOptions};
pub use growing::Growing;
pub use matching::{BREAK_COST, MATCH_WEIGHT, MISFIT_WEIGHT, PairCost};
pub use on_surface::{SurfaceSynthesisError, make_band_on_surface, make_object_on_surface, make_on_surface, part_role};
pub use piece::{Piece, PieceSet};
pub use pipeline::{
    CORNER_RADIUS, LOOP_LEAST_BANDS, RESOLUTION_MM, Synthesis, SynthesisError, settled_region, synthesize,
    synthesize_alternatives, synthesize_rectangle,
};
pub use portal::{Portal, portals_at};
pub use positioning::{position_offsets, spread_offsets};
pub use product::{make_alternatives, make_product};
pub use settings::{ALTERNATIVES, InvalidSetting, MAX_SCALE, MIN_SCALE, Settings};
pub use shade::{ShadeSynthesisError, make_shade};
pub use slicing::{MAX_PORTALS, SliceOptions, SlicingMode, cut_positions, topology_events};
pub use solver::{
    BAND_MARGIN, CurveKind, LengthGrid, STATE_BYTES, Solution, SolveOptions, Target, solve, tolerance_levels,
};
pub use stitching::{BandPattern, stitch};
