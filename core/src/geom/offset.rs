//! Offsetting a region outwards (dilation) or inwards (erosion), through
//! `i_overlay`'s outline offset with round joins.

use i_overlay::mesh::float::outline::offset::OutlineOffset;
use i_overlay::mesh::float::style::{LineJoin, OutlineStyle};

use super::boolean::{Contour, from_shapes};
use super::{Region, arc_step};

/// Largest distance between a round join's arc and its chords, mm. Far
/// below what a nozzle or a laser resolves.
pub const OFFSET_ARC_TOLERANCE_MM: f64 = 0.005;

/// `region` grown by `distance_mm` (shrunk when negative), with round
/// corners: every outer contour moves out and every hole moves in by
/// `distance_mm`. Parts thinner than twice a negative distance vanish;
/// gaps narrower than twice a positive one close.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region, offset};
/// let square = vec![DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)];
/// let region = Region::new(vec![Polygon { outer: square, holes: vec![] }]);
/// let grown = offset(&region, 0.5);
/// // The square, four 0.5 mm strips and four quarter discs.
/// let expected = 16.0 + 4.0 * 4.0 * 0.5 + std::f64::consts::PI * 0.25;
/// assert!((grown.area() - expected).abs() < 0.01);
/// assert!(offset(&region, -2.1).is_empty());
/// ```
pub fn offset(region: &Region, distance_mm: f64) -> Region {
    if region.is_empty() || distance_mm == 0.0 {
        return region.clone();
    }
    let radius = distance_mm.abs();
    // The arc step (chord length over radius) that keeps the chord error
    // under the tolerance.
    let step = arc_step(radius, OFFSET_ARC_TOLERANCE_MM);
    let style = OutlineStyle::new(distance_mm).line_join(LineJoin::Round(step.max(0.05)));
    let shapes: Vec<Vec<Contour>> =
        region.polygons.iter().map(|p| p.rings().map(|r| r.iter().map(|q| [q.x, q.y]).collect()).collect()).collect();
    from_shapes(shapes.outline_as::<i64>(&style))
}
