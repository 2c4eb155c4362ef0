//! What the targets ask of a descriptor.

use super::{CurveKind, SolveOptions, Target};
use crate::vector_brush::TopologyDescriptor;

impl SolveOptions {
    /// The descriptor with the counters a target does not constrain zeroed,
    /// so that more partial solutions merge.
    pub(super) fn clamp(&self, d: &TopologyDescriptor) -> TopologyDescriptor {
        let closed = if self.components == Target::Any { 0 } else { d.closed_components() as u16 };
        let holes = if self.holes == Target::Any { 0 } else { d.holes() as u16 };
        d.with_counters(closed, holes)
    }

    /// Whether a partial solution can still meet the targets.
    ///
    /// On a loop that must run all around, material must also still pass
    /// through from the first piece's left side to the last piece's right:
    /// a component that wraps crosses the closing seam, and a cycle through
    /// it that winds needs a path from one side to the other (with none,
    /// its crossings of the seam alternate in direction and cancel). Once no
    /// component touches both sides, none ever will, since later pieces
    /// join only on the right.
    pub(super) fn viable(&self, d: &TopologyDescriptor) -> bool {
        let may_wrap = self.curve == CurveKind::Open || !self.closed_pattern || d.passes_through();
        may_wrap && !self.components.exceeded_by(d.min_final_components()) && !self.holes.exceeded_by(d.holes())
    }

    /// Components, holes and wraps of a finished pattern, or `None` where
    /// the descriptor cannot end (open portals on an open curve, or a loop
    /// that does not close).
    pub(super) fn finished(&self, d: &TopologyDescriptor) -> Option<(u32, u32, u32)> {
        match self.curve {
            CurveKind::Open => d.is_finished().then(|| (d.components(), d.holes(), 0)),
            CurveKind::Closed => d.close_loop().map(|t| (t.components, t.holes, t.wraps)),
        }
    }

    /// Whether a finished pattern's counts meet the targets.
    pub(super) fn meets_targets(&self, t: (u32, u32, u32)) -> bool {
        let loop_ok = self.curve == CurveKind::Open || !self.closed_pattern || t.2 > 0;
        self.components.accepts(t.0) && self.holes.accepts(t.1) && loop_ok
    }

    /// Whether a partial pattern may stand for another of the same length
    /// and last piece that costs no less and whose portals it connects at
    /// least as much, with no more parts closed inside: every pattern the
    /// other finishes into, it finishes into one with no more parts and,
    /// on a loop, one that runs all around wherever that one does. More
    /// connection may close more holes, so the holes must be free; and
    /// fewer parts is no better unless any number, or exactly one, will do
    /// (a pattern has at least one).
    pub(super) fn dominance_is_sound(&self) -> bool {
        self.holes == Target::Any && matches!(self.components, Target::Any | Target::Exactly(1))
    }
}
