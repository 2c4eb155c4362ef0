//! A lower bound on what finishing a partial pattern costs, so that the
//! search can drop partial patterns that cannot beat one already found
//! (branch and bound), and those that can no longer reach an accepted length
//! and close.

use super::Search;

/// Slack on the incumbent's cost, relative: sums of the same seam costs in
/// another order differ in the last bits.
const INCUMBENT_SLACK: f64 = 1e-9;

impl Search<'_> {
    /// Whether a partial pattern after `piece` at `length`, having cost
    /// `cost` (its variety penalty so far included; that penalty only
    /// grows), can still finish and cost no more than the best pattern this
    /// search has found (the incumbent). The slack keeps ties that differ
    /// only by rounding.
    #[inline]
    pub(super) fn promising(&self, cost: f64, piece: usize, length: f64) -> bool {
        let least = cost + self.bound.after(piece, length);
        let incumbent = self.best.map_or(f64::INFINITY, |(total, _)| total);
        least.is_finite() && least <= incumbent + INCUMBENT_SLACK * (1.0 + incumbent.abs())
    }
}

/// The least seam cost of any way to finish a pattern whose last piece is
/// `a`, relaxed: topology, band and variety are ignored, and widths are
/// rounded up to whole quanta, so the bound never exceeds the true cost of
/// any finish the search could find.
pub(super) struct CompletionBound {
    pieces: usize,
    quantum: f64,
    /// The last row of `lower`: finishes needing that many quanta or more.
    last_k: usize,
    /// The shortest accepted length, exemplar units.
    min_length: f64,
    /// `lower[k·pieces + a]`: the least cost of following piece `a` with
    /// pieces adding at least `k` quanta of length, then closing the loop
    /// onto the start piece (on loops). `INFINITY` where no finish exists.
    lower: Vec<f64>,
}

impl CompletionBound {
    /// The bound for one search.
    ///
    /// - `cost[a·n + b]`: what the seam from `a` to `b` costs at least,
    ///   `NaN` where `b` cannot follow `a`;
    /// - `following[a]`: the pieces the search lets follow `a`;
    /// - `steps[b]`: piece `b`'s width in quanta, rounded up;
    /// - `closing`: on loops, the start piece the last piece must join.
    pub(super) fn new(
        cost: &[f64],
        following: &[Vec<usize>],
        steps: &[u32],
        quantum: f64,
        min_length: f64,
        closing: Option<usize>,
    ) -> Self {
        let n = following.len();
        let most = (min_length / quantum).floor().max(0.0) as usize;
        let mut lower = vec![f64::INFINITY; (most + 1) * n];
        // No more length needed: the cheapest way to close from `a`, through
        // any pieces (Bellman–Ford; seam costs are never negative).
        match closing {
            None => lower[..n].fill(0.0),
            Some(s) => {
                for a in 0..n {
                    let c = cost[a * n + s];
                    if !c.is_nan() {
                        lower[a] = c;
                    }
                }
                for _ in 0..n {
                    let mut changed = false;
                    for a in 0..n {
                        for &b in &following[a] {
                            let through = cost[a * n + b] + lower[b];
                            if through < lower[a] {
                                lower[a] = through;
                                changed = true;
                            }
                        }
                    }
                    if !changed {
                        break;
                    }
                }
            }
        }
        for k in 1..=most {
            for a in 0..n {
                let mut least = f64::INFINITY;
                for &b in &following[a] {
                    let rest = k.saturating_sub(steps[b] as usize);
                    least = least.min(cost[a * n + b] + lower[rest * n + b]);
                }
                lower[k * n + a] = least;
            }
        }
        let last_k = lower.len() / n.max(1) - 1;
        CompletionBound { pieces: n, quantum, last_k, min_length, lower }
    }

    /// The least that finishing costs after `piece`, at `length` so far
    /// (exemplar units).
    #[inline]
    pub(super) fn after(&self, piece: usize, length: f64) -> f64 {
        // Called for every state and follower: the row count is kept, not
        // divided out. (The length is divided, not multiplied by an
        // inverse, which could round a whole number of quanta up by one
        // and the bound with it.)
        // Truncating a non-negative number is its floor, without the call
        // that `floor` costs where the CPU has no rounding instruction.
        let needed = ((self.min_length - length) / self.quantum).max(0.0) as usize;
        self.lower[needed.min(self.last_k) * self.pieces + piece]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::random::splitmix64;

    /// The cheapest finish by trying every sequence: what the bound must
    /// never exceed.
    fn cheapest_finish(
        cost: &[f64],
        widths: &[f64],
        n: usize,
        last: usize,
        length: f64,
        window: (f64, f64),
        closing: Option<usize>,
    ) -> f64 {
        let mut best = f64::INFINITY;
        if length >= window.0 {
            best = match closing {
                None => 0.0,
                Some(s) if !cost[last * n + s].is_nan() => cost[last * n + s],
                Some(_) => f64::INFINITY,
            };
        }
        for b in 0..n {
            let c = cost[last * n + b];
            if c.is_nan() || length + widths[b] > window.1 {
                continue;
            }
            let rest = cheapest_finish(cost, widths, n, b, length + widths[b], window, closing);
            best = best.min(c + rest);
        }
        best
    }

    #[test]
    fn the_bound_never_exceeds_the_cheapest_finish() {
        let mut checked = 0;
        for case in 0..40u64 {
            let r = |k: u64| (splitmix64(case * 1000 + k) >> 11) as f64 / (1u64 << 53) as f64;
            let n = 2 + (case % 3) as usize;
            let widths: Vec<f64> = (0..n).map(|i| 0.7 + r(i as u64)).collect();
            // Some seams forbidden, the others of any cost.
            let cost: Vec<f64> =
                (0..n * n).map(|i| if r(100 + i as u64) < 0.25 { f64::NAN } else { r(200 + i as u64) }).collect();
            let quantum = 0.3;
            let steps: Vec<u32> = widths.iter().map(|w| ((w / quantum).ceil() as u32).max(1)).collect();
            let following: Vec<Vec<usize>> =
                (0..n).map(|a| (0..n).filter(|&b| !cost[a * n + b].is_nan()).collect()).collect();
            let window = (4.0, 4.6);
            for closing in [None, Some(0)] {
                let bound = CompletionBound::new(&cost, &following, &steps, quantum, window.0, closing);
                for last in 0..n {
                    for length in [0.0, 1.1, 2.5, 3.9, 4.2] {
                        let truth = cheapest_finish(&cost, &widths, n, last, length, window, closing);
                        let lower = bound.after(last, length);
                        assert!(lower <= truth + 1e-12, "case {case}: bound {lower} over the cheapest finish {truth}");
                        checked += usize::from(truth.is_finite());
                    }
                }
            }
        }
        assert!(checked > 100, "too few instances with a finish: {checked}");
    }

    #[test]
    fn a_piece_that_cannot_reach_the_start_has_no_finish() {
        // Piece 1 can only be followed by itself and never joins piece 0.
        let cost = [0.0, 0.5, f64::NAN, 0.1];
        let following = vec![vec![0, 1], vec![1]];
        let bound = CompletionBound::new(&cost, &following, &[1, 1], 1.0, 3.0, Some(0));
        assert!(bound.after(1, 0.0).is_infinite());
        assert_eq!(bound.after(0, 3.0), 0.0);
        assert_eq!(bound.after(0, 0.0), 0.0);
    }
}
