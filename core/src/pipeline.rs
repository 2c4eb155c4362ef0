//! The whole pipeline, from an exemplar and a curve to a planar pattern.

use std::time::Instant;

use glam::DVec2;
use serde::Serialize;

use crate::{
    BandPattern, Control, Curve, CurveKind, Exemplar, ExemplarError, PatternTopology, PieceSet, PlanarPattern,
    SliceError, SliceOptions, SlicingMode, Solution, SolveError, SolveOptions, Target, map_along, planar_topology,
    position_offsets, stitch,
};

/// What to synthesize along a curve; sizes in millimetres.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct SynthesisRequest {
    /// Height of the band the pattern fills.
    pub band_mm: f64,
    /// Connected components wanted.
    pub components: Target,
    /// Holes wanted in the lace (a loop's central opening is not counted).
    pub holes: Target,
    /// On loops, ask for a pattern that runs all around.
    pub closed_pattern: bool,
    /// Variety: weight of the autocorrelation penalty.
    pub variety: f64,
    /// How the exemplar is cut.
    pub slicing: SlicingMode,
    /// Cuts through features thinner than this are dropped.
    pub min_portal_mm: f64,
    /// Topology events closer than this fraction of the exemplar's height
    /// are grouped (see [`SliceOptions::event_grouping`]).
    pub event_grouping: f64,
    /// Millimetres per exemplar unit; `None` fits the exemplar's height to the band.
    pub scale_mm_per_unit: Option<f64>,
    /// Seed for another pattern; 0 gives the best one.
    pub seed: u64,
}

impl Default for SynthesisRequest {
    fn default() -> Self {
        SynthesisRequest {
            band_mm: 12.0,
            components: Target::Exactly(1),
            holes: Target::Any,
            closed_pattern: false,
            variety: 0.0,
            slicing: SlicingMode::Topology,
            min_portal_mm: 0.0,
            event_grouping: SliceOptions::default().event_grouping,
            scale_mm_per_unit: None,
            seed: 0,
        }
    }
}

/// Why synthesis failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SynthesisError {
    /// The request makes no sense.
    #[error("{0}")]
    InvalidRequest(String),
    /// The exemplar could not be cut.
    #[error(transparent)]
    Slice(#[from] SliceError),
    /// The solver found nothing (or was stopped).
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// An intermediate pattern could not be used as an exemplar (rectangles).
    #[error("the first pass of the rectangle gave no usable pattern: {0}")]
    Intermediate(String),
}

impl From<ExemplarError> for SynthesisError {
    fn from(e: ExemplarError) -> Self {
        SynthesisError::Intermediate(e.to_string())
    }
}

/// Milliseconds spent in each stage.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Timings {
    /// Slicing and pair costs.
    pub analysis: f64,
    /// The topology solver.
    pub dp: f64,
    /// Positioning, stitching, mapping and the topology count.
    pub geometry: f64,
    /// Meshing (filled in by whoever meshes).
    pub mesh: f64,
}

/// A synthesized pattern with everything known about it.
#[derive(Clone, Debug)]
pub struct Synthesis {
    /// Millimetres per exemplar unit used.
    pub scale_mm_per_unit: f64,
    /// Pieces the exemplar was cut into.
    pub piece_count: usize,
    /// The solver's answer.
    pub solution: Solution,
    /// The pattern in band space (exemplar units).
    pub band: BandPattern,
    /// The pattern in the plane (millimetres).
    pub planar: PlanarPattern,
    /// Topology counted on `planar`, independently of the solver.
    pub topology: PatternTopology,
    /// Time per stage.
    pub timings: Timings,
    /// Things the person should know.
    pub warnings: Vec<String>,
}

fn ms(since: Instant) -> f64 {
    since.elapsed().as_secs_f64() * 1e3
}

/// Synthesizes a pattern from `exemplar` along `curve` (millimetres).
pub fn synthesize(
    exemplar: &Exemplar,
    curve: &Curve,
    request: &SynthesisRequest,
    control: &Control,
) -> Result<Synthesis, SynthesisError> {
    if !(request.band_mm.is_finite() && request.band_mm > 0.0) {
        return Err(SynthesisError::InvalidRequest(format!(
            "the band {} mm must be a positive width",
            request.band_mm
        )));
    }
    let scale = request.scale_mm_per_unit.unwrap_or(request.band_mm / exemplar.height());
    if !(scale.is_finite() && scale > 0.0) {
        return Err(SynthesisError::InvalidRequest(format!("the scale {scale} mm per unit must be positive")));
    }
    let start = Instant::now();
    let mut slicing = SliceOptions::default();
    slicing.mode = request.slicing;
    slicing.min_portal = request.min_portal_mm / scale;
    slicing.event_grouping = request.event_grouping;
    let set = PieceSet::new(exemplar, &slicing)?;
    let analysis = ms(start);

    let start = Instant::now();
    let kind = if curve.is_closed() { CurveKind::Closed } else { CurveKind::Open };
    let mut options = SolveOptions::new(curve.length() / scale);
    options.curve = kind;
    options.components = request.components;
    options.holes = request.holes;
    options.closed_pattern = request.closed_pattern && kind == CurveKind::Closed;
    options.variety = request.variety;
    options.seed = request.seed;
    let solution = crate::solve(&set, &options, control)?;
    let dp = ms(start);

    let start = Instant::now();
    let offsets = position_offsets(&set, &solution.pieces, kind);
    let band = stitch(&set, &solution.pieces, &offsets, curve.length() / scale, kind);
    let planar = map_along(&band, scale, curve);
    let topology = planar_topology(&planar, curve);
    let geometry = ms(start);

    let mut warnings = planar.warnings.clone();
    let stretch = curve.length() / (solution.length * scale) - 1.0;
    if stretch.abs() > 0.05 {
        warnings.push(format!(
            "no sequence of pieces fits the curve within 5%: the pattern is {} by {:.0}%",
            if stretch > 0.0 { "stretched" } else { "compressed" },
            stretch.abs() * 100.0
        ));
    }
    let expected_holes = solution.holes as usize;
    if topology.components != solution.components as usize || topology.holes != expected_holes {
        warnings.push(format!(
            "the final geometry has {} component(s) and {} hole(s), not the {} and {} planned: the band touches itself",
            topology.components, topology.holes, solution.components, solution.holes
        ));
    }
    Ok(Synthesis {
        scale_mm_per_unit: scale,
        piece_count: set.len(),
        solution,
        band,
        planar,
        topology,
        timings: Timings { analysis, dp, geometry, mesh: 0.0 },
        warnings,
    })
}

/// Synthesizes a rectangle `width_mm` × `height_mm` in two passes (section
/// 6.2): a strip along `u` first, then that strip, turned 90°, used as the
/// exemplar along `v`. Both passes keep the topology targets.
pub fn synthesize_rectangle(
    exemplar: &Exemplar,
    width_mm: f64,
    height_mm: f64,
    request: &SynthesisRequest,
    control: &Control,
) -> Result<Synthesis, SynthesisError> {
    let first = synthesize(exemplar, &line(width_mm)?, request, control)?;
    // The strip, turned so that its height runs along u.
    let turned = first.planar.region.map_points(|p| DVec2::new(p.y, -p.x));
    let strip = Exemplar::from_region("strip", turned)?;
    let mut second_request = request.clone();
    second_request.band_mm = width_mm;
    second_request.scale_mm_per_unit = Some(1.0);
    // The strip is as tall as the rectangle is wide: group its events on
    // the scale of the first band, not of the whole width.
    second_request.event_grouping = request.event_grouping * request.band_mm / width_mm;
    let second = synthesize(&strip, &line(height_mm)?, &second_request, control)?;
    let planar = PlanarPattern {
        region: second.planar.region.map_points(|p| DVec2::new(-p.y + 0.5 * width_mm, p.x)),
        warnings: [first.planar.warnings, second.planar.warnings.clone()].concat(),
        narrowest_band: 1.0,
    };
    let timings = Timings {
        analysis: first.timings.analysis + second.timings.analysis,
        dp: first.timings.dp + second.timings.dp,
        geometry: first.timings.geometry + second.timings.geometry,
        mesh: 0.0,
    };
    let counted = crate::count_topology(&planar.region);
    let topology = crate::PatternTopology { components: counted.components, holes: counted.holes, loop_openings: 0 };
    Ok(Synthesis { warnings: [first.warnings, second.warnings].concat(), topology, planar, timings, ..second })
}

fn line(length_mm: f64) -> Result<Curve, SynthesisError> {
    Curve::line(length_mm).map_err(|e| SynthesisError::InvalidRequest(e.to_string()))
}
