//! The plane geometry of the blends that round a curve's tight turns
//! (`rounding.rs`): where two lines meet, an arc between them, the tightest
//! turn of a quadratic Bézier.

use glam::DVec2;

/// Degrees of arc between the points that draw a rounded corner.
pub(super) const ARC_STEP_DEG: f64 = 3.0;

/// The tightest radius of curvature of the quadratic Bézier `p0, p1, p2`,
/// sampled finely enough for the blends here.
pub(super) fn quadratic_min_radius(p0: DVec2, p1: DVec2, p2: DVec2) -> f64 {
    let second = 2.0 * (p2 - 2.0 * p1 + p0);
    (0..=32)
        .map(|k| {
            let s = k as f64 / 32.0;
            let first = 2.0 * ((1.0 - s) * (p1 - p0) + s * (p2 - p1));
            let cross = first.perp_dot(second).abs();
            if cross < 1e-300 { f64::INFINITY } else { first.length().powi(3) / cross }
        })
        .fold(f64::INFINITY, f64::min)
}

/// Where the line through `p` along `t` meets the line through `q` along
/// `u` (the two not parallel).
pub(super) fn lines_meet(p: DVec2, t: DVec2, q: DVec2, u: DVec2) -> DVec2 {
    p + t * (q - p).perp_dot(u) / t.perp_dot(u)
}

/// An arc turning by `turn` from the point `reach` before `apex` on the
/// line along `t_in` through it, on a circle of `radius`, its points every
/// [`ARC_STEP_DEG`] or closer.
pub(super) fn arc_from(apex: DVec2, t_in: DVec2, turn: f64, reach: f64, radius: f64) -> Vec<DVec2> {
    let arc_start = apex - t_in * reach;
    let centre = arc_start + t_in.perp() * radius * turn.signum();
    let steps = ((turn.abs().to_degrees() / ARC_STEP_DEG).ceil() as usize).max(2);
    (0..=steps).map(|k| centre + DVec2::from_angle(turn * k as f64 / steps as f64).rotate(arc_start - centre)).collect()
}
