//! The draw tool: a stroke grows under the pointer and, on release, becomes
//! a curve of evenly spaced control points, closed if it ends near its start.

use tracery_core::DVec2;
use tracery_core::curve::Curve;

/// Pointer samples closer than this to the last one are skipped, mm.
pub const MIN_SAMPLE_SPACING_MM: f64 = 0.25;
/// Spacing of the control points a finished stroke keeps, mm.
pub const CONTROL_SPACING_MM: f64 = 6.0;
/// Spacing of a pen stroke's control points, mm: pen strokes are details
/// of a fill (a spiral's turns), not a band's path.
pub const PEN_SPACING_MM: f64 = 1.5;
/// A stroke whose end comes back within this many screen points of its start closes.
pub const CLOSE_DISTANCE_POINTS: f64 = 20.0;

/// A stroke being drawn, in world millimetres.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stroke {
    /// The pointer's path so far.
    pub points: Vec<DVec2>,
}

impl Stroke {
    /// A stroke starting at `p` (where the button went down).
    pub fn begin(p: DVec2) -> Stroke {
        Stroke { points: vec![p] }
    }

    /// The pointer moved to `p`.
    pub fn extend(&mut self, p: DVec2) {
        if self.points.last().is_none_or(|q| q.distance(p) > MIN_SAMPLE_SPACING_MM) {
            self.points.push(p);
        }
    }

    /// The button was released: the control points and whether the curve
    /// closes, or `None` for a stroke too short to keep.
    pub fn finish(&self, points_per_mm: f32) -> Option<(Vec<DVec2>, bool)> {
        self.finish_every(points_per_mm, CONTROL_SPACING_MM)
    }

    /// As [`Stroke::finish`], with control points about every `spacing_mm`.
    pub fn finish_every(&self, points_per_mm: f32, spacing_mm: f64) -> Option<(Vec<DVec2>, bool)> {
        let close_mm = CLOSE_DISTANCE_POINTS / f64::from(points_per_mm);
        stroke_to_control_points(&self.points, spacing_mm, close_mm)
    }
}

/// Whether a raw stroke is long enough to become a curve with control
/// points about every `spacing_mm`.
pub fn long_enough(raw: &[DVec2], spacing_mm: f64) -> bool {
    let length: f64 = raw.windows(2).map(|w| w[0].distance(w[1])).sum();
    raw.len() >= 2 && length >= 3.0 * spacing_mm.min(2.0)
}

/// Turns a raw stroke into control points: evenly spaced, about every
/// `spacing_mm`, and whether it closes into a loop (its end came back near
/// its start, within `close_mm`).
pub fn stroke_to_control_points(raw: &[DVec2], spacing_mm: f64, close_mm: f64) -> Option<(Vec<DVec2>, bool)> {
    if !long_enough(raw, spacing_mm) {
        return None;
    }
    let length: f64 = raw.windows(2).map(|w| w[0].distance(w[1])).sum();
    let closed = raw.len() > 8 && raw[0].distance(*raw.last()?) <= close_mm && length > 4.0 * close_mm;
    let curve = Curve::from_polyline(raw, closed).ok()?;
    let count = ((curve.length() / spacing_mm).round() as usize).max(if closed { 4 } else { 2 });
    let mut points: Vec<DVec2> = (0..=count).map(|k| curve.point(curve.length() * k as f64 / count as f64)).collect();
    if closed {
        points.pop();
    }
    Some((points, closed))
}
