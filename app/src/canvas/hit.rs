//! Hit testing: which curve is under the pointer.

use tracery_core::DVec2;
use tracery_core::geom::closest_on_segment;

/// Distance from `p` to a polyline.
pub fn distance_to(points: &[DVec2], closed: bool, p: DVec2) -> f64 {
    let n = points.len();
    if n == 1 {
        return points[0].distance(p);
    }
    let segments = if closed { n } else { n - 1 };
    (0..segments)
        .map(|i| p.distance(closest_on_segment(p, points[i], points[(i + 1) % n]).1))
        .fold(f64::INFINITY, f64::min)
}
