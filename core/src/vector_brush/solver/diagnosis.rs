//! Diagnosis: when nothing meets the targets, which one to relax. The
//! targets are relaxed one at a time and the search is run again.

use super::Goal;
use super::search::search_all;
use super::{CurveKind, SolveOptions, Target};
use crate::control::Control;
use crate::vector_brush::{PieceSet, SolveError, Unmet};

/// Finds which target makes the problem impossible, by relaxing them one at a time.
pub(super) fn diagnose(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Unmet, SolveError> {
    let feasible = |components: Target, holes: Target, closed_pattern: bool| -> Result<bool, SolveError> {
        let relaxed = SolveOptions { components, holes, closed_pattern, variety: 0.0, seed: 0, ..options.clone() };
        Ok(search_all(set, &relaxed, Goal::Any, &control.silent())?.is_some())
    };
    if options.band_height.is_finite() {
        let unbounded = SolveOptions { band_height: f64::INFINITY, ..options.clone() };
        if search_all(set, &unbounded, Goal::Any, &control.silent())?.is_some() {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector_brush::{SliceOptions, builtin};

    #[test]
    fn asking_whether_any_pattern_exists_stops_at_the_first() {
        let set = PieceSet::new(&builtin("filigree").unwrap(), &SliceOptions::default()).unwrap();
        for curve in [CurveKind::Open, CurveKind::Closed] {
            let mut options = SolveOptions::new(60.0 * set.exemplar_width / set.len() as f64);
            options.curve = curve;
            let control = Control::default();
            let best = search_all(&set, &options, Goal::Best, &control).unwrap().expect("a pattern");
            let any = search_all(&set, &options, Goal::Any, &control).unwrap().expect("a pattern too");
            // A pattern all the same. On a loop, whose searches (one per
            // start piece) stop as soon as one has found a pattern, with a
            // fraction of the states; on an open curve the first pattern
            // comes at the shortest accepted length, late in the search, so
            // little is saved there.
            let fraction = if curve == CurveKind::Closed { 0.5 } else { 1.0 };
            assert!(
                any.states as f64 <= fraction * best.states as f64,
                "{curve:?}: {} against {} states",
                any.states,
                best.states
            );
            assert!(any.pieces.len() > 1);
        }
    }
}
