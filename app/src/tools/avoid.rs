//! The avoidance brush: a drag paints an area that raster patterns leave
//! empty, a click paints a dot, and undo takes a whole stroke back. The
//! pointer's path is gathered as the draw tool gathers it ([`Stroke`]).

use crate::document::AvoidStroke;
use crate::tools::draw::Stroke;

/// The painted path as the document keeps it, `width_mm` wide.
pub fn painted(stroke: &Stroke, width_mm: f64) -> AvoidStroke {
    AvoidStroke { points: stroke.points.iter().map(|p| [p.x, p.y]).collect(), width_mm }
}
