//! The search: one dynamic program per start piece (in parallel on loops),
//! over growing length tolerances, and the finished solution recomputed from
//! the pieces themselves.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

mod band;
mod bound;
mod cap;
mod dominance;
mod finish;
mod keep;
mod narrowing;
mod schedule;
mod topology;

use band::{MAX_HOLD, band_allowance};
use bound::CompletionBound;
use finish::finish;
use keep::Looked;
use schedule::in_order_of_size;
use topology::leave_out_what_loops_cannot_cross;
pub(super) use topology::{Topology, search_all};

use super::state::{Arena, Bucket, Interner, LengthGrid, NO_PARENT, PRUNED, State, UNKNOWN};
use super::{CurveKind, Goal, Solution, SolveOptions, tolerance_levels};
use crate::control::Control;
use crate::random::splitmix64;
use crate::vector_brush::{Autocorrelation, MATCH_WEIGHT, PieceSet, Similarity, SolveError, TopologyDescriptor};

/// The variety weight [`super::SolveOptions::diversity`] was set against.
const DIVERSITY_VARIETY: f64 = 0.3;
/// Everything one search needs that does not change while it runs.
pub(super) struct Problem<'a> {
    set: &'a PieceSet,
    options: &'a SolveOptions,
    grid: LengthGrid,
    steps: Vec<u32>,
    widths: Vec<f64>,
    /// Pair costs, seed jitter excluded, `NaN` when incompatible.
    cost: Vec<f64>,
    /// `δ` after joining `a` then `b` is `δ·keep[a·n+b] + τ[a·n+b]`: a break
    /// (a seam without portals) starts a new chain back on the axis.
    tau: Vec<f64>,
    keep: Vec<f32>,
    /// How far each piece may be raised or lowered and stay in the band
    /// (infinite without a band limit).
    allowance: Vec<f32>,
    /// Most a piece may be held back from its alignment to stay in the band.
    max_hold: f32,
    jitter: f64,
    /// What each seam pays for having been used by earlier solutions.
    reuse: Vec<f64>,
    /// On loops, the order of the start pieces: the search from a piece uses
    /// only pieces ranked at or after it, so each cycle is searched once, in
    /// the rotation that starts with its first-ranked piece.
    rank: Vec<u32>,
    similarity: Similarity,
    /// When set, at most this many states of each length are expanded (the
    /// cheapest), and `bounded` records that some were dropped.
    beam: Option<usize>,
    bounded: &'a AtomicBool,
    /// Whether any pattern will do ([`Goal::Any`]): every search stops
    /// once one of them has found one.
    stop_at_first: bool,
    found_any: &'a AtomicBool,
    /// Whether partial patterns another one dominates are dropped
    /// ([`Search::drop_dominated`]), where the targets allow it.
    dominance: bool,
    /// Whether descriptors are followed. Where the targets ask for nothing
    /// ("any" parts and holes), every state shares one descriptor, and the
    /// finished pattern is checked afterwards ([`search_all`]).
    topology: Topology,
    states: &'a AtomicUsize,
    /// Bytes of room for open states held by the searches running at once,
    /// against [`cap::room_budget`].
    room: &'a AtomicUsize,
    /// Set once a search has passed the cap (or is bound to): the others
    /// of the same window stop, since the window's answer is then the cap
    /// error whatever they find.
    capped: &'a AtomicBool,
    created: &'a AtomicUsize,
    work_done: &'a AtomicUsize,
    work_total: usize,
    control: &'a Control<'a>,
}

/// The best finished sequence of one search, if any.
pub(super) struct Found {
    total: f64,
    pieces: Vec<usize>,
    offsets: Vec<f64>,
}

impl Problem<'_> {
    fn n(&self) -> usize {
        self.set.len()
    }

    fn join(&self, interner: &mut Interner, descriptor: u32, piece: usize) -> u32 {
        if self.topology == Topology::Ignored {
            return descriptor;
        }
        let slot = descriptor as usize * interner.pieces + piece;
        let cached = interner.joins[slot];
        if cached != UNKNOWN {
            return cached;
        }
        let joined = interner.list[descriptor as usize]
            .join(&self.set.pieces[piece].descriptor)
            .map(|d| self.options.clamp(&d))
            .filter(|d| self.options.viable(d));
        let id = match joined {
            Some(d) => interner.intern(d),
            None => PRUNED,
        };
        interner.joins[slot] = id;
        id
    }

    fn seam_cost(&self, a: usize, b: usize, length: u32) -> f64 {
        let base = self.cost[a * self.n() + b] + self.reuse[a * self.n() + b];
        if self.options.seed == 0 || self.jitter == 0.0 {
            return base;
        }
        // Vary the perturbation along the curve, in blocks of about a piece,
        // so that another seed changes the pattern everywhere, not just once.
        let block = u64::from(length / self.steps[a].max(1));
        // A well-spread hash of the seed and the seam.
        let h = splitmix64(self.options.seed ^ splitmix64(block << 32 | (a as u64) << 16 | b as u64));
        base + self.jitter * (h >> 11) as f64 / (1u64 << 53) as f64
    }

    fn report_progress(&self) {
        let done = self.work_done.fetch_add(1, Ordering::Relaxed) + 1;
        if done.is_multiple_of(16) || done == self.work_total {
            self.control.report(done as f32 / self.work_total.max(1) as f32);
        }
    }

    /// The descriptor a pattern starting with `piece` begins with, or
    /// `None` where it can no longer meet the targets.
    fn start_descriptor(&self, interner: &mut Interner, piece: usize) -> Option<u32> {
        if self.topology == Topology::Ignored {
            return Some(interner.intern(TopologyDescriptor::default()));
        }
        let d = self.options.clamp(&self.set.pieces[piece].descriptor);
        self.options.viable(&d).then(|| interner.intern(d))
    }

    /// One search from the given start pieces, using pieces ranked at
    /// `min_rank` or later; returns the best finished sequence whose true
    /// length is in `window` (exemplar units).
    fn search(&self, starts: &[usize], min_rank: u32, window: (f64, f64)) -> Result<Option<Found>, SolveError> {
        let mut search = Search::new(self, starts, min_rank, window);
        let result = search.run();
        self.states.fetch_sub(search.counted + search.reserved, Ordering::Relaxed);
        self.room.fetch_sub(search.held_room, Ordering::Relaxed);
        self.created.fetch_add(search.counted, Ordering::Relaxed);
        result?;
        Ok(search.best.map(|(total, end)| search.backtrack(end, total)))
    }
}

/// The table of one search: open states grouped by length, expanded ones
/// in an arena of traces.
pub(super) struct Search<'p> {
    problem: &'p Problem<'p>,
    starts: &'p [usize],
    /// Accepted true lengths, exemplar units.
    window: (f64, f64),
    /// The last key a state can have.
    max_key: u32,
    /// For each piece, the pieces that may follow it.
    compatible: Vec<Vec<usize>>,
    interner: Interner,
    /// Expanded states, for backtracking.
    arena: Arena,
    /// States this search has created, all counted against the cap.
    counted: usize,
    /// States taken from the cap's shared count but not yet created.
    reserved: usize,
    /// Bytes of one open state's room ([`cap::open_state_bytes`]); none in
    /// the bounded search, whose beam keeps that room small.
    open_bytes: usize,
    /// Bytes this search holds of the shared room.
    held_room: usize,
    /// States by length, modulo the widest piece: only lengths within one
    /// piece of the current one are ever open, and their tables are reused.
    buckets: Vec<Bucket>,
    best: Option<(f64, u32)>,
    /// The least any finish costs after each piece and length.
    bound: CompletionBound,
    /// States created before each key was expanded, from the first:
    /// how fast the search grows.
    growth: Vec<usize>,
}

impl<'p> Search<'p> {
    fn new(problem: &'p Problem<'p>, starts: &'p [usize], min_rank: u32, window: (f64, f64)) -> Self {
        let n = problem.n();
        let compatible: Vec<Vec<usize>> = (0..n)
            .map(|a| (0..n).filter(|&b| problem.rank[b] >= min_rank && !problem.cost[a * n + b].is_nan()).collect())
            .collect();
        // A piece of `k` whole steps moves the key by at most `k + 1`.
        let ring = problem.steps.iter().copied().max().unwrap_or(1) as usize + 2;
        let closing = (problem.options.curve == CurveKind::Closed).then(|| starts[0]);
        let bound =
            CompletionBound::new(&problem.cost, &compatible, &problem.steps, problem.grid.quantum, window.0, closing);
        Search {
            bound,
            problem,
            starts,
            window,
            max_key: problem.grid.key(window.1),
            compatible,
            interner: Interner::new(n),
            arena: Arena::default(),
            counted: 0,
            reserved: 0,
            open_bytes: if problem.beam.is_none() { cap::open_state_bytes(problem.options.variety > 0.0) } else { 0 },
            held_room: 0,
            buckets: (0..ring).map(|_| Bucket::default()).collect(),
            best: None,
            growth: Vec::new(),
        }
    }

    fn variety(&self) -> bool {
        self.problem.options.variety > 0.0
    }

    fn run(&mut self) -> Result<(), SolveError> {
        let problem = self.problem;
        let (max_len, max_key) = (self.window.1, self.max_key);
        let mut first_key = 0;
        if let Some(key) = self.seed_prefix()? {
            first_key = key;
        }
        for &s in self.starts.iter().filter(|_| first_key == 0) {
            let length = problem.widths[s];
            if length > max_len {
                continue;
            }
            let Some(descriptor) = problem.start_descriptor(&mut self.interner, s) else {
                continue;
            };
            let state = State { cost: 0.0, length, parent: NO_PARENT, descriptor, delta: 0.0, piece: s as u16 };
            let key = problem.grid.key(length).max(1);
            self.add(key, state, 0.0, || Autocorrelation::default().push(s, &problem.similarity))?;
        }
        let (mut open, mut autos): (Vec<State>, Vec<Autocorrelation>) = (Vec::new(), Vec::new());
        let (mut followers, mut looked): (Vec<(u32, State)>, Vec<Looked>) = (Vec::new(), Vec::new());
        for key in first_key..=max_key {
            if problem.stop_at_first && problem.found_any.load(Ordering::Relaxed) {
                break;
            }
            problem.control.check()?;
            problem.report_progress();
            if problem.capped.load(Ordering::Relaxed) || self.bound_to_pass_cap(key, first_key) {
                return Err(self.passed_cap());
            }
            let slot = key as usize % self.buckets.len();
            open.clear();
            autos.clear();
            self.buckets[slot].drain_into(&mut open, &mut autos);
            if self.dominance_applies() {
                self.drop_dominated(&mut open, &mut autos);
            }
            if let Some(width) = problem.beam
                && open.len() > width
            {
                self.keep_cheapest(width, &mut open, &mut autos);
            }
            for (i, state) in open.iter().enumerate() {
                // Borrowed, not copied: a history is 104 bytes, and the copy
                // was a call to `memcpy` for every state expanded.
                let auto = autos.get(i).unwrap_or(&Autocorrelation::EMPTY);
                let a = state.piece as usize;
                let floor = if self.variety() { problem.options.variety * auto.value() } else { 0.0 };
                // The incumbent may have dropped since the state was kept.
                if !self.promising(state.cost + floor, a, state.length) {
                    continue;
                }
                let index = self.arena.push(state.parent, state.piece);
                if state.length >= self.window.0 {
                    self.consider_end(state, auto, index);
                }
                followers.clear();
                for k in 0..self.compatible[a].len() {
                    let b = self.compatible[a][k];
                    let next_length = state.length + problem.widths[b];
                    if next_length > max_len {
                        continue;
                    }
                    let Some(next) = self.follow(state, index, key, b) else {
                        continue;
                    };
                    if !self.promising(next.cost + floor, b, next.length) {
                        continue;
                    }
                    // Never below the next key, whatever the rounding: the
                    // search runs in order of keys. (Only for the followers
                    // kept: a division each.)
                    let next_key = problem.grid.key(next_length).max(key + 1);
                    followers.push((next_key, next));
                }
                // Every follower is looked up before any is kept: their
                // table slots are scattered over megabytes, and looked up
                // in a row their cache misses overlap instead of queueing
                // one after the other. The followers have distinct pieces,
                // hence distinct keys, so keeping one never moves another.
                looked.clear();
                looked.extend(followers.iter().map(|(next_key, next)| self.lookup(*next_key, next)));
                for (&(_, next), &found) in followers.iter().zip(&looked) {
                    let b = usize::from(next.piece);
                    self.add_looked_up(found, next, floor, || auto.push(b, &problem.similarity))?;
                }
            }
        }
        Ok(())
    }

    /// Records the state (traced in the arena at `index`) as a finished
    /// pattern if it closes and meets the targets.
    fn consider_end(&mut self, state: &State, auto: &Autocorrelation, index: u32) {
        let problem = self.problem;
        let options = problem.options;
        let a = state.piece as usize;
        let target = options.target_length;
        let epsilon = (self.window.1 - target * (1.0 + LENGTH_SLACK)).max(f64::MIN_POSITIVE);
        let mut total = state.cost + options.length_weight * ((state.length - target) / epsilon).powi(2);
        if options.curve == CurveKind::Closed {
            // One search per start piece: its only start closes the loop.
            let s = self.starts[0];
            let closing = problem.cost[a * problem.n() + s];
            let seam = a * problem.n() + s;
            if closing.is_nan() {
                return;
            }
            // The loop closes onto the first piece, on the axis: what the
            // offsets do not close is spread over the seams afterwards.
            let raw = problem.aligned(state.delta, a, s);
            if raw.abs() > problem.max_hold {
                return;
            }
            total += closing + problem.reuse[seam];
            if options.band_height.is_finite() {
                total += problem.misalignment_cost(raw);
            }
        }
        if problem.topology == Topology::Ignored {
            // What the targets ask of a finished pattern is checked on the
            // best one afterwards; an open curve's pattern ends without a
            // portal left open.
            if options.curve == CurveKind::Open && !problem.set.pieces[a].right.is_empty() {
                return;
            }
        } else {
            let Some(t) = problem.options.finished(&self.interner.list[state.descriptor as usize]) else {
                return;
            };
            if !problem.options.meets_targets(t) {
                return;
            }
        }
        if self.variety() {
            total += options.variety * auto.value();
        }
        if self.best.is_none_or(|(b, _)| total < b) {
            self.best = Some((total, index));
            problem.found_any.store(true, Ordering::Relaxed);
        }
    }

    /// The state after `state` (in the arena at `parent`, keyed `key`) when
    /// piece `b` follows it, or `None` where `b` cannot be held in the band
    /// or the targets could no longer be met.
    #[inline(always)]
    fn follow(&mut self, state: &State, parent: u32, key: u32, b: usize) -> Option<State> {
        let problem = self.problem;
        let a = usize::from(state.piece);
        let (delta, held_back) = problem.offset_after(state.delta, a, b)?;
        let descriptor = problem.join(&mut self.interner, state.descriptor, b);
        if descriptor == PRUNED {
            return None;
        }
        Some(State {
            cost: state.cost + problem.seam_cost(a, b, key) + held_back,
            length: state.length + problem.widths[b],
            parent,
            descriptor,
            delta,
            piece: b as u16,
        })
    }

    fn backtrack(&self, end: u32, total: f64) -> Found {
        let pieces = self.arena.pieces_to(end);
        let offsets = self.problem.offsets_of(&pieces);
        Found { total, pieces, offsets }
    }
}

/// Slack on the accepted lengths, relative to the target length.
const LENGTH_SLACK: f64 = 1e-9;

/// One search over growing tolerances, following the descriptors or not.
pub(super) fn search_with(
    set: &PieceSet,
    options: &SolveOptions,
    goal: Goal,
    control: &Control,
    topology: Topology,
) -> Result<Option<Solution>, SolveError> {
    let bounded_search = goal == Goal::Bounded;
    let n = set.len();
    let grid = LengthGrid::new(set, options);
    let steps: Vec<u32> = set.pieces.iter().map(|p| grid.steps(p.width)).collect();
    let widths: Vec<f64> = set.pieces.iter().map(|p| p.width).collect();
    let mut cost = vec![f64::NAN; n * n];
    let mut tau = vec![0.0; n * n];
    let mut keep = vec![1.0; n * n];
    for a in 0..n {
        for b in 0..n {
            if let Some(pair) = set.pair(a, b) {
                cost[a * n + b] = pair.cost_at(options.misfit_weight);
                tau[a * n + b] = pair.tau;
                if set.joining(a, b).is_none() {
                    keep[a * n + b] = 0.0;
                }
            }
        }
    }
    let compatible_costs: Vec<f64> = cost.iter().copied().filter(|c| !c.is_nan()).collect();
    let mean_cost = compatible_costs.iter().sum::<f64>() / compatible_costs.len().max(1) as f64;
    let jitter = 0.5 * mean_cost;
    // Exemplars whose seams all match perfectly still pay for reuse.
    let mean_cost = mean_cost.max(1e-3 * MATCH_WEIGHT);
    // A heavier variety term pulls alternatives back as much more strongly.
    let variety_pull = (options.variety / DIVERSITY_VARIETY).max(1.0);
    let mut reuse = vec![0.0; n * n];
    for earlier in &options.avoid {
        let closing = (options.curve == CurveKind::Closed).then(|| (earlier.last(), earlier.first()));
        let seams = earlier.windows(2).map(|w| (w[0], w[1])).chain(closing.and_then(|(a, b)| Some((*a?, *b?))));
        let mut seen = vec![false; n * n];
        for (a, b) in seams.filter(|&(a, b)| a < n && b < n) {
            if !std::mem::replace(&mut seen[a * n + b], true) {
                reuse[a * n + b] += options.diversity * mean_cost * variety_pull;
            }
        }
    }
    if topology == Topology::Ignored && options.curve == CurveKind::Closed && options.closed_pattern {
        // After the mean seam cost above, which sets the jitter and the
        // reuse penalty, so that the objective is the one the full search
        // minimizes.
        leave_out_what_loops_cannot_cross(set, &mut cost);
    }
    let states = AtomicUsize::new(0);
    let room = AtomicUsize::new(0);
    let capped = AtomicBool::new(false);
    let bounded = AtomicBool::new(false);
    let found_any = AtomicBool::new(false);
    let created = AtomicUsize::new(0);
    let work_done = AtomicUsize::new(0);
    let tolerances = tolerance_levels(options);
    let runs_per_level = match options.curve {
        CurveKind::Open => 1,
        CurveKind::Closed => n,
    };
    // Sums of the same widths in another order differ in the last bits: a
    // hair of slack keeps a loop's acceptance the same in every rotation.
    let slack = LENGTH_SLACK * options.target_length;
    let window_of = |tolerance: f64| {
        ((options.target_length - tolerance - slack).max(0.0), options.target_length + tolerance + slack)
    };
    let work_total = runs_per_level * (grid.key(window_of(tolerances[0]).1) as usize + 1);
    // A loop's search carries its start piece's left portals until the loop
    // closes, and the first search may use every piece: starting with the
    // pieces that leave the fewest portals open keeps the largest searches
    // the smallest.
    let mut order: Vec<usize> = (0..n).collect();
    if options.curve == CurveKind::Closed {
        order.sort_by_key(|&p| set.pieces[p].left.len());
    }
    // Largest first, where the best pattern is wanted, so that the search
    // that decides how long the loop takes starts at once; smallest first
    // where any pattern will do, since every search stops once one has
    // found one, and the small ones finish first (`search/schedule.rs`).
    let schedule: Vec<usize> = if goal == Goal::Any { order.iter().rev().copied().collect() } else { order.clone() };
    let mut rank = vec![0; n];
    for (r, &p) in order.iter().enumerate() {
        rank[p] = r as u32;
    }
    let mut problem = Problem {
        set,
        rank,
        options,
        grid,
        steps,
        widths,
        cost,
        tau,
        keep,
        allowance: set.pieces.iter().map(|p| band_allowance(options.band_height, p.extent()) as f32).collect(),
        max_hold: (MAX_HOLD * options.band_height).min(f64::from(f32::MAX)) as f32,
        jitter,
        reuse,
        similarity: Similarity::new(options.autocorrelation_sigma),
        beam: None,
        bounded: &bounded,
        stop_at_first: goal == Goal::Any,
        dominance: matches!(goal, Goal::Dominated | Goal::Bounded),
        found_any: &found_any,
        topology,
        states: &states,
        room: &room,
        capped: &capped,
        created: &created,
        work_done: &work_done,
        work_total,
        control,
    };
    // A fixed beginning is worth keeping only if it fits at the usual
    // tolerance: wider searches from it would cost more than starting again.
    let levels = if options.prefix.is_empty() { tolerances.len() } else { 1 };
    for &tolerance in &tolerances[..levels] {
        let window = window_of(tolerance);
        if bounded_search {
            problem.beam = Some(cap::beam_width(options, &problem.steps, grid.key(window.1), runs_per_level));
        }
        problem.work_total = problem.work_total.max(runs_per_level * (grid.key(window.1) as usize + 1));
        let found = match options.curve {
            CurveKind::Open => {
                let starts: Vec<usize> = (0..n).filter(|&i| set.pieces[i].left.is_empty()).collect();
                problem.search(&starts, 0, window)?
            }
            CurveKind::Closed => {
                let results = in_order_of_size(&schedule, |s| problem.search(&[s], problem.rank[s], window));
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
            control.report(1.0);
            let mut solution = finish(set, options, found, tolerance, created.load(Ordering::Relaxed));
            solution.bounded = bounded.load(Ordering::Relaxed).then_some(problem.beam.unwrap_or(0));
            solution.dominance = goal == Goal::Dominated;
            return Ok(Some(solution));
        }
    }
    Ok(None)
}
