//! The point of a segment nearest to a point, and a point's distance to a polyline.

use glam::DVec2;

/// Where on segment `a`–`b` the point nearest to `p` lies: its parameter
/// `t` in `[0, 1]` from `a` to `b`, and the point. A segment of no length
/// answers `a`.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::closest_on_segment;
/// let (t, q) = closest_on_segment(DVec2::new(1.0, 5.0), DVec2::ZERO, DVec2::new(4.0, 0.0));
/// assert_eq!((t, q), (0.25, DVec2::new(1.0, 0.0)));
/// assert_eq!(closest_on_segment(DVec2::new(9.0, 1.0), DVec2::ZERO, DVec2::new(4.0, 0.0)).0, 1.0);
/// ```
pub fn closest_on_segment(p: DVec2, a: DVec2, b: DVec2) -> (f64, DVec2) {
    let ab = b - a;
    let len2 = ab.length_squared();
    if len2 == 0.0 {
        return (0.0, a);
    }
    let t = ((p - a).dot(ab) / len2).clamp(0.0, 1.0);
    (t, a + ab * t)
}

/// Distance from `p` to the polyline through `points` (closed: back to the
/// first); infinite for no points.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::polyline_distance;
/// let l = [DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0)];
/// assert_eq!(polyline_distance(&l, false, DVec2::new(1.0, 2.0)), 2.0);
/// assert_eq!(polyline_distance(&l, true, DVec2::new(1.0, 2.0)), (0.5f64).sqrt());
/// ```
pub fn polyline_distance(points: &[DVec2], closed: bool, p: DVec2) -> f64 {
    let n = points.len();
    if n == 1 {
        return points[0].distance(p);
    }
    let segments = if closed { n } else { n.saturating_sub(1) };
    (0..segments)
        .map(|i| p.distance(closest_on_segment(p, points[i], points[(i + 1) % n]).1))
        .fold(f64::INFINITY, f64::min)
}
