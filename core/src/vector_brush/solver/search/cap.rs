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
        let cap = StateCap { max_states: max, bytes_per_state: STATE_BYTES };
        Err(SolveError::TooManyStates { limit: cap.max_states, megabytes: cap.megabytes() })
    }
}
