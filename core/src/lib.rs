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
//! 4. [`position_offsets`] and [`stitch`]: the pieces placed, deformed to meet
//!    exactly and merged into a [`BandPattern`] in band space.
//! 5. [`map_along`] a [`Curve`]: the [`PlanarPattern`] in millimetres, whose
//!    topology [`planar_topology`] counts from the geometry alone.
//! 6. [`extrude`] into a [`Mesh`] (binary STL) or [`region_to_svg`].
//!
//! [`synthesize`] runs stages 2 to 5.
//!
//! Geometry uses `u` along the pattern and `v` across it, up; see [`exemplar`].
#![warn(missing_docs)]

mod autocorrelation;
mod boolean;
mod builtin;
mod curve;
mod descriptor;
mod error;
pub mod exemplar;
mod mapping;
mod matching;
mod mesh;
mod piece;
mod pipeline;
mod polygon;
mod portal;
mod positioning;
mod rect;
mod slicing;
mod solver;
mod stitching;
mod svg_export;
mod topology;

pub use autocorrelation::{Autocorrelation, LAGS, Similarity};
pub use boolean::{FillRule, clip_to_rect, difference, resolve_contours, union};
pub use builtin::{BUILTIN_NAMES, builtin, builtin_svg};
pub use curve::{Curve, CurveError};
pub use descriptor::{LoopTopology, PortalIds, TopologyDescriptor};
pub use error::{ExemplarError, SliceError, SolveError, Unmet};
pub use exemplar::{Exemplar, LoadOptions, first_path_points};
pub use mapping::{PatternTopology, PlanarPattern, map_along, planar_topology};
pub use matching::{MATCH_WEIGHT, PairCost};
pub use mesh::{Mesh, MeshError, extrude};
pub use piece::{Piece, PieceSet};
pub use pipeline::{Synthesis, SynthesisError, SynthesisRequest, Timings, synthesize, synthesize_rectangle};
pub use polygon::{Polygon, Region, ring_contains, signed_area};
pub use portal::{Portal, portals_at};
pub use positioning::position_offsets;
pub use rect::Rect;
pub use slicing::{MAX_PORTALS, SliceOptions, SlicingMode, cut_positions, topology_events};
pub use solver::{
    Control, CurveKind, LengthGrid, STATE_BYTES, Solution, SolveOptions, Target, solve, tolerance_levels,
};
pub use stitching::{BandPattern, stitch};
pub use svg_export::region_to_svg;
pub use topology::{Topology, count_topology};

pub use glam::DVec2;
