//! The topology solver: dynamic programming over piece sequences (sections 3.5 to 3.7).
//!
//! # State
//!
//! A partial solution is keyed by *(last piece, topology descriptor, length
//! key)*. It carries its true length, and the key is that length rounded to a
//! quantum ([`LengthGrid`]). States are expanded in order of key, and two
//! partial solutions compete only when they agree on all three. The length
//! window, and the length term of the cost, use the true length, so the
//! quantum never adds up into a length error. An earlier version summed
//! rounded widths: 13 pieces of uniform width came out 9.8% long against a
//! 5% tolerance.
//!
//! The quantum decides how much is merged. By default it is the narrowest
//! piece, or a tenth of the tolerance, whichever is smaller. Then sequences
//! whose lengths differ by less than about a piece keep only the cheaper,
//! which makes the search approximate: it has three to five times fewer
//! states on ornaments with many portals than with a third of a piece. The
//! tests measure the approximation against brute force
//! (`the_default_length_key_stays_close_to_exact`). With a fine quantum,
//! the variety term off and no band limit, the search is exact, and the
//! exactness test checks it against exhaustive search.
//!
//! Descriptors are interned and each *(descriptor, piece) → descriptor* join
//! is computed once, which turns the search into a shortest path over a small
//! product graph.
//!
//! # Closed curves
//!
//! A loop has no first piece, so every cycle is searched in the rotation that
//! starts with its smallest piece index: one search per start piece `s`, using
//! only pieces `≥ s`, run in parallel. At the end the descriptor is joined with
//! itself ([`TopologyDescriptor::close_loop`]).
//!
//! # Any number of parts and holes
//!
//! Where the targets constrain neither, the search first runs with one
//! descriptor for all, and a loop's pattern is recounted afterwards
//! (`search::search_all`): the descriptors only told apart partial
//! patterns the targets accept alike.

mod diagnosis;
mod search;
mod state;
mod targets;

use serde::{Deserialize, Serialize};

use super::{PieceSet, SolveError};
use crate::control::Control;
use diagnosis::diagnose;
use search::search_all;
pub use state::LengthGrid;

/// A target for a count: an exact number, or anything.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Target {
    /// Exactly this many.
    Exactly(u32),
    /// Any number.
    #[default]
    Any,
}

impl Target {
    /// Whether `n` meets the target.
    pub fn accepts(&self, n: u32) -> bool {
        match self {
            Target::Exactly(t) => n == *t,
            Target::Any => true,
        }
    }

    /// Whether a count that can only grow has already passed the target.
    fn exceeded_by(&self, n: u32) -> bool {
        matches!(self, Target::Exactly(t) if n > *t)
    }
}

impl std::fmt::Display for Target {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Target::Exactly(n) => write!(f, "exactly {n}"),
            Target::Any => write!(f, "any number of"),
        }
    }
}

/// Whether the curve is open or a loop.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CurveKind {
    /// From one end to the other: the pattern starts and ends without open portals.
    #[default]
    Open,
    /// A loop: the last piece joins the first.
    Closed,
}

/// What to synthesize.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct SolveOptions {
    /// Length of the curve, in exemplar units.
    pub target_length: f64,
    /// Open curve or loop.
    pub curve: CurveKind,
    /// Connected components wanted.
    pub components: Target,
    /// Holes wanted. On loops, the central opening of a pattern that runs
    /// around the loop is not counted: it is not a hole in the lace.
    pub holes: Target,
    /// On loops, keep only patterns with a component that runs all around.
    pub closed_pattern: bool,
    /// Height of the band, in exemplar units: a piece may be raised or
    /// lowered (by the accumulated alignments `τ`) only as far as it stays
    /// within `±band_height / 2`, give or take [`BAND_MARGIN`]. A seam without
    /// portals starts a new chain back on the axis. Infinite turns the limit off.
    pub band_height: f64,
    /// Relative length tolerance ε / L (the paper's 0.05); widened when no
    /// solution meets it.
    pub length_tolerance: f64,
    /// Weight of the length term `((l - L) / ε)²` added to a finished
    /// pattern's cost, so that among patterns within the tolerance the ones
    /// that need less stretching win when seams cost about the same.
    pub length_weight: f64,
    /// Weight β of the autocorrelation penalty; 0 turns it off.
    pub variety: f64,
    /// σ of the autocorrelation similarity, in piece indices.
    pub autocorrelation_sigma: f64,
    /// Length quantum of the state keys, in exemplar units; `None` picks the
    /// narrowest piece or a tenth of ε, whichever is smaller. Never wider
    /// than the narrowest piece.
    pub length_quantum: Option<f64>,
    /// Most DP states held at once before giving up with an error (or,
    /// where the targets allow it, handing over to a search that keeps
    /// only the cheapest states of each length). The default, 4 M states
    /// at [`STATE_BYTES`] each, is 32 MB; the room for the open states
    /// beside them is held to 26 MB, so that with the 5 MB the process
    /// holds before the search the whole stays under 64 MB.
    pub max_states: usize,
    /// Zero for the best solution; any other value perturbs the seam costs
    /// along the curve to give another, slightly worse, pattern.
    pub seed: u64,
    /// Earlier solutions (piece sequences) to differ from: every seam that
    /// joins two shapes in the order one of them did pays
    /// [`SolveOptions::diversity`] times the mean seam cost, once per
    /// solution that used it. Position plays no part, so a loop's rotated
    /// copy of an earlier pattern pays in full.
    pub avoid: Vec<Vec<usize>>,
    /// Weight of reusing an earlier solution's seams, in mean seam costs.
    /// Two: with one, the variety term (which sees periods up to
    /// [`crate::vector_brush::LAGS`]) pulled the built-in lace's alternatives
    /// back to the same few varied sequences (two of six differed over 21%
    /// of a 150 mm line; with two, every pair differs over 46% or more).
    /// Set against a variety weight of 0.3, it grows in proportion above it.
    pub diversity: f64,
    /// Weight of each seam's misfit ([`crate::vector_brush::PairCost::d_misfit`]);
    /// [`crate::vector_brush::MISFIT_WEIGHT`] unless a search is told to
    /// vary a pattern whatever its seams cost.
    pub misfit_weight: f64,
    /// On open curves, pieces the pattern must begin with (a pattern
    /// growing while it is drawn keeps what is already laid): the search
    /// only extends them. Where they cannot be extended to a pattern that
    /// meets the targets, the search starts again from nothing.
    pub prefix: Vec<usize>,
}

impl SolveOptions {
    /// Options for a curve of `target_length` exemplar units, one component, any holes.
    pub fn new(target_length: f64) -> Self {
        SolveOptions {
            target_length,
            curve: CurveKind::Open,
            components: Target::Exactly(1),
            holes: Target::Any,
            closed_pattern: false,
            band_height: f64::INFINITY,
            length_tolerance: 0.05,
            length_weight: 0.05,
            variety: 0.0,
            autocorrelation_sigma: 0.5,
            length_quantum: None,
            max_states: 4_000_000,
            seed: 0,
            avoid: Vec::new(),
            diversity: 2.0,
            misfit_weight: crate::vector_brush::MISFIT_WEIGHT,
            prefix: Vec::new(),
        }
    }
}

/// The chosen piece sequence and what it achieves.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Solution {
    /// Piece indices, in order along the curve.
    pub pieces: Vec<usize>,
    /// Vertical offset of each piece accumulated from the pairwise alignments
    /// `τ`, first piece at 0 (exemplar units).
    pub offsets: Vec<f64>,
    /// The objective minimized: matching cost, plus `β` times the
    /// autocorrelation, plus the length term.
    pub cost: f64,
    /// Matching cost `F(η)`: the sum of seam costs (the closing seam included on loops).
    pub matching_cost: f64,
    /// Autocorrelation of the sequence (the variety term before weighting).
    pub autocorrelation: f64,
    /// Sum of piece widths, exemplar units.
    pub length: f64,
    /// The curve length asked for.
    pub target_length: f64,
    /// The length tolerance finally used (widened when needed).
    pub tolerance: f64,
    /// Components of the result, from the descriptors.
    pub components: u32,
    /// Holes in the lace (on loops, without the central openings).
    pub holes: u32,
    /// On loops, components that run all around; 0 on open curves.
    pub wraps: u32,
    /// DP states created over all searches.
    pub states: usize,
    /// `Some(width)` when the exact search needed more states than the cap
    /// and a bounded one (the `width` cheapest states of each length kept)
    /// found this pattern instead: it meets every target, but a cheaper one
    /// may exist.
    #[serde(default)]
    pub bounded: Option<usize>,
    /// Whether the exact search needed more states than the cap and one
    /// that drops dominated partial patterns found this pattern instead
    /// (`Goal::Dominated`): the same pattern when the variety term is off.
    #[serde(default)]
    pub dominance: bool,
}

/// How far past the band's edge, as a fraction of half the band, the solver
/// lets a raised piece reach. Stitching moves portal endpoints by half their
/// remaining mismatch, so this leaves room under the 5% the geometry allows.
pub const BAND_MARGIN: f64 = 0.03;

/// Bytes one DP state is counted at: the 6 bytes it leaves once expanded
/// (its parent and piece, in two arrays that grow by doubling), rounded
/// up; used to turn the state cap into megabytes. The open states, held
/// whole, are counted apart ([`SolveOptions::max_states`]). Measured on
/// the corpus's largest exact search (`vectorian168` round a 40 mm circle,
/// two parts, 3.4 M states at once and 25 MB of room for open states), the
/// process's peak less what it held before is 6 bytes a state plus that
/// room, to a few hundred kilobytes.
pub const STATE_BYTES: usize = 8;

/// Finds the best piece sequence for `options`.
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::vector_brush::{builtin, solve, PieceSet, SliceOptions, SolveOptions};
/// let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
/// let solution = solve(&set, &SolveOptions::new(3.0 * set.exemplar_width), &Control::default()).unwrap();
/// assert_eq!(solution.components, 1);
/// assert!((solution.length / solution.target_length - 1.0).abs() <= solution.tolerance / solution.target_length + 0.01);
/// ```
pub fn solve(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Solution, SolveError> {
    validate(set, options)?;
    // Pieces of the same shape are interchangeable: search one of each.
    let distinct = set.shape_classes().iter().enumerate().all(|(i, &c)| c == i);
    let reduced;
    let (search_set, originals) = if distinct {
        (set, None)
    } else {
        let (smaller, originals) = set.distinct_shapes();
        reduced = smaller;
        (&reduced, Some(originals))
    };
    // Earlier solutions and the prefix in the searched set's indices (one per shape).
    let searched;
    let options = match &originals {
        Some(originals) if !options.avoid.is_empty() || !options.prefix.is_empty() => {
            let to_search = |p: usize| originals.binary_search(&set.shape_classes()[p]).unwrap_or(0);
            let avoid = options.avoid.iter().map(|s| s.iter().map(|&p| to_search(p)).collect()).collect();
            let prefix = options.prefix.iter().map(|&p| to_search(p)).collect();
            searched = SolveOptions { avoid, prefix, ..options.clone() };
            &searched
        }
        _ => options,
    };
    let mut found = match search_all(search_set, options, Goal::Best, control) {
        Err(SolveError::TooManyStates { .. }) if !options.prefix.is_empty() => None,
        other => other.or_else(|e| past_cap_retry(search_set, options, e, control))?,
    };
    if found.is_none() && !options.prefix.is_empty() {
        let fresh = SolveOptions { prefix: Vec::new(), ..options.clone() };
        found = search_all(search_set, &fresh, Goal::Best, control)
            .or_else(|e| past_cap_retry(search_set, &fresh, e, control))?;
    }
    match found {
        Some(mut solution) => {
            if let Some(originals) = originals {
                for p in &mut solution.pieces {
                    *p = originals[*p];
                }
            }
            Ok(solution)
        }
        None => Err(SolveError::NoSolution(diagnose(search_set, options, control)?)),
    }
}

/// Where the exact search needs more states than the cap, one that drops
/// dominated partial patterns runs instead, where the targets allow it: it
/// finds the same pattern when the variety term is off, and its answer,
/// pattern or none, stands. Past the cap again, a bounded one (the
/// cheapest states of each length) looks for a pattern that meets every
/// target. Finding none proves nothing, so the cap error stands then.
pub(super) fn past_cap_retry(
    set: &PieceSet,
    options: &SolveOptions,
    error: SolveError,
    control: &Control,
) -> Result<Option<Solution>, SolveError> {
    if !matches!(error, SolveError::TooManyStates { .. }) {
        return Err(error);
    }
    if options.dominance_is_sound() {
        match search_all(set, options, Goal::Dominated, control) {
            Err(SolveError::TooManyStates { .. }) => {}
            answer => return answer,
        }
    }
    match search_all(set, options, Goal::Bounded, control)? {
        Some(solution) => Ok(Some(solution)),
        None => Err(error),
    }
}

/// What a search is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Goal {
    /// The cheapest pattern.
    Best,
    /// The cheapest pattern of a search that drops every partial pattern
    /// another one of the same length and last piece dominates (cheaper,
    /// and connected at least as much: `search/dominance.rs`), where the
    /// targets allow it.
    Dominated,
    /// The cheapest pattern of a search that keeps only the cheapest
    /// states of each length, within the cap (dominated ones dropped first).
    Bounded,
    /// Any pattern, to tell whether there is one: the diagnosis of targets
    /// that cannot be met. Stopping at the first made a refusal's
    /// diagnosis 100 → a few ms where the relaxed targets can be met.
    Any,
}

fn validate(set: &PieceSet, options: &SolveOptions) -> Result<(), SolveError> {
    let invalid = |what: String| Err(SolveError::InvalidOption(what));
    if set.is_empty() {
        return invalid("the exemplar has no piece".into());
    }
    if !(options.target_length.is_finite() && options.target_length > 0.0) {
        return invalid(format!("the curve length {} must be a positive number", options.target_length));
    }
    if !(options.length_tolerance.is_finite() && options.length_tolerance > 0.0) {
        return invalid(format!("the length tolerance {} must be positive", options.length_tolerance));
    }
    if !(options.length_weight.is_finite() && options.length_weight >= 0.0) {
        return invalid(format!("the length weight {} must be zero or more", options.length_weight));
    }
    if !(options.variety.is_finite() && options.variety >= 0.0) {
        return invalid(format!("variety {} must be zero or more", options.variety));
    }
    if options.autocorrelation_sigma.is_nan() || options.autocorrelation_sigma <= 0.0 {
        return invalid("the autocorrelation sigma must be positive".into());
    }
    if options.band_height.is_nan() || options.band_height <= 0.0 {
        return invalid(format!("the band height {} must be positive", options.band_height));
    }
    let grid = LengthGrid::new(set, options);
    let widest = set.pieces.iter().map(|p| p.width).fold(0.0, f64::max);
    if grid.quantum.is_nan()
        || grid.quantum <= 0.0
        || options.target_length / grid.quantum > 5e7
        || widest / grid.quantum > 5e6
    {
        return invalid(
            "the curve is too long for pieces this small: widen the band, raise the scale, or draw a shorter curve"
                .into(),
        );
    }
    Ok(())
}

/// The length tolerances tried in turn, in exemplar units: ε, then wider
/// when nothing fits, up to half the length. Beyond that the pattern would be
/// stretched out of shape and the targets, not the length, are the problem.
pub fn tolerance_levels(options: &SolveOptions) -> Vec<f64> {
    let base = options.length_tolerance * options.target_length;
    let mut levels = vec![base];
    for wider in [4.0 * base, 0.5 * options.target_length] {
        if wider > *levels.last().unwrap_or(&0.0) {
            levels.push(wider);
        }
    }
    levels
}
