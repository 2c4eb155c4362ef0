//! The topology solver: dynamic programming over piece sequences (sections 3.5 to 3.7).
//!
//! # State
//!
//! A partial solution is keyed by *(last piece, topology descriptor, length)*,
//! with the length counted in integer steps of a small quantum. Lengths only
//! grow, so states are expanded in order of length, and two partial solutions
//! compete only when they agree on all three: no solution is lost because it
//! differs from a cheaper one in length alone (the paper keys by the number of
//! pieces instead, which merges sequences of different lengths). With the
//! variety term off and no band limit, the search is exact over the
//! quantized widths; the exactness test checks it against exhaustive search.
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

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use rayon::prelude::*;
use rustc_hash::FxHashMap;
use serde::{Deserialize, Serialize};

use crate::{Autocorrelation, PieceSet, Similarity, SolveError, TopologyDescriptor, Unmet};

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
    /// Height of the band, in exemplar units: partial solutions whose
    /// accumulated vertical offset leaves `±band_height / 2` are dropped.
    /// Infinite turns the limit off.
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
    /// Length quantum in exemplar units; `None` picks a third of the
    /// narrowest piece (at most a fiftieth of ε).
    pub length_quantum: Option<f64>,
    /// Most DP states held at once before giving up with an error.
    pub max_states: usize,
    /// Zero for the best solution; any other value perturbs the seam costs
    /// along the curve to give another, slightly worse, pattern.
    pub seed: u64,
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
            max_states: 2_000_000,
            seed: 0,
        }
    }
}

/// Cancellation and progress for a running search.
#[derive(Clone, Copy, Default)]
pub struct Control<'a> {
    /// Set to stop the search; it then returns [`SolveError::Cancelled`].
    pub cancel: Option<&'a AtomicBool>,
    /// Called with the fraction done, from 0 to 1, possibly from several threads.
    pub progress: Option<&'a (dyn Fn(f32) + Sync)>,
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
}

/// Lengths as integer steps of a quantum, shared by the solver and its tests.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LengthGrid {
    /// Exemplar units per step.
    pub quantum: f64,
    /// The target length in steps.
    pub target: u32,
}

impl LengthGrid {
    /// The grid the solver uses for `set` and `options`.
    pub fn new(set: &PieceSet, options: &SolveOptions) -> Self {
        let narrowest = set.pieces.iter().map(|p| p.width).fold(f64::INFINITY, f64::min);
        let epsilon = options.length_tolerance * options.target_length;
        let quantum = options.length_quantum.unwrap_or_else(|| (narrowest / 3.0).min(epsilon / 50.0).max(1e-12));
        LengthGrid { quantum, target: (options.target_length / quantum).round() as u32 }
    }

    /// A width (or length) in steps; every piece takes at least one step.
    pub fn steps(&self, width: f64) -> u32 {
        ((width / self.quantum).round() as u32).max(1)
    }

    /// The accepted window `[lo, hi]` in steps for a tolerance in exemplar units.
    pub fn window(&self, tolerance: f64) -> (u32, u32) {
        let e = (tolerance / self.quantum).floor() as u32;
        (self.target.saturating_sub(e), self.target + e)
    }
}

const UNKNOWN: u32 = u32::MAX - 1;
const PRUNED: u32 = u32::MAX;
const NO_PARENT: u32 = u32::MAX;

#[derive(Clone, Copy)]
struct State {
    cost: f64,
    parent: u32,
    descriptor: u32,
    delta: f32,
    piece: u16,
}

/// The states of one length, indexed by `descriptor × pieces + piece`.
#[derive(Default)]
struct Bucket {
    slots: Vec<u32>,
    /// Occupied slots, in insertion order (which is also the expansion order).
    occupied: Vec<u32>,
}

impl Bucket {
    fn get(&self, key: usize) -> Option<u32> {
        self.slots.get(key).copied().filter(|&i| i != NO_PARENT)
    }

    fn insert(&mut self, key: usize, index: u32) {
        if key >= self.slots.len() {
            self.slots.resize((key + 1).next_power_of_two(), NO_PARENT);
        }
        self.slots[key] = index;
        self.occupied.push(key as u32);
    }

    /// Moves the state indices out, leaving the bucket empty for reuse.
    fn drain_into(&mut self, out: &mut Vec<u32>) {
        for key in self.occupied.drain(..) {
            out.push(std::mem::replace(&mut self.slots[key as usize], NO_PARENT));
        }
    }
}

/// Descriptors seen in one search, with memoized joins.
struct Interner {
    ids: FxHashMap<TopologyDescriptor, u32>,
    list: Vec<TopologyDescriptor>,
    joins: Vec<u32>,
    pieces: usize,
}

impl Interner {
    fn new(pieces: usize) -> Self {
        Interner { ids: FxHashMap::default(), list: Vec::new(), joins: Vec::new(), pieces }
    }

    fn intern(&mut self, d: TopologyDescriptor) -> u32 {
        if let Some(&id) = self.ids.get(&d) {
            return id;
        }
        let id = self.list.len() as u32;
        self.ids.insert(d.clone(), id);
        self.list.push(d);
        self.joins.resize(self.joins.len() + self.pieces, UNKNOWN);
        id
    }
}

/// Everything one search needs that does not change while it runs.
struct Problem<'a> {
    set: &'a PieceSet,
    options: &'a SolveOptions,
    grid: LengthGrid,
    steps: Vec<u32>,
    /// Pair costs, seed jitter excluded, `NaN` when incompatible.
    cost: Vec<f64>,
    tau: Vec<f64>,
    jitter: f64,
    similarity: Similarity,
    states: &'a AtomicUsize,
    created: &'a AtomicUsize,
    work_done: &'a AtomicUsize,
    work_total: usize,
    control: &'a Control<'a>,
}

/// The best finished sequence of one search, if any.
struct Found {
    total: f64,
    pieces: Vec<usize>,
    offsets: Vec<f64>,
}

fn mix(mut x: u64) -> u64 {
    // splitmix64: a well-spread hash of the seed and the seam.
    x = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

impl Problem<'_> {
    fn n(&self) -> usize {
        self.set.len()
    }

    fn clamp(&self, d: &TopologyDescriptor) -> TopologyDescriptor {
        let closed = if self.options.components == Target::Any { 0 } else { d.closed_components() as u16 };
        let holes = if self.options.holes == Target::Any { 0 } else { d.holes() as u16 };
        d.with_counters(closed, holes)
    }

    /// Whether a partial solution can still meet the targets.
    fn viable(&self, d: &TopologyDescriptor) -> bool {
        !self.options.components.exceeded_by(d.min_final_components()) && !self.options.holes.exceeded_by(d.holes())
    }

    fn join(&self, interner: &mut Interner, descriptor: u32, piece: usize) -> u32 {
        let slot = descriptor as usize * interner.pieces + piece;
        let cached = interner.joins[slot];
        if cached != UNKNOWN {
            return cached;
        }
        let joined = interner.list[descriptor as usize]
            .join(&self.set.pieces[piece].descriptor)
            .map(|d| self.clamp(&d))
            .filter(|d| self.viable(d));
        let id = match joined {
            Some(d) => interner.intern(d),
            None => PRUNED,
        };
        interner.joins[slot] = id;
        id
    }

    fn seam_cost(&self, a: usize, b: usize, length: u32) -> f64 {
        let base = self.cost[a * self.n() + b];
        if self.options.seed == 0 || self.jitter == 0.0 {
            return base;
        }
        // Vary the perturbation along the curve, in blocks of about a piece,
        // so that another seed changes the pattern everywhere, not just once.
        let block = u64::from(length / self.steps[a].max(1));
        let h = mix(self.options.seed ^ mix(block << 32 | (a as u64) << 16 | b as u64));
        base + self.jitter * (h >> 11) as f64 / (1u64 << 53) as f64
    }

    fn finished(&self, d: &TopologyDescriptor) -> Option<(u32, u32, u32)> {
        match self.options.curve {
            CurveKind::Open => d.is_finished().then(|| (d.components(), d.holes(), 0)),
            CurveKind::Closed => d.close_loop().map(|t| (t.components, t.holes, t.wraps)),
        }
    }

    fn meets_targets(&self, t: (u32, u32, u32)) -> bool {
        let loop_ok = self.options.curve == CurveKind::Open || !self.options.closed_pattern || t.2 > 0;
        self.options.components.accepts(t.0) && self.options.holes.accepts(t.1) && loop_ok
    }

    fn report_progress(&self) {
        let done = self.work_done.fetch_add(1, Ordering::Relaxed) + 1;
        if let Some(progress) = self.control.progress
            && (done.is_multiple_of(16) || done == self.work_total)
        {
            progress((done as f32 / self.work_total.max(1) as f32).min(1.0));
        }
    }

    /// One search from the given start pieces, using pieces `>= min_piece`,
    /// up to `window.1` steps; returns the best finished sequence in `window`.
    fn search(&self, starts: &[usize], min_piece: usize, window: (u32, u32)) -> Result<Option<Found>, SolveError> {
        let mut search = Search::new(self, starts, min_piece, window);
        let result = search.run();
        self.states.fetch_sub(search.arena.len(), Ordering::Relaxed);
        result?;
        Ok(search.best.map(|(total, end)| search.backtrack(end, total)))
    }
}

/// The table of one search: states in an arena, grouped by length.
struct Search<'p> {
    problem: &'p Problem<'p>,
    starts: &'p [usize],
    window: (u32, u32),
    /// For each piece, the pieces that may follow it.
    compatible: Vec<Vec<usize>>,
    interner: Interner,
    arena: Vec<State>,
    /// Variety history per state, only when the variety term is on.
    auto: Vec<Autocorrelation>,
    /// States by length, modulo the widest piece: only lengths within one
    /// piece of the current one are ever open, and their tables are reused.
    buckets: Vec<Bucket>,
    best: Option<(f64, u32)>,
}

impl<'p> Search<'p> {
    fn new(problem: &'p Problem<'p>, starts: &'p [usize], min_piece: usize, window: (u32, u32)) -> Self {
        let n = problem.n();
        let compatible =
            (0..n).map(|a| (min_piece..n).filter(|&b| !problem.cost[a * n + b].is_nan()).collect()).collect();
        let ring = problem.steps.iter().copied().max().unwrap_or(1) as usize + 1;
        Search {
            problem,
            starts,
            window,
            compatible,
            interner: Interner::new(n),
            arena: Vec::new(),
            auto: Vec::new(),
            buckets: (0..ring).map(|_| Bucket::default()).collect(),
            best: None,
        }
    }

    fn variety(&self) -> bool {
        self.problem.options.variety > 0.0
    }

    fn total(&self, state: &State, correlation: &Autocorrelation) -> f64 {
        if self.variety() { state.cost + self.problem.options.variety * correlation.value() } else { state.cost }
    }

    /// Keeps `state` at `length` unless a cheaper one with the same key is
    /// there. `penalty_floor` is a lower bound of the variety penalty of
    /// `state` (its parent's: the per-lag sums only grow), so the new
    /// autocorrelation is computed only when the state may win.
    fn add(
        &mut self,
        length: u32,
        state: State,
        penalty_floor: f64,
        correlation: impl FnOnce(&Self) -> Autocorrelation,
    ) -> Result<(), SolveError> {
        // Descriptor ids are dense and few: a state's key indexes a table.
        let key = state.descriptor as usize * self.problem.n() + usize::from(state.piece);
        let slot = length as usize % self.buckets.len();
        let variety = self.variety();
        if let Some(existing) = self.buckets[slot].get(key) {
            let old = &self.arena[existing as usize];
            let old_total = if variety { self.total(old, &self.auto[existing as usize]) } else { old.cost };
            if old_total <= state.cost + penalty_floor {
                return Ok(());
            }
            if variety {
                let correlation = correlation(self);
                if self.total(&state, &correlation) < old_total {
                    self.arena[existing as usize] = state;
                    self.auto[existing as usize] = correlation;
                }
            } else {
                self.arena[existing as usize] = state;
            }
            return Ok(());
        }
        let problem = self.problem;
        if problem.states.fetch_add(1, Ordering::Relaxed) + 1 > problem.options.max_states {
            return Err(SolveError::TooManyStates {
                limit: problem.options.max_states,
                megabytes: problem.options.max_states * STATE_BYTES / (1 << 20),
            });
        }
        problem.created.fetch_add(1, Ordering::Relaxed);
        self.buckets[slot].insert(key, self.arena.len() as u32);
        self.arena.push(state);
        if variety {
            let correlation = correlation(self);
            self.auto.push(correlation);
        }
        Ok(())
    }

    fn run(&mut self) -> Result<(), SolveError> {
        let problem = self.problem;
        let n = problem.n();
        let max_len = self.window.1;
        let half_band = 0.5 * problem.options.band_height;
        for &s in self.starts {
            let length = problem.steps[s];
            let d = problem.clamp(&problem.set.pieces[s].descriptor);
            if length > max_len || !problem.viable(&d) {
                continue;
            }
            let descriptor = self.interner.intern(d);
            let state = State { cost: 0.0, parent: NO_PARENT, descriptor, delta: 0.0, piece: s as u16 };
            self.add(length, state, 0.0, |_| Autocorrelation::default().push(s, &problem.similarity))?;
        }
        let mut open: Vec<u32> = Vec::new();
        for length in 0..=max_len {
            if problem.control.cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
                return Err(SolveError::Cancelled);
            }
            problem.report_progress();
            let slot = length as usize % self.buckets.len();
            open.clear();
            self.buckets[slot].drain_into(&mut open);
            for &index in &open {
                let state = self.arena[index as usize];
                let a = state.piece as usize;
                if length >= self.window.0 {
                    self.consider_end(index, length);
                }
                for k in 0..self.compatible[a].len() {
                    let b = self.compatible[a][k];
                    let next_length = length + problem.steps[b];
                    if next_length > max_len {
                        continue;
                    }
                    let delta = state.delta + problem.tau[a * n + b] as f32;
                    if f64::from(delta.abs()) > half_band {
                        continue;
                    }
                    let descriptor = problem.join(&mut self.interner, state.descriptor, b);
                    if descriptor == PRUNED {
                        continue;
                    }
                    let next = State {
                        cost: state.cost + problem.seam_cost(a, b, length),
                        parent: index,
                        descriptor,
                        delta,
                        piece: b as u16,
                    };
                    let floor =
                        if self.variety() { problem.options.variety * self.auto[index as usize].value() } else { 0.0 };
                    self.add(next_length, next, floor, |search| {
                        search.auto[index as usize].push(b, &problem.similarity)
                    })?;
                }
            }
        }
        Ok(())
    }

    /// Records the state as a finished pattern if it closes and meets the targets.
    fn consider_end(&mut self, index: u32, length: u32) {
        let problem = self.problem;
        let options = problem.options;
        let state = &self.arena[index as usize];
        let a = state.piece as usize;
        let target = f64::from(problem.grid.target);
        let epsilon = (f64::from(self.window.1) - target).max(1.0);
        let mut total = state.cost + options.length_weight * ((f64::from(length) - target) / epsilon).powi(2);
        if options.curve == CurveKind::Closed {
            // One search per start piece: its only start closes the loop.
            let s = self.starts[0];
            let closing = problem.cost[a * problem.n() + s];
            let delta = state.delta + problem.tau[a * problem.n() + s] as f32;
            if closing.is_nan() || f64::from(delta.abs()) > 0.5 * options.band_height {
                return;
            }
            total += closing;
        }
        let Some(t) = problem.finished(&self.interner.list[state.descriptor as usize]) else {
            return;
        };
        if !problem.meets_targets(t) {
            return;
        }
        if self.variety() {
            total += options.variety * self.auto[index as usize].value();
        }
        if self.best.is_none_or(|(b, _)| total < b) {
            self.best = Some((total, index));
        }
    }

    fn backtrack(&self, end: u32, total: f64) -> Found {
        let mut pieces = Vec::new();
        let mut offsets = Vec::new();
        let mut i = end;
        while i != NO_PARENT {
            let s = &self.arena[i as usize];
            pieces.push(s.piece as usize);
            offsets.push(f64::from(s.delta));
            i = s.parent;
        }
        pieces.reverse();
        offsets.reverse();
        Found { total, pieces, offsets }
    }
}

/// Bytes one DP state takes, with its share of the bucket maps and the
/// variety history; used to turn the state cap into megabytes.
pub const STATE_BYTES: usize = 96;

/// Finds the best piece sequence for `options`.
///
/// ```
/// use tracery_core::{builtin, solve, Control, PieceSet, SliceOptions, SolveOptions};
/// let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
/// let solution = solve(&set, &SolveOptions::new(3.0 * set.exemplar_width), &Control::default()).unwrap();
/// assert_eq!(solution.components, 1);
/// assert!((solution.length / solution.target_length - 1.0).abs() <= solution.tolerance / solution.target_length + 0.01);
/// ```
pub fn solve(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Solution, SolveError> {
    validate(set, options)?;
    match search_all(set, options, control)? {
        Some(solution) => Ok(solution),
        None => Err(SolveError::NoSolution(diagnose(set, options, control)?)),
    }
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
        return invalid("the length quantum is too small for this curve".into());
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

/// Runs the searches for growing tolerances until one finds a solution.
fn search_all(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Option<Solution>, SolveError> {
    let n = set.len();
    let grid = LengthGrid::new(set, options);
    let steps: Vec<u32> = set.pieces.iter().map(|p| grid.steps(p.width)).collect();
    let mut cost = vec![f64::NAN; n * n];
    let mut tau = vec![0.0; n * n];
    for a in 0..n {
        for b in 0..n {
            if let Some(pair) = set.pair(a, b) {
                cost[a * n + b] = pair.cost;
                tau[a * n + b] = pair.tau;
            }
        }
    }
    let compatible_costs: Vec<f64> = cost.iter().copied().filter(|c| !c.is_nan()).collect();
    let jitter = 0.5 * compatible_costs.iter().sum::<f64>() / compatible_costs.len().max(1) as f64;
    let states = AtomicUsize::new(0);
    let created = AtomicUsize::new(0);
    let work_done = AtomicUsize::new(0);
    let tolerances = tolerance_levels(options);
    let runs_per_level = match options.curve {
        CurveKind::Open => 1,
        CurveKind::Closed => n,
    };
    let first_window = grid.window(tolerances[0]);
    let work_total = runs_per_level * (first_window.1 as usize + 1);
    let mut problem = Problem {
        set,
        options,
        grid,
        steps,
        cost,
        tau,
        jitter,
        similarity: Similarity::new(options.autocorrelation_sigma),
        states: &states,
        created: &created,
        work_done: &work_done,
        work_total,
        control,
    };
    for &tolerance in &tolerances {
        let window = grid.window(tolerance);
        let window = (window.0, window.1.max(1));
        problem.work_total = problem.work_total.max(runs_per_level * (window.1 as usize + 1));
        let found = match options.curve {
            CurveKind::Open => {
                let starts: Vec<usize> = (0..n).filter(|&i| set.pieces[i].left.is_empty()).collect();
                problem.search(&starts, 0, window)?
            }
            CurveKind::Closed => {
                let results: Vec<Result<Option<Found>, SolveError>> =
                    (0..n).into_par_iter().map(|s| problem.search(&[s], s, window)).collect();
                let mut best: Option<Found> = None;
                for r in results {
                    if let Some(f) = r?
                        && best.as_ref().is_none_or(|b| f.total < b.total)
                    {
                        best = Some(f);
                    }
                }
                best
            }
        };
        if let Some(found) = found {
            if let Some(progress) = control.progress {
                progress(1.0);
            }
            return Ok(Some(finish(set, options, found, tolerance, created.load(Ordering::Relaxed))));
        }
    }
    Ok(None)
}

/// Recomputes what a sequence achieves from the pieces themselves.
fn finish(set: &PieceSet, options: &SolveOptions, found: Found, tolerance: f64, created: usize) -> Solution {
    let n = found.pieces.len();
    let mut matching = 0.0;
    let mut descriptor = set.pieces[found.pieces[0]].descriptor.clone();
    for w in found.pieces.windows(2) {
        matching += set.pair(w[0], w[1]).map_or(0.0, |p| p.cost);
        descriptor = descriptor.join(&set.pieces[w[1]].descriptor).unwrap_or(descriptor);
    }
    let (components, holes, wraps) = match options.curve {
        CurveKind::Open => (descriptor.components(), descriptor.holes(), 0),
        CurveKind::Closed => {
            matching += set.pair(found.pieces[n - 1], found.pieces[0]).map_or(0.0, |p| p.cost);
            let t = descriptor.close_loop().unwrap_or_default();
            (t.components, t.holes, t.wraps)
        }
    };
    let similarity = Similarity::new(options.autocorrelation_sigma);
    Solution {
        length: found.pieces.iter().map(|&p| set.pieces[p].width).sum(),
        autocorrelation: Autocorrelation::of(&found.pieces, &similarity).value(),
        pieces: found.pieces,
        offsets: found.offsets,
        cost: found.total,
        matching_cost: matching,
        target_length: options.target_length,
        tolerance,
        components,
        holes,
        wraps,
        states: created,
    }
}

/// Finds which target makes the problem impossible, by relaxing them one at a time.
fn diagnose(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Unmet, SolveError> {
    let feasible = |components: Target, holes: Target, closed_pattern: bool| -> Result<bool, SolveError> {
        let relaxed = SolveOptions { components, holes, closed_pattern, variety: 0.0, seed: 0, ..options.clone() };
        Ok(search_all(set, &relaxed, &Control { progress: None, ..*control })?.is_some())
    };
    if options.band_height.is_finite() {
        let unbounded = SolveOptions { band_height: f64::INFINITY, ..options.clone() };
        if search_all(set, &unbounded, &Control { progress: None, ..*control })?.is_some() {
            return Ok(Unmet::Band);
        }
    }
    if !feasible(Target::Any, Target::Any, false)? {
        return Ok(Unmet::NoClosingSequence);
    }
    if options.closed_pattern && options.curve == CurveKind::Closed && !feasible(Target::Any, Target::Any, true)? {
        return Ok(Unmet::ClosedPattern);
    }
    let closed = options.closed_pattern;
    let components_ok = options.components == Target::Any || feasible(options.components, Target::Any, closed)?;
    if !components_ok {
        return Ok(Unmet::Components(options.components));
    }
    let holes_ok = options.holes == Target::Any || feasible(Target::Any, options.holes, closed)?;
    if !holes_ok {
        return Ok(Unmet::Holes(options.holes));
    }
    Ok(Unmet::Combination { components: options.components, holes: options.holes })
}
