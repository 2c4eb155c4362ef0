//! Canvas tools, each a small state machine driven by the canvas: a gesture
//! begins on a primary press, moves with the pointer and ends on release.
//! Secondary and middle drags pan whatever the tool.

pub mod avoid;
pub mod draw;
pub mod edit;
pub mod pan;

use serde::{Deserialize, Serialize};

/// What a primary drag on the canvas does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Tool {
    /// Draw a new curve.
    Draw,
    /// Select, move and reshape curves.
    Edit,
    /// Move the view.
    Pan,
    /// Click to hang a jump ring there on the nearest curve.
    Ring,
    /// Paint areas that raster patterns leave empty.
    Avoid,
    /// Draw pen strokes; in a region fill, autocomplete continues them.
    Pen,
    /// Drag a source rectangle in a region fill, then a target to clone it to.
    Clone,
}

impl Tool {
    /// Every tool, in toolbar order.
    pub const ALL: [Tool; 7] = [Tool::Draw, Tool::Edit, Tool::Pan, Tool::Ring, Tool::Avoid, Tool::Pen, Tool::Clone];

    /// Its name on the toolbar.
    pub fn label(self) -> &'static str {
        match self {
            Tool::Draw => "Draw",
            Tool::Edit => "Edit",
            Tool::Pan => "Pan",
            Tool::Ring => "Ring",
            Tool::Avoid => "Avoid",
            Tool::Pen => "Pen",
            Tool::Clone => "Clone",
        }
    }
}

/// A gesture in progress.
#[derive(Debug)]
pub enum Gesture {
    /// A stroke being drawn.
    Stroke(draw::Stroke),
    /// A point or a whole curve being dragged.
    Edit(edit::EditDrag),
    /// The view being dragged.
    Pan(pan::Pan),
    /// An area being painted with the avoidance brush.
    Avoid(draw::Stroke),
    /// A pen stroke being drawn.
    Pen(draw::Stroke),
    /// A clone rectangle being dragged, from corner to corner, mm.
    Clone(tracery_core::DVec2, tracery_core::DVec2),
}
