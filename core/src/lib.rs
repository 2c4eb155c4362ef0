//! Tracery's engine: patterns synthesized from exemplars, with no GUI dependency.
//!
//! The folders show the data flow. Shared stages, which know no mode:
//!
//! - [`geom`]: polygons with holes, rectangles, booleans, the independent
//!   topology count, SVG path flattening.
//! - [`curve`]: curves (smoothing, arc length, frames), the band-to-plane
//!   mapping, curve specifications (`line:120`, `circle:25`, …).
//! - [`mesh`]: triangle meshes, extrusion of planar regions.
//! - [`export`]: SVG and STL writers.
//! - [`control`]: cancellation, progress, state caps, and [`control::Cancelled`].
//! - [`random`]: SplitMix64, the engine's reproducible randomness.
//! - [`report`]: typed [`report::Warning`]s and [`report::Timings`].
//! - [`print`]: printability on the final planar geometry (thin features,
//!   narrow gaps, weak bridges) and thickening.
//! - [`surface`]: patterns laid on 3D surfaces: lamp shades (rows wrapped
//!   onto a cylinder or a cone, welded all around, made solid).
//! - [`product`]: the [`Product`] every mode returns; the app's canvas, 3D
//!   preview, export and the command-line report consume only it.
//!
//! Modes, which use the shared stages and never each other:
//!
//! - [`vector_brush`]: topology-constrained synthesis of vector patterns
//!   along curves, from an SVG exemplar to a printable mesh, and lamp shades
//!   made of its rows.
//! - [`raster_brush`]: bitmap exemplars synthesized along curves without
//!   distortion, traced into printable outlines.
//! - [`mesh_quilt`]: 3D texture grown over the plane from a mesh swatch,
//!   element by element, stitched along graph cuts.
//! - [`region_fill`]: regions filled with continuous curve textures (its
//!   first stages: curve exemplars, sample graphs, robust matching).
//!
//! Geometry uses `u` along the pattern and `v` across it, up (band space);
//! the plane is in millimetres, `y` up.
#![warn(missing_docs)]

pub mod control;
pub mod curve;
pub mod disjoint_sets;
pub mod export;
pub mod geom;
pub mod mesh;
pub mod mesh_quilt;
pub mod print;
pub mod product;
pub mod quality;
pub mod random;
pub mod raster_brush;
pub mod region_fill;
pub mod report;
pub mod setting;
pub mod surface;
pub mod svg_input;
pub mod vector_brush;

pub use glam::DVec2;
pub use product::Product;
