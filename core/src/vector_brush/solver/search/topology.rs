//! Searching with the topology left out where the targets ask nothing of
//! it: any number of parts and holes.

use super::{Goal, Solution, SolveOptions, search_with};
use crate::control::Control;
use crate::vector_brush::solver::Target;
use crate::vector_brush::{PieceSet, SolveError};

/// Whether a search follows the topology descriptors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::vector_brush::solver) enum Topology {
    /// Every state carries its descriptor: what the targets ask is met by
    /// construction.
    Followed,
    /// One descriptor for all: states differ only by last piece and length.
    Ignored,
}

/// Runs the searches for growing tolerances until one finds a solution.
///
/// Where the targets ask for any number of parts and holes, the topology is
/// first left out: the descriptors then only tell patterns apart that the
/// targets accept alike, and merging them leaves a small fraction of the
/// states (a loop of the corpus: 3.3 M → tens of thousands). On an open
/// curve nothing is lost by it. On a loop that must run all around, the
/// pattern found is checked and, where it does not, the search runs again
/// following the descriptors. The same holds when nothing is found: without
/// the topology every sequence the full search could finish is still there.
pub(in crate::vector_brush::solver) fn search_all(
    set: &PieceSet,
    options: &SolveOptions,
    goal: Goal,
    control: &Control,
) -> Result<Option<Solution>, SolveError> {
    if options.components == Target::Any && options.holes == Target::Any {
        match search_with(set, options, goal, control, Topology::Ignored) {
            // The solution's counts are recounted from its pieces' own
            // descriptors (`finish`), not taken from the search.
            Ok(Some(solution)) if options.meets_targets((solution.components, solution.holes, solution.wraps)) => {
                return Ok(Some(solution));
            }
            // A bounded search's empty answer proves nothing.
            Ok(None) if goal != Goal::Bounded => return Ok(None),
            Ok(_) => {}
            // Following the descriptors takes at least as many states.
            Err(e) => return Err(e),
        }
    }
    search_with(set, options, goal, control, Topology::Followed)
}

/// Marks as incompatible (`NaN` in `cost`, `n × n`) every seam without
/// portals and every seam to or from a piece that no material crosses from
/// left to right. Material that runs all around a loop passes every seam
/// and crosses every piece, so every such pattern is still there, and few
/// others are.
pub(super) fn leave_out_what_loops_cannot_cross(set: &PieceSet, cost: &mut [f64]) {
    let n = set.len();
    let through: Vec<bool> = set.pieces.iter().map(|p| p.descriptor.passes_through()).collect();
    for a in 0..n {
        for b in 0..n {
            if !(through[a] && through[b]) || set.joining(a, b).is_none() {
                cost[a * n + b] = f64::NAN;
            }
        }
    }
}
