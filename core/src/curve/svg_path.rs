//! A curve taken from a drawing: the first path of an SVG document.

use glam::DVec2;

use super::CurveError;
use crate::geom::flatten::{Subpath, flatten_subpaths};

/// Millimetres per CSS pixel (96 px to the inch).
const MM_PER_PX: f64 = 25.4 / 96.0;

/// Whether the document's root gives its `width` in a physical unit (mm,
/// cm, in, pt, pc): then the drawing has a real size to honour. Without one
/// (a bare number, or px), user units are taken as millimetres.
fn has_physical_size(data: &[u8]) -> bool {
    let mut reader = quick_xml::Reader::from_reader(data);
    let mut buf = Vec::new();
    loop {
        match reader.read_event_into(&mut buf) {
            Ok(quick_xml::events::Event::Start(e) | quick_xml::events::Event::Empty(e))
                if e.local_name().as_ref() == b"svg" =>
            {
                let width = e.attributes().flatten().find(|a| a.key.as_ref() == b"width");
                let value = width.map(|a| String::from_utf8_lossy(&a.value).trim().to_ascii_lowercase());
                return value.is_some_and(|v| ["mm", "cm", "in", "pt", "pc"].iter().any(|u| v.ends_with(u)));
            }
            Ok(quick_xml::events::Event::Eof) | Err(_) => return false,
            _ => {}
        }
        buf.clear();
    }
}

/// The first path of an SVG document (in document order) as a polyline in
/// millimetres, `y` flipped to point up; a closed path repeats its first
/// point at the end. A document sized in a physical unit (`width="100mm"`)
/// keeps its real size; otherwise one user unit is one millimetre. Used to
/// take a curve from a drawing.
///
/// ```
/// let mm = br#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><path d="M10,50 L90,50"/></svg>"#;
/// let points = tracery_core::curve::first_path_points(mm).unwrap();
/// assert!((points[0].distance(points[1]) - 80.0).abs() < 1e-3);
/// let bare = br#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path d="M10,50 L90,50"/></svg>"#;
/// let points = tracery_core::curve::first_path_points(bare).unwrap();
/// assert!((points[0].distance(points[1]) - 80.0).abs() < 1e-3);
/// ```
pub fn first_path_points(data: &[u8]) -> Result<Vec<DVec2>, CurveError> {
    let tree = usvg::Tree::from_data(data, &usvg::Options::default()).map_err(|e| CurveError::NotSvg(e.to_string()))?;
    fn first(group: &usvg::Group) -> Option<&usvg::Path> {
        group.children().iter().find_map(|node| match node {
            usvg::Node::Group(g) => first(g),
            usvg::Node::Path(p) => Some(p.as_ref()),
            _ => None,
        })
    }
    let path = first(tree.root()).ok_or(CurveError::NoPath)?;
    let bbox = tree.root().abs_bounding_box();
    let tolerance = (f64::from(bbox.width()).hypot(f64::from(bbox.height())) * 1e-4).max(1e-9);
    let points = match flatten_subpaths(path.data(), path.abs_transform(), tolerance).into_iter().next() {
        Some(Subpath { mut points, closed }) => {
            if closed && let Some(&first) = points.first() {
                points.push(first);
            }
            points
        }
        None => Vec::new(),
    };
    if points.iter().any(|p| !p.is_finite()) {
        return Err(CurveError::NotFinite);
    }
    // usvg maps the viewBox onto the document's size in CSS pixels.
    let scale = if has_physical_size(data) { MM_PER_PX } else { 1.0 };
    Ok(points.into_iter().map(|p| p * scale).collect())
}
