//! The edit tool: press on a control point of the selected curve to move
//! it, or on a curve to select it and move it whole.

use tracery_core::DVec2;

use crate::document::Document;

/// Pick radius around points and curves, in screen points.
pub const PICK_RADIUS_POINTS: f64 = 8.0;

/// What an edit drag moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EditDrag {
    /// One control point of a curve.
    Point {
        /// The curve.
        curve: u64,
        /// The point's index.
        index: usize,
    },
    /// A whole curve, from where the pointer last was.
    Curve {
        /// The curve.
        curve: u64,
        /// The pointer's last position, mm.
        last: DVec2,
    },
}

impl EditDrag {
    /// A press at `p`: a control point of the selected curve within
    /// `tolerance_mm`, else the curve `curve_at` finds there (which becomes selected).
    pub fn begin(
        doc: &Document,
        selected: Option<u64>,
        p: DVec2,
        tolerance_mm: f64,
        curve_at: impl Fn(DVec2) -> Option<u64>,
    ) -> Option<EditDrag> {
        if let Some(item) = selected.and_then(|id| doc.curve(id))
            && let Some(index) = item.control_points().iter().position(|q| q.distance(p) <= tolerance_mm)
        {
            return Some(EditDrag::Point { curve: item.id, index });
        }
        curve_at(p).map(|curve| EditDrag::Curve { curve, last: p })
    }

    /// The curve being edited.
    pub fn curve(&self) -> u64 {
        match *self {
            EditDrag::Point { curve, .. } | EditDrag::Curve { curve, .. } => curve,
        }
    }

    /// The pointer moved to `p`.
    pub fn drag(&mut self, doc: &mut Document, p: DVec2) {
        match self {
            EditDrag::Point { curve, index } => {
                if let Some(slot) = doc.curve_mut(*curve).and_then(|c| c.points.get_mut(*index)) {
                    *slot = [p.x, p.y];
                }
            }
            EditDrag::Curve { curve, last } => {
                let delta = p - *last;
                *last = p;
                if let Some(c) = doc.curve_mut(*curve) {
                    for q in &mut c.points {
                        q[0] += delta.x;
                        q[1] += delta.y;
                    }
                }
            }
        }
    }
}
