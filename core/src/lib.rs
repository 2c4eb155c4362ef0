//! Tracery's engine: topology-constrained synthesis of vector patterns.
//!
//! Data flows one way, one module per stage:
//!
//! 1. [`Exemplar`]: an SVG ornament loaded as clean polygons with holes.
//! 2. [`PieceSet`]: the exemplar cut into pieces ([`cut_positions`]), each with
//!    [`Portal`]s and a [`TopologyDescriptor`], and the [`PairCost`] of every
//!    compatible pair.
//! 3. [`solve`]: the dynamic program that picks a piece sequence with exactly
//!    the requested topology ([`Solution`]).
//!
//! Geometry uses `u` along the pattern and `v` across it, up; see [`exemplar`].
#![warn(missing_docs)]

mod autocorrelation;
mod boolean;
mod builtin;
mod descriptor;
mod error;
pub mod exemplar;
mod matching;
mod piece;
mod polygon;
mod portal;
mod rect;
mod slicing;
mod solver;
mod topology;

pub use autocorrelation::{Autocorrelation, LAGS, Similarity};
pub use boolean::{FillRule, clip_to_rect, difference, resolve_contours, union};
pub use builtin::{BUILTIN_NAMES, builtin, builtin_svg};
pub use descriptor::{LoopTopology, PortalIds, TopologyDescriptor};
pub use error::{ExemplarError, SliceError, SolveError, Unmet};
pub use exemplar::{Exemplar, LoadOptions};
pub use matching::{MATCH_WEIGHT, PairCost};
pub use piece::{Piece, PieceSet};
pub use polygon::{Polygon, Region, ring_contains, signed_area};
pub use portal::{Portal, portals_at};
pub use rect::Rect;
pub use slicing::{MAX_PORTALS, SliceOptions, SlicingMode, cut_positions, topology_events};
pub use solver::{
    Control, CurveKind, LengthGrid, STATE_BYTES, Solution, SolveOptions, Target, solve, tolerance_levels,
};
pub use topology::{Topology, count_topology};

pub use glam::DVec2;
