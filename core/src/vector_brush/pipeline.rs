//! The vector brush's pipeline, from an exemplar and a curve to a planar
//! pattern, each stage timed.

use glam::DVec2;
use rayon::prelude::*;

use super::shade::derived_seed;
use super::{
    BAND_MARGIN, BandPattern, CurveKind, Exemplar, ExemplarError, InvalidSetting, PieceSet, Settings, SliceError,
    SliceOptions, Solution, SolveError, SolveOptions, spread_offsets, stitch,
};
use crate::control::{Control, MaybeCancelled};
use crate::curve::{
    Curve, CurveError, MAPPING_TOLERANCE_MM, PlanarPattern, map_along_within, planar_topology_of_clean,
};
use crate::geom::{
    PatternTopology, Region, close_narrow_gaps, count_topology, separate_contacts, separate_touching, union,
    without_slivers,
};
use crate::mesh::MeshError;
use crate::report::{Timings, Warning};

/// Why synthesis failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SynthesisError {
    /// A setting is out of range.
    #[error(transparent)]
    Setting(#[from] InvalidSetting),
    /// The curve cannot carry a pattern.
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// The exemplar could not be cut.
    #[error(transparent)]
    Slice(#[from] SliceError),
    /// The solver found nothing (or was stopped).
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// An intermediate pattern could not be used as an exemplar (rectangles).
    #[error("the first pass of the rectangle gave no usable pattern: {0}")]
    Intermediate(String),
    /// The pattern could not be turned into a solid.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// A loop too narrow for the band ([`LOOP_LEAST_BANDS`]): the band's
    /// inside would close up.
    #[error(
        "the loop is about {across_mm:.1} mm across, too narrow for the {band_mm:.1} mm band: draw it larger or narrow the band"
    )]
    LoopTooSmall {
        /// How wide the loop is, mm: four times its area over its length (a circle's diameter).
        across_mm: f64,
        /// The band asked for, mm.
        band_mm: f64,
    },
    /// A fault in Tracery itself, caught in a worker.
    #[error(transparent)]
    Internal(#[from] crate::control::Internal),
}

impl From<ExemplarError> for SynthesisError {
    fn from(e: ExemplarError) -> Self {
        SynthesisError::Intermediate(e.to_string())
    }
}

impl MaybeCancelled for SynthesisError {
    fn is_cancelled(&self) -> bool {
        matches!(self, SynthesisError::Solve(e) if e.is_cancelled())
    }
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
    /// Shape class of each placed piece, in order ([`PieceSet::shape_classes`]):
    /// equal classes are geometrically identical pieces.
    pub shape_classes: Vec<usize>,
    /// The pattern in band space (exemplar units).
    pub band: BandPattern,
    /// The pattern in the plane (millimetres).
    pub planar: PlanarPattern,
    /// The curve the pattern follows: the one asked for, with its sharp
    /// corners rounded so that the band turns them without folding.
    pub curve: Curve,
    /// Topology counted on `planar`, independently of the solver.
    pub topology: PatternTopology,
    /// Time per stage: `analysis`, `solve`, `geometry`.
    pub timings: Timings,
    /// Things the person should know.
    pub warnings: Vec<Warning>,
}

impl Synthesis {
    /// Whether the topology counted on the geometry is the one the solver
    /// planned.
    pub fn as_planned(&self) -> bool {
        self.topology.components == self.solution.components as usize
            && self.topology.holes == self.solution.holes as usize
    }
}

/// Relative length error past which the person is told the pattern was
/// stretched or compressed to fit.
pub const LENGTH_WARNING: f64 = 0.05;

/// Synthesizes a pattern from `exemplar` along `curve` (millimetres).
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::curve::Curve;
/// use tracery_core::vector_brush::{Settings, builtin, synthesize};
/// let synthesis = synthesize(&builtin("vine").unwrap(), &Curve::line(80.0).unwrap(), &Settings::default(), &Control::default()).unwrap();
/// assert_eq!(synthesis.topology.components, 1);
/// ```
pub fn synthesize(
    exemplar: &Exemplar,
    curve: &Curve,
    settings: &Settings,
    control: &Control,
) -> Result<Synthesis, SynthesisError> {
    settings.validate()?;
    synthesize_at_scale(exemplar, curve, settings, settings.mm_per_unit(exemplar.height()), control)
}

/// Resolution of the geometry, mm: holes and specks of a mean width below
/// this ([`crate::geom::mean_width`]) are removed from the exemplar, at its
/// final size, before analysis, and from the result. Far below a 0.4 mm
/// nozzle or a laser's kerf.
pub const RESOLUTION_MM: f64 = 0.01;

/// The least radius of the arcs that replace a curve's sharp corners, in
/// half bands: a little more than the band's half-height, so that its inner
/// edge turns the corner instead of folding over itself. A person may ask
/// for more ([`Settings::corner_radius_mm`]).
pub const CORNER_RADIUS: f64 = 1.25;

/// The narrowest loop a band can run round, in bands across: below it the
/// band, narrowed to 0.85 of the loop's radius, folds across the middle
/// (an 8 mm circle drawn by hand under a 10 mm band came out unlike its plan
/// for 13 of the corpus's ornaments); a 10 mm circle under a 12 mm band
/// still comes out as planned.
pub const LOOP_LEAST_BANDS: f64 = 0.8;

/// How many times finer the chords are when a pattern is mapped again
/// because its count differed from the plan (`map_along_within`).
const FINER_MAPPING: f64 = 25.0;

/// The first `count` of the alternatives (see [`Settings::alternative`])
/// from `exemplar` along `curve`, sharing one analysis of the exemplar:
/// what a gallery shows. Settings are checked; `settings.alternative` is
/// not used.
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::curve::Curve;
/// use tracery_core::vector_brush::{Settings, builtin, synthesize_alternatives};
/// let curve = Curve::line(120.0).unwrap();
/// let all = synthesize_alternatives(&builtin("vine").unwrap(), &curve, &Settings::default(), 3, &Control::default()).unwrap();
/// assert_eq!(all.len(), 3);
/// assert_ne!(all[0].solution.pieces, all[1].solution.pieces);
/// ```
pub fn synthesize_alternatives(
    exemplar: &Exemplar,
    curve: &Curve,
    settings: &Settings,
    count: u32,
    control: &Control,
) -> Result<Vec<Synthesis>, SynthesisError> {
    settings.validate()?;
    let scale = settings.mm_per_unit(exemplar.height());
    alternatives_at_scale(exemplar, curve, settings, scale, count, true, control)
}

fn synthesize_at_scale(
    exemplar: &Exemplar,
    curve: &Curve,
    settings: &Settings,
    scale: f64,
    control: &Control,
) -> Result<Synthesis, SynthesisError> {
    let mut all = alternatives_at_scale(exemplar, curve, settings, scale, settings.alternative + 1, false, control)?;
    Ok(all.pop().expect("at least one alternative"))
}

/// The first `count` alternatives; with `every` false only the last one is
/// turned into geometry (the others only steer the search).
fn alternatives_at_scale(
    exemplar: &Exemplar,
    curve: &Curve,
    settings: &Settings,
    scale: f64,
    count: u32,
    every: bool,
    control: &Control,
) -> Result<Vec<Synthesis>, SynthesisError> {
    let (set, timings) = analyse(exemplar, settings, scale, None)?;
    let mut all = laid_out(&set, exemplar, curve, settings, scale, count, every, &[], 0, timings, control)?;
    if all.iter().all(Synthesis::as_planned) {
        return Ok(all);
    }
    // The plan holds on paper, but the exemplar has features finer than
    // the geometry can carry through, and this sequence of pieces pinched
    // one. A tip grazing a stroke is joined to it by a neck a thousandth of
    // a millimetre across, which every sequence pinches off somewhere: the
    // drawing's narrow gaps are closed (the neck becomes material the
    // resolution across) and it is analysed again. Otherwise (hairline
    // walls, say) other sequences are tried, the ones already tried
    // excluded; most come out as planned. Only patterns that then come
    // out as planned replace the others.
    let resolution = RESOLUTION_MM / scale;
    let closed = close_narrow_gaps(&exemplar.region, resolution);
    let retried = |set: &PieceSet, timings: Timings| {
        laid_out(set, exemplar, curve, settings, scale, count, every, &[], TOPOLOGY_RETRIES, timings, control)
    };
    let others = if closed != exemplar.region {
        analyse(exemplar, settings, scale, Some(closed)).and_then(|(closed_set, timings)| retried(&closed_set, timings))
    } else {
        // Nothing to close: the first analysis stands.
        retried(&set, Timings::default())
    };
    match others {
        Ok(others) => {
            for (slot, other) in all.iter_mut().zip(others) {
                if !slot.as_planned() && other.as_planned() {
                    let spent = std::mem::replace(slot, other);
                    slot.timings.absorb(&spent.timings);
                }
            }
        }
        Err(e) if e.is_cancelled() => return Err(e),
        // The first patterns stand, with their warnings.
        Err(_) => {}
    }
    Ok(all)
}

/// The exemplar cut into pieces at `scale` (mm per exemplar unit), with the
/// time it took: what every pattern from the same exemplar and settings
/// shares, whatever the curve.
///
/// `drawn` replaces the exemplar's region where given (its narrow gaps
/// closed, see [`close_narrow_gaps`]).
pub(crate) fn analyse(
    exemplar: &Exemplar,
    settings: &Settings,
    scale: f64,
    drawn: Option<Region>,
) -> Result<(PieceSet, Timings), SynthesisError> {
    if !(scale.is_finite() && scale > 0.0) {
        return Err(InvalidSetting::new("scale", format!("the scale {scale} mm per unit must be positive")).into());
    }
    let mut timings = Timings::default();
    let mut slicing = SliceOptions::default();
    slicing.mode = settings.slicing;
    slicing.min_portal = settings.min_portal_mm / scale;
    slicing.event_grouping = settings.event_grouping;
    let set = timings.time("analysis", || {
        let resolution = RESOLUTION_MM / scale;
        let drawn = drawn.as_ref().unwrap_or(&exemplar.region);
        let settled = Exemplar::from_region(exemplar.name.clone(), settled_region(drawn, resolution))
            .unwrap_or_else(|_| exemplar.clone());
        PieceSet::new(&settled, &slicing)
    })?;
    Ok((set, timings))
}

/// A drawing as the pipeline analyses it, `resolution` being
/// [`RESOLUTION_MM`] in the drawing's units: hairline slivers filled, specks
/// dropped, and parts that only touch at a point moved apart, as they are in
/// the result, so that the plan and the final geometry agree on them.
pub fn settled_region(drawn: &Region, resolution: f64) -> Region {
    separate_touching(&without_slivers(drawn, resolution), resolution)
}

/// Patterns from an analysed exemplar along `curve`: the first `count`
/// alternatives (only the last turned into geometry unless `every`), the
/// first of them beginning with `prefix` where it can.
#[allow(clippy::too_many_arguments)]
pub(crate) fn laid_out(
    set: &PieceSet,
    exemplar: &Exemplar,
    curve: &Curve,
    settings: &Settings,
    scale: f64,
    count: u32,
    every: bool,
    prefix: &[usize],
    retries: usize,
    mut timings: Timings,
    control: &Control,
) -> Result<Vec<Synthesis>, SynthesisError> {
    let curve = &settings.oriented(curve).with_rounded_corners(settings.corner_radius_used_mm());
    if curve.is_closed() {
        // A loop much narrower than the band has no inside left for the
        // band's inner edge, even narrowed: its pattern folds across the
        // middle and seldom comes out as planned.
        let across_mm = 4.0 * curve.signed_area().abs() / curve.length();
        if across_mm < LOOP_LEAST_BANDS * settings.band_mm {
            return Err(SynthesisError::LoopTooSmall { across_mm, band_mm: settings.band_mm });
        }
    }
    let kind = if curve.is_closed() { CurveKind::Closed } else { CurveKind::Open };
    let mut options = SolveOptions::new(curve.length() / scale);
    options.curve = kind;
    options.components = settings.components;
    options.holes = settings.holes;
    options.closed_pattern = settings.closed_pattern && kind == CurveKind::Closed;
    options.variety = settings.variety;
    options.seed = settings.seed;
    options.band_height = settings.band_mm / scale;
    options.prefix = prefix.to_vec();
    let build = |solution: Solution, mut timings: Timings| -> Synthesis {
        let (band, planar, topology) = timings.time("geometry", || {
            let offsets = spread_offsets(set, &solution.pieces, &solution.offsets, kind);
            // The pieces stitched with their outlines within `tolerance` of
            // the deformed curves, pressed into the band, and parts touching
            // at a point moved apart by `apart`.
            let stitched_within = |tolerance: f64, apart: fn(&Region, f64) -> Region| {
                let mut band = stitch(set, &solution.pieces, &offsets, curve.length() / scale, kind, tolerance);
                // The solver kept every piece within the band and stitching moves
                // endpoints by half their mismatch; what still pokes out (a loop's
                // closing error spread over its seams) is pressed back in, so the
                // pattern never strays from the curve. Never below the exemplar's
                // own half-height: a person who scaled it past the band asked for that.
                let limit = (0.5 * options.band_height).max(0.5 * exemplar.height()) * (1.0 + BAND_MARGIN);
                band.fit_within(limit);
                // Parts that only touch at a point are apart in the plan; mapped
                // onto a curve, rounding could merge them, so they are moved a
                // resolution apart here, once.
                band.region = apart(&band.region, RESOLUTION_MM / scale);
                band
            };
            let planned = (solution.components as usize, solution.holes as usize);
            let mapped = |band: &Region, tolerance_mm: f64| {
                let mut planar = map_along_within(band, scale, curve, tolerance_mm);
                let cleaned = without_slivers(&planar.region, RESOLUTION_MM);
                // Straight from the union in `map_along`, less slivers: clean.
                let topology = planar_topology_of_clean(&cleaned, curve);
                if (topology.components, topology.holes) != planned {
                    // A speck the plan counts as a part (the tip of a stroke
                    // a cut grazed, left alone by a break) is the plan's and
                    // stays; so is a hairline hole it counts.
                    let raw = planar_topology_of_clean(&planar.region, curve);
                    if (raw.components, raw.holes) == planned {
                        return (planar, raw);
                    }
                }
                planar.region = cleaned;
                (planar, topology)
            };
            let mut band = stitched_within(MAPPING_TOLERANCE_MM / scale, separate_touching);
            let (mut planar, mut topology) = mapped(&band.region, MAPPING_TOLERANCE_MM);
            if (topology.components, topology.holes) != planned {
                // Three rare ways the geometry can differ from the plan, all
                // mended at a cost only paid here: a part's tip touching the
                // middle of another's edge (thinned outlines leave no shared
                // point to separate); a neck squeezed on the inside of a turn
                // cut through by the chords of its two sides; and a tip
                // thinner than twice the tolerance, whose long side's chord
                // crosses the other side when stitched and pinches it off.
                let finer = MAPPING_TOLERANCE_MM / FINER_MAPPING;
                band = stitched_within(finer / scale, separate_contacts);
                (planar, topology) = mapped(&band.region, finer);
            }
            (band, planar, topology)
        });

        let mut warnings = planar.warnings.clone();
        if let Some(width) = solution.bounded {
            warnings.push(Warning::SearchBounded { width });
        }
        let stretch = curve.length() / (solution.length * scale) - 1.0;
        if stretch.abs() > LENGTH_WARNING {
            warnings.push(Warning::LengthMismatch { stretched: stretch > 0.0, percent: stretch.abs() * 100.0 });
        }
        let (planned_components, planned_holes) = (solution.components as usize, solution.holes as usize);
        if topology.components != planned_components || topology.holes != planned_holes {
            warnings.push(Warning::TopologyDiffers {
                planned_components,
                planned_holes,
                counted_components: topology.components,
                counted_holes: topology.holes,
            });
        }
        Synthesis {
            scale_mm_per_unit: scale,
            piece_count: set.len(),
            shape_classes: solution.pieces.iter().map(|&p| set.shape_classes()[p]).collect(),
            solution,
            band,
            planar,
            curve: curve.clone(),
            topology,
            timings,
            warnings,
        }
    };
    let total = count.max(1);
    let mut built: Vec<Synthesis> = Vec::new();
    // Geometry made for patterns that were then set aside.
    let mut discarded = Timings::default();
    for k in 0..total {
        let solution = timings.time("solve", || solve_varied(set, &options, control))?;
        options.prefix.clear();
        options.avoid.push(solution.pieces.clone());
        if !(every || k + 1 == total) {
            continue;
        }
        let mut synthesis = build(solution, Timings::default());
        // Counted on the final geometry, a pattern that did not come out as
        // planned is set aside for another, searched with it excluded.
        for _ in 0..retries {
            if synthesis.as_planned() {
                break;
            }
            let other = match timings.time("solve", || solve_varied(set, &options, control)) {
                Ok(other) => other,
                Err(e) if e.is_cancelled() => return Err(e.into()),
                // No other pattern: the one found stands, with its warning.
                Err(_) => break,
            };
            options.avoid.push(other.pieces.clone());
            discarded.absorb(&synthesis.timings);
            synthesis = build(other, Timings::default());
        }
        built.push(synthesis);
    }
    // Analysis and searches are shared: the last carries their time.
    if let Some(last) = built.last_mut() {
        let own = std::mem::replace(&mut last.timings, timings);
        last.timings.absorb(&own);
        last.timings.absorb(&discarded);
    }
    Ok(built)
}

/// Share of a pattern's pieces that its own variety measure (the
/// autocorrelation, [`Solution::autocorrelation`]) finds repeated, above
/// which the pattern counts as one motif over and over. Over the whole
/// corpus the patterns that repeat with a period under a third of their
/// length score 0.92 or more at the tenth percentile, and 99 % of the
/// others less than 0.77.
const REPETITIVE: f64 = 0.85;

/// Share of repeated pieces under which the second search's pattern
/// (below) counts as varied and is taken: well under [`REPETITIVE`], so
/// that a pattern still nearly as periodic does not replace seams that fit
/// better.
const VARIED: f64 = 0.6;

/// How much more variety weighs in the second search for a pattern that
/// came out repetitive.
const VARIETY_BOOST: f64 = 4.0;

/// The most states a first search may have taken for the second to be
/// run: past this a search takes upwards of a second. Every pattern of the
/// corpus that repeats with a period under a third of its length was found
/// within 312 k states; `vectorian109`'s loops, 3.3 M states and two
/// seconds, count as repetitive by the solver's measure and were searched
/// twice for nothing.
const BOOST_MAX_STATES: usize = 500_000;

/// The cheapest pattern, unless it is one motif over and over where the
/// exemplar has more to give. Seams that fit exactly cost nothing, so a
/// plain rule repeated can be cheaper than any varied sequence; at the
/// person's weight the variety term, which grows with the pattern just as
/// the seams' cost does, then never catches up (`docs/solver.md`,
/// *Variety*). Such a pattern is searched for again, first with the seams'
/// misfit left out ([`crate::vector_brush::MISFIT_WEIGHT`]): where the only
/// variety there is comes from seams that do not fit (a corner ornament
/// whose flourishes join only roughly), a person wants the flourishes, not
/// the rule. Its pattern is taken if it no longer repeats; else the search
/// runs once more with variety weighing [`VARIETY_BOOST`] times as much,
/// and that pattern is taken if it is varied ([`VARIED`]), the one without
/// the misfit term if not. A pattern from a later search carries that
/// search's cost.
fn solve_varied(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Solution, SolveError> {
    let first = super::solve(set, options, control)?;
    // The share of its pieces a pattern's autocorrelation counts as repeats.
    let repeated = |s: &Solution| s.autocorrelation / s.pieces.len().max(1) as f64;
    let repetitive = |s: &Solution| s.pieces.len() >= 6 && repeated(s) >= REPETITIVE;
    if options.variety <= 0.0 || !repetitive(&first) || first.states > BOOST_MAX_STATES {
        return Ok(first);
    }
    let mut relaxed = options.clone();
    relaxed.misfit_weight = 0.0;
    let first = if options.misfit_weight > 0.0 {
        match super::solve(set, &relaxed, control) {
            // Repetitive or not, the pattern that may vary by seams that
            // do not fit: where fitting seams give one motif over and
            // over, what varies it is those seams.
            Ok(other) if !repetitive(&other) || other.states > BOOST_MAX_STATES => return Ok(other),
            Ok(other) => other,
            Err(e) if e.is_cancelled() => return Err(e),
            Err(_) => first,
        }
    } else {
        first
    };
    let mut boosted = relaxed;
    boosted.variety *= VARIETY_BOOST;
    match super::solve(set, &boosted, control) {
        Ok(other) if repeated(&other) <= VARIED => Ok(other),
        Err(e) if e.is_cancelled() => Err(e),
        _ => Ok(first),
    }
}

/// How many other patterns are tried, one after another, when the one
/// found comes out with a topology other than planned (see
/// `alternatives_at_scale`).
pub const TOPOLOGY_RETRIES: usize = 3;

/// Strips made along `u` for a rectangle's second pass: stacked, they are
/// its exemplar, so that the rows it cuts from them differ (one strip
/// would give the same row over and over).
pub const RECTANGLE_STRIPS: usize = 3;

/// How far stacked strips overlap, as a share of the band: a hair, so
/// that material reaching a strip's edge is welded to the next strip's
/// by the union rather than left touching along a line.
const STRIP_OVERLAP: f64 = 1e-4;

/// Synthesizes a rectangle `width_mm` × `height_mm` in two passes (section
/// 6.2): [`RECTANGLE_STRIPS`] strips along `u` first, each with its own
/// seed, stacked; then the stack, turned 90°, used as the exemplar along
/// `v`, which cuts rows out of it with seams and topology of its own. Both
/// passes keep the topology targets.
pub fn synthesize_rectangle(
    exemplar: &Exemplar,
    width_mm: f64,
    height_mm: f64,
    settings: &Settings,
    control: &Control,
) -> Result<Synthesis, SynthesisError> {
    let line = Curve::line(width_mm)?;
    // The first strip with the person's seed, the others with seeds drawn from it.
    let mut first = synthesize(exemplar, &line, settings, &control.silent())?;
    let others: Vec<Synthesis> = (1..RECTANGLE_STRIPS)
        .into_par_iter()
        .map(|k| {
            let mut strip_settings = settings.clone();
            strip_settings.seed = derived_seed(settings.seed, k);
            synthesize(exemplar, &line, &strip_settings, &control.silent())
        })
        .collect::<Result<_, _>>()?;
    control.report(0.5);
    let pitch_mm = settings.band_mm * (1.0 - STRIP_OVERLAP);
    let mut stacked = vec![first.planar.region.clone()];
    for (k, strip) in others.iter().enumerate() {
        let lift = DVec2::new(0.0, (k + 1) as f64 * pitch_mm);
        stacked.push(strip.planar.region.map_points(|p| p + lift));
        first.timings.absorb(&strip.timings);
        first
            .warnings
            .extend(strip.warnings.iter().filter(|w| !first.warnings.contains(w)).cloned().collect::<Vec<_>>());
    }
    first.planar.region = union(&stacked.iter().collect::<Vec<_>>());
    let turned = first.planar.region.map_points(|p| DVec2::new(p.y, -p.x));
    let strip = Exemplar::from_region("strip", turned)?;
    let mut second_settings = settings.clone();
    second_settings.band_mm = width_mm;
    // The strip is as tall as the rectangle is wide: group its events on
    // the scale of the first band, not of the whole width.
    second_settings.event_grouping = settings.event_grouping * settings.band_mm / width_mm;
    // The strip is already in millimetres.
    let second = synthesize_at_scale(&strip, &Curve::line(height_mm)?, &second_settings, 1.0, control)?;
    let planar = PlanarPattern {
        region: second.planar.region.map_points(|p| DVec2::new(-p.y + 0.5 * width_mm, p.x)),
        warnings: [first.planar.warnings, second.planar.warnings.clone()].concat(),
        narrowest_band: 1.0,
    };
    let mut timings = first.timings;
    timings.absorb(&second.timings);
    let counted = count_topology(&planar.region);
    let topology =
        PatternTopology { components: counted.components, holes: counted.holes, ..PatternTopology::default() };
    Ok(Synthesis { warnings: [first.warnings, second.warnings].concat(), topology, planar, timings, ..second })
}
