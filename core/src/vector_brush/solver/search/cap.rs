//! The state cap, shared by the parallel searches of a loop.

use std::sync::atomic::Ordering;

use super::Search;
use crate::control::StateCap;
use crate::vector_brush::SolveError;
use crate::vector_brush::solver::STATE_BYTES;

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
        self.growth.push(self.counted);
        if problem.beam.is_some() || problem.stop_at_first {
            return false;
        }
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
