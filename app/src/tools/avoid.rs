//! The avoidance brush: a drag paints an area that raster patterns leave
//! empty. A click paints a dot. Undo takes a whole stroke back.

use tracery_core::DVec2;

use crate::document::AvoidStroke;

/// Pointer samples closer than this to the last one are skipped, mm.
pub const MIN_SAMPLE_SPACING_MM: f64 = 0.25;

/// A stroke of the avoidance brush being painted, in world millimetres.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AvoidDrag {
    /// The pointer's path so far.
    pub points: Vec<DVec2>,
}

impl AvoidDrag {
    /// A stroke starting at `p`.
    pub fn begin(p: DVec2) -> AvoidDrag {
        AvoidDrag { points: vec![p] }
    }

    /// The pointer moved to `p`.
    pub fn extend(&mut self, p: DVec2) {
        if self.points.last().is_none_or(|q| q.distance(p) > MIN_SAMPLE_SPACING_MM) {
            self.points.push(p);
        }
    }

    /// The stroke as the document keeps it, painted `width_mm` wide.
    pub fn finish(&self, width_mm: f64) -> AvoidStroke {
        AvoidStroke { points: self.points.iter().map(|p| [p.x, p.y]).collect(), width_mm }
    }
}
