//! Diagnosis: when nothing meets the targets, which one to relax. The
//! targets are relaxed one at a time and the search is run again.

use super::Goal;
use super::search::search_all;
use super::{CurveKind, SolveOptions, Target, past_cap_retry};
use crate::control::Control;
use crate::vector_brush::{PieceSet, SolveError, Unmet};

/// Finds which target makes the problem impossible, by relaxing them one at a time.
pub(super) fn diagnose(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Unmet, SolveError> {
    let feasible = |components: Target, holes: Target, closed_pattern: bool| -> Result<bool, SolveError> {
        let relaxed = SolveOptions { components, holes, closed_pattern, variety: 0.0, seed: 0, ..options.clone() };
        exists(set, &relaxed, control)
    };
    if options.band_height.is_finite() {
        let unbounded = SolveOptions { band_height: f64::INFINITY, ..options.clone() };
        match exists(set, &unbounded, control) {
            Ok(true) => return Ok(Unmet::Band),
            // Undecided within the cap: the band is not named, and the
            // checks below need no answer from this one.
            Ok(false) | Err(SolveError::TooManyStates { .. }) => {}
            Err(e) => return Err(e),
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
    let unmet = if !components_ok {
        Unmet::Components(options.components)
    } else if !(options.holes == Target::Any || feasible(Target::Any, options.holes, closed)?) {
        Unmet::Holes(options.holes)
    } else {
        Unmet::Combination { components: options.components, holes: options.holes }
    };
    if options.curve != CurveKind::Closed {
        return Ok(unmet);
    }
    // On a loop, say what does work: the exemplar may meet the targets
    // with the pattern not closed round the loop, or along an open curve.
    let without_closed_pattern = closed && feasible(options.components, options.holes, false)?;
    let open = SolveOptions { curve: CurveKind::Open, closed_pattern: false, variety: 0.0, seed: 0, ..options.clone() };
    let along_open_curve = !without_closed_pattern && exists(set, &open, control).unwrap_or(false);
    if !(without_closed_pattern || along_open_curve) {
        return Ok(unmet);
    }
    Ok(Unmet::OnLoop { unmet: Box::new(unmet), without_closed_pattern, along_open_curve })
}

/// Whether some pattern meets `options`. Where the exhaustive search
/// needs more than the state cap, a pattern found by a bounded search is
/// proof enough that one exists (vectorian93 along a line with one
/// component: the targets relaxed to any number of parts need 1.3 M
/// states); only where that finds none too does the cap stand.
fn exists(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<bool, SolveError> {
    let control = control.silent();
    let found = search_all(set, options, Goal::Any, &control).or_else(|e| past_cap_retry(set, options, e, &control))?;
    Ok(found.is_some())
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

    #[test]
    fn a_refusal_is_explained_when_only_a_bounded_search_finds_the_relaxed_pattern() {
        // Three parts without holes cannot be made from lace; three parts
        // with holes can. The state cap is set a little below what the
        // exhaustive search for "three parts, any holes" needs, so only a
        // pattern found by the bounded search can show that relaxing the
        // holes works.
        let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
        let mut options = SolveOptions::new(6.0 * set.exemplar_width);
        options.components = Target::Exactly(3);
        options.holes = Target::Exactly(0);
        let control = Control::default();
        let relaxed = SolveOptions { holes: Target::Any, variety: 0.0, seed: 0, ..options.clone() };
        let needed = search_all(&set, &relaxed, Goal::Any, &control).unwrap().expect("three parts with holes").states;
        options.max_states = needed * 9 / 10;
        let capped = SolveOptions { max_states: options.max_states, ..relaxed };
        assert!(
            matches!(search_all(&set, &capped, Goal::Any, &control), Err(SolveError::TooManyStates { .. })),
            "the exhaustive search for the relaxed targets must pass the cap"
        );
        assert!(search_all(&set, &options, Goal::Best, &control).unwrap().is_none(), "no pattern, within the cap");
        assert_eq!(
            diagnose(&set, &options, &control).unwrap(),
            Unmet::Combination { components: Target::Exactly(3), holes: Target::Exactly(0) }
        );
    }
}
