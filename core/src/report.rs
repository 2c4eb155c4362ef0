//! What a run tells the person besides its geometry: typed [`Warning`]s and
//! [`Timings`] per stage.

use std::time::Instant;

use serde::Serialize;
use serde::ser::SerializeMap;

/// Something the person should know about a result that was still produced.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// The curve turns tighter than half the band: the band was narrowed there.
    BandNarrowed {
        /// Where, along the curve, mm.
        at_mm: f64,
        /// The band's height there, percent of the asked height.
        percent: f64,
    },
    /// Distant parts of the curve come close: the band overlapped and was merged.
    BandOverlapsItself {
        /// Share of the pattern's area merged away, percent.
        merged_percent: f64,
    },
    /// No sequence of pieces fits the curve's length within 5%.
    LengthMismatch {
        /// Whether the pattern was stretched (`true`) or compressed to fit.
        stretched: bool,
        /// How much, percent.
        percent: f64,
    },
    /// The final geometry's topology differs from the planned one.
    TopologyDiffers {
        /// Components planned by the solver.
        planned_components: usize,
        /// Holes planned by the solver.
        planned_holes: usize,
        /// Components counted on the final geometry.
        counted_components: usize,
        /// Holes counted on the final geometry.
        counted_holes: usize,
    },
    /// Features thinner than the nozzle: the slicer would drop them.
    ThinFeatures {
        /// How many.
        count: usize,
        /// The thinnest, mm.
        width_mm: f64,
        /// The nozzle, mm.
        nozzle_mm: f64,
    },
    /// Gaps narrower than the nozzle: they would print closed.
    NarrowGaps {
        /// How many.
        count: usize,
        /// The narrowest, mm.
        width_mm: f64,
        /// The nozzle, mm.
        nozzle_mm: f64,
    },
    /// Bridges between pieces narrower than the limit.
    WeakBridges {
        /// How many.
        count: usize,
        /// The weakest, mm.
        width_mm: f64,
        /// The limit, mm.
        limit_mm: f64,
    },
    /// The pattern is only a few layers thick.
    FewLayers {
        /// Layers in its thickness.
        layers: f64,
    },
    /// Thickening thin features joined parts or closed holes.
    ThickeningChangedTopology {
        /// Components before and after.
        components: (usize, usize),
        /// Holes (loop openings included) before and after.
        holes: (usize, usize),
    },
    /// A jump ring touched more than one part and joined them.
    JumpRingsJoinedParts {
        /// Components before.
        before: usize,
        /// Components after.
        after: usize,
    },
    /// The thickened pattern could not be made solid; the pattern is as synthesized.
    ThickeningFailed {
        /// Why.
        reason: String,
    },
    /// The exact search needed more memory than the cap: a bounded search
    /// found the pattern, which meets every target but may not be the cheapest.
    SearchBounded {
        /// Partial patterns kept per length.
        width: usize,
    },
    /// Points given for a curve on a surface were not on it, and were moved
    /// to the nearest surface point.
    PointsSnapped {
        /// How far each point moved, mm, in the order given.
        moved_mm: Vec<f64>,
    },
    /// The band was wider than the surface allows along the curve, and was narrowed.
    BandNarrowedOnSurface {
        /// The band asked for, mm.
        asked_mm: f64,
        /// The band used, mm.
        used_mm: f64,
    },
    /// Carving the pattern out cut the shell into several bodies (each
    /// hole of the pattern cuts one loose; a ring all round severs it).
    CarvedApart {
        /// Bodies left.
        bodies: usize,
    },
    /// Carved patterns asked for different walls: the model is hollowed
    /// once, to the thickest, and thinner cuts may not reach through it.
    CarveWallsDiffer {
        /// The shell's wall, mm.
        shell_mm: f64,
        /// The thinnest wall asked, mm.
        thinnest_mm: f64,
    },
    /// A quilt leaves much more of its model bare than its swatch leaves
    /// of a plane: the swatch is large for the model's curves.
    QuiltSparse {
        /// The model's area left bare, percent.
        bare_percent: f64,
        /// The swatch's own area left bare, percent.
        swatch_bare_percent: f64,
    },
}

impl std::fmt::Display for Warning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Warning::BandNarrowed { at_mm, percent } => write!(
                f,
                "the curve turns tighter than the band near {at_mm:.0} mm along it: the band was narrowed to {percent:.0}% there"
            ),
            Warning::BandOverlapsItself { merged_percent } => write!(
                f,
                "the band overlaps itself where the curve comes close to itself: {merged_percent:.1}% of the pattern was merged there"
            ),
            Warning::LengthMismatch { stretched, percent } => write!(
                f,
                "no sequence of pieces fits the curve within 5%: the pattern is {} by {percent:.0}%",
                if *stretched { "stretched" } else { "compressed" }
            ),
            Warning::TopologyDiffers { planned_components, planned_holes, counted_components, counted_holes } => {
                write!(
                    f,
                    "the final geometry has {counted_components} component(s) and {counted_holes} hole(s), not the {planned_components} and {planned_holes} planned: the band touches itself"
                )
            }
            Warning::ThinFeatures { count, width_mm, nozzle_mm } => write!(
                f,
                "{count} feature(s) thinner than the {nozzle_mm} mm nozzle (thinnest {width_mm:.2} mm): thicken them, or widen the band"
            ),
            Warning::NarrowGaps { count, width_mm, nozzle_mm } => write!(
                f,
                "{count} gap(s) narrower than the {nozzle_mm} mm nozzle (narrowest {width_mm:.2} mm): they may print closed"
            ),
            Warning::WeakBridges { count, width_mm, limit_mm } => write!(
                f,
                "{count} bridge(s) between pieces narrower than {limit_mm:.2} mm (weakest {width_mm:.2} mm): thicken thin features, or with the vector brush raise the minimum portal width"
            ),
            Warning::FewLayers { layers } => {
                write!(f, "the pattern is only {layers:.1} layers thick: make it thicker or the layers thinner")
            }
            Warning::ThickeningChangedTopology { components, holes } => write!(
                f,
                "thickening changed the topology: {} → {} component(s), {} → {} hole(s)",
                components.0, components.1, holes.0, holes.1
            ),
            Warning::JumpRingsJoinedParts { before, after } => {
                write!(f, "the jump rings joined parts of the pattern: {before} → {after} component(s)")
            }
            Warning::ThickeningFailed { reason } => write!(f, "thin features were left as they are: {reason}"),
            Warning::SearchBounded { width } => write!(
                f,
                "the exact search needed more memory than allowed, so only the {width} cheapest partial patterns of each length were kept: the pattern meets every target, but a better-matching one may exist"
            ),
            Warning::PointsSnapped { moved_mm } => {
                let most = moved_mm.iter().copied().fold(0.0, f64::max);
                let list: Vec<String> = moved_mm.iter().map(|d| format!("{d:.2}")).collect();
                write!(
                    f,
                    "points off the surface were moved onto it (at most {most:.2} mm; each point, mm: {})",
                    list.join(", ")
                )
            }
            Warning::BandNarrowedOnSurface { asked_mm, used_mm } => write!(
                f,
                "the curve turns too tightly on the surface for a {asked_mm:.1} mm band: it was narrowed to {used_mm:.1} mm"
            ),
            Warning::CarvedApart { bodies } => write!(
                f,
                "carving the pattern out leaves the shell in {bodies} separate pieces: each hole of the pattern cuts one loose, and a ring all round the model cuts it in two; for one piece, carve a pattern with no holes (--holes 0) along an open curve"
            ),
            Warning::QuiltSparse { bare_percent, swatch_bare_percent } => write!(
                f,
                "{bare_percent:.0} % of the model is left bare, where the swatch leaves {swatch_bare_percent:.0} % of a plane bare: the swatch is large for the model's curves; try a smaller scale"
            ),
            Warning::CarveWallsDiffer { shell_mm, thinnest_mm } => write!(
                f,
                "the carved patterns ask for walls from {thinnest_mm:.1} to {shell_mm:.1} mm: the model was hollowed once, to {shell_mm:.1} mm, so cuts made for a thinner wall may not reach through it; give every carved curve the same wall"
            ),
        }
    }
}

impl Serialize for Warning {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// Time spent in each stage, in milliseconds, in the order the stages ran.
/// Serialized as a map from stage name to milliseconds.
///
/// ```
/// use tracery_core::report::Timings;
/// let mut timings = Timings::default();
/// let answer = timings.time("solve", || 6 * 7);
/// timings.add_ms("solve", 1.0);
/// assert_eq!(answer, 42);
/// assert_eq!(timings.stages().len(), 1);
/// assert!(timings.stage_ms("solve").unwrap() >= 1.0);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Timings {
    stages: Vec<(&'static str, f64)>,
}

impl Timings {
    /// Adds `ms` to `stage` (a new stage goes last).
    pub fn add_ms(&mut self, stage: &'static str, ms: f64) {
        match self.stages.iter_mut().find(|(name, _)| *name == stage) {
            Some((_, total)) => *total += ms,
            None => self.stages.push((stage, ms)),
        }
    }

    /// Runs `work` and adds its wall-clock time to `stage`.
    pub fn time<T>(&mut self, stage: &'static str, work: impl FnOnce() -> T) -> T {
        let start = Instant::now();
        let out = work();
        self.add_ms(stage, start.elapsed().as_secs_f64() * 1e3);
        out
    }

    /// Adds every stage of `other` to this one.
    pub fn absorb(&mut self, other: &Timings) {
        for &(stage, ms) in &other.stages {
            self.add_ms(stage, ms);
        }
    }

    /// Milliseconds of one stage.
    pub fn stage_ms(&self, stage: &str) -> Option<f64> {
        self.stages.iter().find(|(name, _)| *name == stage).map(|(_, ms)| *ms)
    }

    /// The stages and their milliseconds, in order.
    pub fn stages(&self) -> &[(&'static str, f64)] {
        &self.stages
    }

    /// Milliseconds over all stages.
    pub fn total_ms(&self) -> f64 {
        self.stages.iter().map(|(_, ms)| ms).sum()
    }
}

impl Serialize for Timings {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.stages.len()))?;
        for (stage, ms) in &self.stages {
            map.serialize_entry(stage, ms)?;
        }
        map.end()
    }
}
