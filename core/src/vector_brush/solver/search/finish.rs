//! The finished solution, recomputed from the pieces themselves.

use super::{CurveKind, Found, Solution, SolveOptions};
use crate::vector_brush::{Autocorrelation, PieceSet, Similarity};

/// Recomputes what a sequence achieves from the pieces themselves.
pub(super) fn finish(set: &PieceSet, options: &SolveOptions, found: Found, tolerance: f64, created: usize) -> Solution {
    let n = found.pieces.len();
    let mut matching = 0.0;
    let mut descriptor = set.pieces[found.pieces[0]].descriptor.clone();
    for w in found.pieces.windows(2) {
        matching += set.pair(w[0], w[1]).map_or(0.0, |p| p.cost_at(options.misfit_weight));
        descriptor = descriptor.join(&set.pieces[w[1]].descriptor).unwrap_or(descriptor);
    }
    let (components, holes, wraps) = match options.curve {
        CurveKind::Open => (descriptor.components(), descriptor.holes(), 0),
        CurveKind::Closed => {
            matching +=
                set.pair(found.pieces[n - 1], found.pieces[0]).map_or(0.0, |p| p.cost_at(options.misfit_weight));
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
        bounded: None,
        dominance: false,
    }
}
