//! Keeping a new state in its length's table, or not: the state already
//! under its key is kept where it costs no more.

use super::narrowing::total;
use super::{Search, State};
use crate::vector_brush::{Autocorrelation, SolveError};

/// Where a state goes in its bucket ([`Search::lookup`]).
#[derive(Clone, Copy)]
pub(super) struct Looked {
    key: usize,
    slot: usize,
    /// The state already kept under the key, and its total.
    existing: Option<(usize, f64)>,
}

impl Search<'_> {
    /// Where `state`, to be kept at `length`, would go: its key, its
    /// bucket, and the state already there with its total, if any.
    #[inline(always)]
    pub(super) fn lookup(&self, length: u32, state: &State) -> Looked {
        // Descriptor ids are dense and few: a state's key indexes a table.
        let key = state.descriptor as usize * self.problem.n() + usize::from(state.piece);
        let slot = length as usize % self.buckets.len();
        let bucket = &self.buckets[slot];
        let beta = self.problem.options.variety;
        let existing = bucket.get(key).map(|i| (i, total(&bucket.open, &bucket.auto, beta, i)));
        Looked { key, slot, existing }
    }

    /// Keeps `state` at `length` unless a cheaper one with the same key is
    /// there. `penalty_floor` is a lower bound of the variety penalty of
    /// `state` (its parent's: the per-lag sums only grow), so the new
    /// autocorrelation is computed only when the state may win.
    pub(super) fn add(
        &mut self,
        length: u32,
        state: State,
        penalty_floor: f64,
        correlation: impl FnOnce() -> Autocorrelation,
    ) -> Result<(), SolveError> {
        let looked = self.lookup(length, &state);
        self.add_looked_up(looked, state, penalty_floor, correlation)
    }

    /// [`Search::add`] once the state has been looked up.
    #[inline(always)]
    pub(super) fn add_looked_up(
        &mut self,
        looked: Looked,
        state: State,
        penalty_floor: f64,
        correlation: impl FnOnce() -> Autocorrelation,
    ) -> Result<(), SolveError> {
        let Looked { key, slot, existing } = looked;
        let variety = self.variety();
        let beta = self.problem.options.variety;
        if let Some((existing, old_total)) = existing {
            if old_total <= state.cost + penalty_floor {
                return Ok(());
            }
            let bucket = &mut self.buckets[slot];
            if variety {
                let correlation = correlation();
                if state.cost + beta * correlation.value() < old_total {
                    bucket.open[existing] = state;
                    bucket.auto[existing] = correlation;
                }
            } else {
                bucket.open[existing] = state;
            }
            return Ok(());
        }
        if self.reserved == 0 {
            self.reserve()?;
        }
        self.reserved -= 1;
        self.counted += 1;
        let grown = self.buckets[slot].insert(key, state, variety.then(correlation));
        // The bounded search counts no room (`open_bytes` is zero).
        let bytes = grown * self.open_bytes;
        if bytes > 0 {
            self.make_room(bytes)?;
        }
        Ok(())
    }
}
