//! The state cap, shared by the parallel searches of a loop.

use std::sync::atomic::Ordering;

use super::{Search, State};
use crate::control::StateCap;
use crate::vector_brush::Autocorrelation;
use crate::vector_brush::SolveError;
use crate::vector_brush::solver::{STATE_BYTES, SolveOptions};

/// States a search takes from the cap at a time: while the parallel
/// searches each hold up to this many unused, the cap may be met that many
/// states early (a few thousand of its two million).
pub(super) const RESERVE: usize = 1024;

impl Search<'_> {
    /// Takes states from the cap's count shared by the parallel searches:
    /// [`RESERVE`] at a time while they fit, then one at a time. One shared
    /// counter touched for every state was a tenth of a loop's search time,
    /// the two cores taking its cache line from each other.
    pub(super) fn reserve(&mut self) -> Result<(), SolveError> {
        let problem = self.problem;
        let max = problem.options.max_states;
        for batch in [RESERVE, 1] {
            if problem.states.fetch_add(batch, Ordering::Relaxed) + batch <= max {
                self.reserved = batch;
                return Ok(());
            }
            problem.states.fetch_sub(batch, Ordering::Relaxed);
        }
        Err(self.passed_cap())
    }

    /// Takes `bytes` more of the room for open states shared by the
    /// searches running at once; the cap error where that passes
    /// [`room_budget`]. The room, once made, stays for the whole search
    /// (each length's table is reused), so it is held until the search
    /// ends.
    pub(super) fn make_room(&mut self, bytes: usize) -> Result<(), SolveError> {
        let problem = self.problem;
        self.held_room += bytes;
        let held = problem.room.fetch_add(bytes, Ordering::Relaxed) + bytes;
        if held > room_budget(problem.options.max_states) { Err(self.passed_cap()) } else { Ok(()) }
    }

    /// The cap error, after telling the other searches of the window to stop.
    pub(super) fn passed_cap(&self) -> SolveError {
        self.problem.capped.store(true, Ordering::Relaxed);
        let cap = StateCap { max_states: self.problem.options.max_states, bytes_per_state: STATE_BYTES };
        SolveError::TooManyStates { limit: cap.max_states, megabytes: cap.megabytes() }
    }

    /// Whether this search, about to expand `key` (it began at
    /// `first_key`), is bound to pass the cap on its own: its states grow
    /// at an about steady rate once the descriptors have appeared, so the
    /// rate over the second half of the lengths done so far, carried to the
    /// last length, tells where it will end. It is trusted only past
    /// [`PROJECT_AFTER`] of the lengths and with [`PROJECTED_MARGIN`] to
    /// spare. The other searches running at once are left out: they may
    /// end and give their states back before this one grows, and a search
    /// that passes the cap on its own passes it whatever they do. A search
    /// that stops at the first pattern, or keeps only the cheapest states,
    /// is not projected.
    pub(super) fn bound_to_pass_cap(&mut self, key: u32, first_key: u32) -> bool {
        let problem = self.problem;
        if problem.beam.is_some() || problem.stop_at_first {
            return false;
        }
        self.growth.push(self.counted);
        let (done, total) = ((key - first_key) as usize, (self.max_key - first_key) as usize + 1);
        if done < MIN_PROJECTED_LENGTHS || (done as f64) < PROJECT_AFTER * total as f64 {
            return false;
        }
        let half = done / 2;
        let rate = self.counted.saturating_sub(self.growth[half]) as f64 / (done - half) as f64;
        let projected = self.counted as f64 + rate * (total - done) as f64;
        projected > PROJECTED_MARGIN * problem.options.max_states as f64
    }
}

/// The bytes of the room for one open state: the whole state, with its
/// variety history where the variety term is on, its key and two slots of
/// its length's table.
pub(super) fn open_state_bytes(variety: bool) -> usize {
    let history = if variety { std::mem::size_of::<Autocorrelation>() } else { 0 };
    std::mem::size_of::<State>() + history + 4 + 2 * 8
}

/// The room for open states the exact searches running at once may hold,
/// bytes: 13/16 of the cap's, beside it (26 MB beside the 32 MB of the
/// default 4 M states, 63 MB with what the process holds before the
/// search). The largest exact search of the corpus needs 25 MB of it
/// (`vectorian168` round `circle:40`, two parts). Open states are held
/// whole, about 220 bytes with their variety history, where an expanded
/// one leaves 6: a loop whose descriptors run to tens of thousands
/// (`vectorian105` round `circle:40`, any number of parts: 56 k
/// descriptors, 60 k open states per length) held 50 MB of room, and
/// 106–117 MB in all, when only states were counted.
pub(super) fn room_budget(max_states: usize) -> usize {
    max_states.saturating_mul(STATE_BYTES) / 16 * 13
}

/// The share of a search's lengths after which its growth is projected
/// ([`Search::bound_to_pass_cap`]). On the corpus's largest searches the
/// states grow by about the same number per length from a tenth of the
/// lengths on.
const PROJECT_AFTER: f64 = 0.2;

/// Fewest lengths a search must have expanded to be projected.
const MIN_PROJECTED_LENGTHS: usize = 16;

/// How far past the cap a projection must reach for the search to stop
/// early. Projected from a fifth of the lengths on, the largest searches
/// of the corpus that end within the cap ended up to 11 % below their
/// projection (the last lengths hold fewer states: those that can no
/// longer close the loop in time are dropped).
const PROJECTED_MARGIN: f64 = 1.25;

/// Most states the bounded search sizes its beam for. Its states are
/// mostly open ones, held whole, so it is held to the 2 M states of the
/// cap before expanded states were counted at 6 bytes: `vectorian105`'s
/// loops with any number of parts then peak at 37–40 MB, and with a beam
/// twice as wide (the default cap of 4 M) at 71 MB.
const BOUNDED_MAX_STATES: usize = 2_000_000;

/// The bounded search's beam: how many states of each length it keeps.
/// Each search running at once keeps `width` traces per length, and the
/// children of `width` states wait in the next lengths (one per following
/// piece, over the lengths a piece spans): all of it within the cap, and
/// within [`BOUNDED_MAX_STATES`], since the waiting states are held whole
/// (with their variety history, about 30 times what an expanded one
/// leaves) and no room is counted for them. `steps` are the pieces'
/// widths in length keys, `last_key` the window's last key.
pub(super) fn beam_width(options: &SolveOptions, steps: &[u32], last_key: u32, runs: usize) -> usize {
    let lengths = last_key as usize + 1;
    let waiting = steps.len() * (steps.iter().copied().max().unwrap_or(1) as usize + 2);
    let running = rayon::current_num_threads().min(runs).max(1);
    let held = options.max_states.min(BOUNDED_MAX_STATES);
    (held / (running * (lengths + waiting))).max(1)
}
