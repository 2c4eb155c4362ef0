//! Two ways a search starts from less than everything: a fixed beginning
//! laid as a chain of states, and the bounded search that keeps only the
//! cheapest states of each length.

use std::sync::atomic::Ordering;

use super::{CurveKind, NO_PARENT, Search, State};
use crate::vector_brush::{Autocorrelation, SolveError};

impl Search<'_> {
    /// Keeps the `width` cheapest of the open states of one length (their
    /// variety penalty included), dropping the rest: the bounded search.
    pub(super) fn keep_cheapest(&mut self, width: usize, open: &mut Vec<State>, autos: &mut Vec<Autocorrelation>) {
        let beta = self.problem.options.variety;
        let total = |i: usize| total(open, autos, beta, i);
        let mut order: Vec<usize> = (0..open.len()).collect();
        order.select_nth_unstable_by(width, |&i, &j| total(i).total_cmp(&total(j)));
        order.truncate(width);
        order.sort_unstable();
        self.keep_only(&order, open, autos);
        self.problem.bounded.store(true, Ordering::Relaxed);
    }

    /// Keeps only the open states at `kept` (in ascending order), giving
    /// the others' places in the cap back.
    pub(super) fn keep_only(&mut self, kept: &[usize], open: &mut Vec<State>, autos: &mut Vec<Autocorrelation>) {
        let dropped = open.len() - kept.len();
        *open = kept.iter().map(|&i| open[i]).collect();
        if !autos.is_empty() {
            *autos = kept.iter().map(|&i| autos[i]).collect();
        }
        self.counted -= dropped;
        self.problem.states.fetch_sub(dropped, Ordering::Relaxed);
    }

    /// Lays the fixed beginning (`SolveOptions::prefix`, open curves) as a
    /// chain of states, the search growing only from its last one. Returns
    /// that state's key, or `None` when there is no prefix or it cannot be
    /// laid (the search then starts from scratch).
    pub(super) fn seed_prefix(&mut self) -> Result<Option<u32>, SolveError> {
        let problem = self.problem;
        let prefix = &problem.options.prefix;
        if prefix.is_empty() || problem.options.curve != CurveKind::Open || prefix.iter().any(|&p| p >= problem.n()) {
            return Ok(None);
        }
        let s = prefix[0];
        if !problem.set.pieces[s].left.is_empty() {
            return Ok(None);
        }
        let n = problem.n();
        let Some(descriptor) = problem.start_descriptor(&mut self.interner, s) else {
            return Ok(None);
        };
        let mut state =
            State { cost: 0.0, length: problem.widths[s], parent: NO_PARENT, descriptor, delta: 0.0, piece: s as u16 };
        let mut correlation = Autocorrelation::default().push(s, &problem.similarity);
        let arena_start = self.arena.len();
        for &b in &prefix[1..] {
            let key = problem.grid.key(state.length).max(1);
            let parent = self.arena.len() as u32;
            let compatible = !problem.cost[usize::from(state.piece) * n + b].is_nan();
            let Some(next) = self.follow(&state, parent, key, b).filter(|_| compatible) else {
                self.arena.truncate(arena_start);
                return Ok(None);
            };
            // Chain states live in the arena only, for backtracking.
            self.arena.push(state.parent, state.piece);
            state = next;
            correlation = correlation.push(b, &problem.similarity);
        }
        if state.length > self.window.1 {
            self.arena.truncate(arena_start);
            return Ok(None);
        }
        let key = problem.grid.key(state.length).max(1);
        self.add(key, state, 0.0, || correlation)?;
        Ok(Some(key))
    }
}

/// The open state `i`'s cost with its variety penalty (`autos` is empty
/// where the variety term is off): what the searches that drop states rank
/// them by.
pub(super) fn total(open: &[State], autos: &[Autocorrelation], beta: f64, i: usize) -> f64 {
    open[i].cost + autos.get(i).map_or(0.0, |a| beta * a.value())
}
