//! Hit testing: which curve is under the pointer.

use tracery_core::DVec2;

/// Distance from `p` to a polyline.
pub fn distance_to(points: &[DVec2], closed: bool, p: DVec2) -> f64 {
    let n = points.len();
    if n == 1 {
        return points[0].distance(p);
    }
    let segments = if closed { n } else { n - 1 };
    (0..segments)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            let t = ((p - a).dot(b - a) / (b - a).length_squared().max(1e-12)).clamp(0.0, 1.0);
            p.distance(a.lerp(b, t))
        })
        .fold(f64::INFINITY, f64::min)
}
