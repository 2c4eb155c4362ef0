//! Geometry at a resolution: details far below what a printer or a laser
//! resolves, but which still change the topology (a hairline sliver between
//! two strokes drawn nearly tangent), are removed the same way from the
//! exemplar and from the result, so that a small deformation cannot flip
//! the count.

use glam::DVec2;

use super::{Polygon, Region, ring_perimeter, signed_area};

/// Mean width of a ring, `2·area / perimeter`: half the width of a long thin
/// strip, a quarter of the diameter of a disc.
///
/// ```
/// use glam::DVec2;
/// let strip = [DVec2::ZERO, DVec2::new(10.0, 0.0), DVec2::new(10.0, 0.1), DVec2::new(0.0, 0.1)];
/// let w = tracery_core::geom::mean_width(&strip);
/// assert!((w - 0.0990).abs() < 1e-3);
/// ```
pub fn mean_width(ring: &[DVec2]) -> f64 {
    let perimeter = ring_perimeter(ring);
    if perimeter <= 0.0 {
        return 0.0;
    }
    2.0 * signed_area(ring).abs() / perimeter
}

/// `region` without the holes and parts whose [`mean_width`] is below
/// `width`: hairline slivers left where two outlines nearly coincide, and
/// specks. Holes are filled, parts dropped. Cheap: no boolean operation.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{Polygon, Region, without_slivers};
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let mut sliver = vec![DVec2::new(-1.0, 0.0), DVec2::new(1.0, 0.0), DVec2::new(1.0, 0.001), DVec2::new(-1.0, 0.001)];
/// sliver.reverse();
/// let region = Region::new(vec![Polygon { outer: square(2.0), holes: vec![sliver] }]);
/// assert_eq!(without_slivers(&region, 0.01).hole_count(), 0);
/// ```
pub fn without_slivers(region: &Region, width: f64) -> Region {
    let polygons = region
        .polygons
        .iter()
        .filter(|p| mean_width(&p.outer) >= width)
        .map(|p| Polygon {
            outer: p.outer.clone(),
            holes: p.holes.iter().filter(|h| mean_width(h) >= width).cloned().collect(),
        })
        .collect();
    Region { polygons }
}
