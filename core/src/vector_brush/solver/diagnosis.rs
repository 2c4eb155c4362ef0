//! Diagnosis: when nothing meets the targets, which one to relax. The
//! targets are relaxed one at a time and the search is run again.

use super::search::search_all;
use super::{CurveKind, SolveOptions, Target};
use crate::control::Control;
use crate::vector_brush::{PieceSet, SolveError, Unmet};

/// Finds which target makes the problem impossible, by relaxing them one at a time.
pub(super) fn diagnose(set: &PieceSet, options: &SolveOptions, control: &Control) -> Result<Unmet, SolveError> {
    let feasible = |components: Target, holes: Target, closed_pattern: bool| -> Result<bool, SolveError> {
        let relaxed = SolveOptions { components, holes, closed_pattern, variety: 0.0, seed: 0, ..options.clone() };
        Ok(search_all(set, &relaxed, false, &control.silent())?.is_some())
    };
    if options.band_height.is_finite() {
        let unbounded = SolveOptions { band_height: f64::INFINITY, ..options.clone() };
        if search_all(set, &unbounded, false, &control.silent())?.is_some() {
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
