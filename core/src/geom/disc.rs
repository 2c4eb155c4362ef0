//! Discs as polygons, and how finely an arc must be cut to stay within a
//! tolerance.

use glam::DVec2;

use super::Polygon;

/// The angle an arc of `radius` may turn per chord so that the chord stays
/// within `tolerance` of it: `2·acos(1 − tolerance / radius)`.
///
/// ```
/// let step = tracery_core::geom::arc_step(1.0, 1.0 - (0.25f64).cos());
/// assert!((step - 0.5).abs() < 1e-12);
/// ```
pub fn arc_step(radius: f64, tolerance: f64) -> f64 {
    2.0 * (1.0 - (tolerance / radius).min(1.0)).acos()
}

/// A disc as a regular polygon of `sides` corners on its circle,
/// counter-clockwise, the first on the `x` axis.
///
/// ```
/// use tracery_core::DVec2;
/// let square = tracery_core::geom::disc(DVec2::ZERO, 1.0, 4);
/// assert_eq!(square.outer.len(), 4);
/// assert!((square.area() - 2.0).abs() < 1e-12);
/// ```
pub fn disc(centre: DVec2, radius: f64, sides: usize) -> Polygon {
    let outer = (0..sides)
        .map(|k| centre + DVec2::from_angle(k as f64 / sides as f64 * std::f64::consts::TAU) * radius)
        .collect();
    Polygon { outer, holes: Vec::new() }
}
