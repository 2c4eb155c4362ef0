//! Region fill with continuous curve textures (the curve-texture paper):
//! a region filled with a pattern of connected curves learned from a curve
//! exemplar. This is the first stage: curve exemplars ([`CurvePath`],
//! [`builtin_curves`]), their sample graphs at three levels
//! ([`SampleGraph`], [`hierarchy`]), and the similarity of neighbourhoods
//! ([`SampleGrid`], [`neighbourhood_distance`]) by robust matching
//! ([`robust_match`]), and the PatchMatch search step ([`search`]).

mod along_drawn;
mod assignment;
mod builtin;
mod corners;
mod crossings;
mod curve_path;
mod element;
mod error;
mod exemplar;
mod fragments;
mod joins;
mod junctions;
mod matching;
mod neighbourhood;
mod orientation;
mod pipeline;
mod reconstruct;
mod region;
mod sample_graph;
mod search;
mod settings;
mod synthesis;

pub use along_drawn::{ALONG_DRAWN_MIN_RUN_SPACINGS, ALONG_DRAWN_SPACINGS, cut_runs_along_drawn};
pub use assignment::{MatchedPair, assign_edges, assign_positions, existence_votes};
pub use builtin::{BUILTIN_CURVES, builtin_curves, builtin_shapes};
pub use corners::corner_vertices;
pub use crossings::{Crossing, crossings, cut_crossings};
pub use curve_path::CurvePath;
pub use element::{ELEMENT_MAX_SPACINGS, Elements, PlacedElement, SAME_KIND_SHARE, centroid, is_element_sized};
pub use error::FillError;
pub use exemplar::{BAND_MAX_WIDTH_SPACINGS, CurveExemplar, EXEMPLAR_TOLERANCE_MM, FilledShape, MAX_EXEMPLAR_SAMPLES};
pub use fragments::FragmentLimits;
pub use joins::join_drawn_ends;
pub use junctions::{greatest_degree, undo_junctions};
pub use matching::{Matching, robust_match};
pub use neighbourhood::{
    EDGE_WEIGHT, EdgeVectors, NeighbourhoodPair, SampleGrid, Similarity, edge_difference, edge_vectors,
    neighbourhood_distance, unmatched_cost,
};
pub use orientation::{EdgeTangents, THROUGH_TOLERANCE, assign_orientations};
pub use pipeline::{Drawn, PREDICTION_ITERATIONS, Prediction, make_product, make_product_around, predict, print_drawn};
pub use reconstruct::{CORNER_TURN, SMOOTH_TOLERANCE_MM, smooth_paths, smooth_paths_oriented};
pub use region::{MAX_FILL_SAMPLES, REGION_TOLERANCE_MM, check_region, parse_region, region_from_outlines};
pub use sample_graph::{
    JOIN_TOLERANCE_MM, MAX_SEGMENTS, Sample, SampleError, SampleGraph, SampleKind, TANGENT_REACH_SPACINGS,
};
pub use search::{NearestField, Neighbourhoods, SearchSettings, search};
pub use settings::{InvalidSetting, MAX_EXEMPLAR_SCALE, MAX_ITERATIONS, MIN_DELTA_MM, MIN_EXEMPLAR_SCALE, Settings};
pub use synthesis::{Synthesized, fill_rectangle, synthesize, synthesize_around, synthesize_oriented};

/// Levels of the sample hierarchy, coarse to fine.
pub const LEVELS: usize = 3;

/// The sample graphs of `paths` from coarse to fine: spacing `4δ`, `2δ`
/// and `δ`. Ends and junctions are samples at every level.
///
/// ```
/// use tracery_core::region_fill::{builtin_curves, hierarchy};
/// let levels = hierarchy(&builtin_curves("waves").unwrap(), 1.0).unwrap();
/// assert!(levels[0].samples.len() < levels[1].samples.len());
/// assert!(levels[1].samples.len() < levels[2].samples.len());
/// ```
pub fn hierarchy(paths: &[CurvePath], delta_mm: f64) -> Result<[SampleGraph; LEVELS], SampleError> {
    let at = |k: i32| SampleGraph::new(paths, delta_mm * 2f64.powi(k));
    Ok([at(2)?, at(1)?, at(0)?])
}
