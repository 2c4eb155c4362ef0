//! SVG output of a planar pattern, for laser cutting.

use std::fmt::Write;

use crate::geom::{Rect, Region};

/// The region as an SVG document in millimetres: one filled path per
/// component (outer ring and holes, `evenodd`), with a `viewBox` framing the
/// pattern and a small margin. SVG's `y` points down, so `y` is flipped.
///
/// ```
/// use tracery_core::export::region_to_svg;
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let mut hole = square(1.0);
/// hole.reverse();
/// let frame = Region::new(vec![Polygon { outer: square(2.0), holes: vec![hole] }]);
/// let svg = region_to_svg(&frame);
/// assert_eq!(svg.matches("<path").count(), 1);
/// assert!(svg.contains("evenodd") && svg.contains("viewBox"));
/// ```
pub fn region_to_svg(region: &Region) -> String {
    let bounds = region.bounds().unwrap_or(Rect::new(glam::DVec2::ZERO, glam::DVec2::ONE));
    let margin = 0.02 * bounds.size().max_element().max(1.0);
    let r = bounds.inflate(margin);
    let (w, h) = (r.width(), r.height());
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.3}mm" height="{h:.3}mm" viewBox="{:.4} {:.4} {w:.4} {h:.4}">"#,
        r.min.x, -r.max.y
    );
    for polygon in &region.polygons {
        let mut d = String::new();
        for ring in polygon.rings() {
            for (k, p) in ring.iter().enumerate() {
                let _ = write!(d, "{}{:.6},{:.6} ", if k == 0 { 'M' } else { 'L' }, p.x, -p.y);
            }
            d.push_str("Z ");
        }
        let _ = writeln!(svg, r#"  <path fill="black" fill-rule="evenodd" d="{}"/>"#, d.trim_end());
    }
    svg.push_str("</svg>\n");
    svg
}
