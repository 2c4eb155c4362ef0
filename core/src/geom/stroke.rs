//! A polyline drawn with a round brush of some width, as a region: the
//! shape a person paints with a brush tool. Through `i_overlay`'s stroke
//! outline with round caps and joins.

use i_overlay::mesh::float::stroke::offset::StrokeOffset;
use i_overlay::mesh::float::style::{LineCap, LineJoin, StrokeStyle};

use super::boolean::from_shapes;
use super::{Region, arc_step, disc};
use crate::DVec2;

/// Largest distance between a round cap's or join's arc and its chords, mm.
pub const STROKE_ARC_TOLERANCE_MM: f64 = 0.01;

/// The area a round brush `width_mm` wide covers along `points_mm` (a loop
/// when `closed`): round caps and joins, self-overlaps merged. A single
/// point is a disc; no points, or a width that is not positive, cover nothing.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::brush_stroke;
/// let line = [DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0)];
/// let region = brush_stroke(&line, 2.0, false);
/// // A 10 x 2 strip with two half discs of radius 1 at its ends.
/// // Chords of the caps cut off a little (about 0.02 mm² each).
/// assert!((region.area() - (20.0 + std::f64::consts::PI)).abs() < 0.05);
/// assert_eq!(region.polygons.len(), 1);
/// assert!(brush_stroke(&line, 0.0, false).is_empty());
/// ```
pub fn brush_stroke(points_mm: &[DVec2], width_mm: f64, closed: bool) -> Region {
    if points_mm.is_empty() || !(width_mm.is_finite() && width_mm > 0.0) {
        return Region::default();
    }
    let radius = 0.5 * width_mm;
    let step = arc_step(radius, STROKE_ARC_TOLERANCE_MM).max(0.05);
    let mut path: Vec<[f64; 2]> = Vec::with_capacity(points_mm.len());
    for p in points_mm {
        if path.last().is_none_or(|q: &[f64; 2]| DVec2::new(q[0], q[1]).distance(*p) > 1e-6) {
            path.push([p.x, p.y]);
        }
    }
    if path.len() < 2 {
        let sides = (std::f64::consts::TAU / step).ceil().max(8.0) as usize;
        return Region::new(vec![disc(points_mm[0], radius, sides)]);
    }
    let style = StrokeStyle::new(width_mm)
        .line_join(LineJoin::Round(step))
        .start_cap(LineCap::Round(step))
        .end_cap(LineCap::Round(step));
    from_shapes(path.stroke_as::<i64>(style, closed && path.len() > 2))
}
