//! Sharp corners of a curve kept where a path is resampled: each stretch
//! between two corners is sampled on its own, so a square frame drawn in
//! SVG keeps the corners it was drawn with. Rounding them is
//! [`Curve::with_rounded_corners`]'s (`rounding.rs`).

use glam::DVec2;

use super::Curve;

/// A vertex that turns by more than this is a corner that
/// [`Curve::resampled_keeping_corners`] keeps, degrees.
pub const CORNER_ANGLE_DEG: f64 = 5.0;

impl Curve {
    /// The curve with points about every `spacing` units of arc length, its
    /// corners (vertices turning [`CORNER_ANGLE_DEG`] or more) kept where
    /// they are: each stretch between two corners is sampled evenly on its
    /// own. Sampled straight through, a corner is cut by a short chord, and
    /// the straight sides beside it no longer meet where they were drawn.
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// let square = Curve::regular_polygon(4, 50.0).unwrap();
    /// let sampled = square.resampled_keeping_corners(0.7);
    /// for corner in square.points() {
    ///     assert!(sampled.points().iter().any(|p| p.distance(*corner) < 1e-9));
    /// }
    /// assert!((sampled.length() - square.length()).abs() < 1e-9);
    /// ```
    pub fn resampled_keeping_corners(&self, spacing: f64) -> Curve {
        let closed = self.is_closed();
        let mut points = self.points().to_vec();
        if closed {
            points.pop();
        }
        let n = points.len();
        let threshold = CORNER_ANGLE_DEG.to_radians();
        let corners: Vec<usize> =
            (0..n).zip(turns(&points, closed)).filter(|(_, t)| t.abs() >= threshold).map(|(i, _)| i).collect();
        if n < 3 || corners.is_empty() || spacing.is_nan() || spacing <= 0.0 {
            return self.resampled(spacing);
        }
        // Stretches from corner to corner (and from the ends, when open).
        let mut stops: Vec<usize> = corners.clone();
        if closed {
            stops.push(corners[0] + n);
        } else {
            stops.insert(0, 0);
            stops.push(n - 1);
        }
        let mut out: Vec<DVec2> = Vec::new();
        for pair in stops.windows(2) {
            let stretch: Vec<DVec2> = (pair[0]..=pair[1]).map(|i| points[i % n]).collect();
            let Ok(piece) = Curve::from_polyline(&stretch, false) else { continue };
            let count = ((piece.length() / spacing).ceil() as usize).max(1);
            // Each stretch's last point is the next one's first.
            out.extend((0..count).map(|k| piece.point(piece.length() * k as f64 / count as f64)));
        }
        if !closed {
            out.push(points[n - 1]);
        }
        Curve::from_polyline(&out, closed).unwrap_or_else(|_| self.resampled(spacing))
    }
}

/// The signed turn at each vertex of a polyline, radians: wrapping on a
/// loop, zero at an open curve's ends.
pub(super) fn turns(points: &[DVec2], closed: bool) -> Vec<f64> {
    let n = points.len();
    (0..n)
        .map(|i| {
            if !closed && (i == 0 || i + 1 == n) {
                return 0.0;
            }
            let (prev, here, next) = (points[(i + n - 1) % n], points[i], points[(i + 1) % n]);
            let (d_in, d_out) = (here - prev, next - here);
            d_in.perp_dot(d_out).atan2(d_in.dot(d_out))
        })
        .collect()
}
