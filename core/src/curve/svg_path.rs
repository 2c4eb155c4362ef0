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
    let tree = crate::svg_input::parse(data).map_err(CurveError::NotSvg)?;
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

/// One subpath of a drawing, in millimetres, `y` up.
#[derive(Clone, Debug, PartialEq)]
pub struct SvgShape {
    /// The points (a closed subpath does not repeat its first).
    pub points_mm: Vec<DVec2>,
    /// Whether the subpath ended with a `Z`.
    pub closed: bool,
    /// Whether its path is filled.
    pub filled: bool,
    /// Whether its path is stroked.
    pub stroked: bool,
    /// Which path of the document it belongs to, counted from 0: the
    /// subpaths of one filled path make one shape (a hole is one of them).
    pub element: usize,
    /// How its path's fill decides what is inside.
    pub fill_rule: crate::geom::FillRule,
}

/// Every subpath of every path of an SVG document, flattened so that no
/// point of a curve is farther than `tolerance_mm` from its chords, in
/// millimetres (sized as [`first_path_points`] sizes them), `y` up.
///
/// ```
/// let svg = br#"<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="40mm" viewBox="0 0 40 40">
///   <path d="M0,0 C10,10 20,10 30,0" stroke="black" fill="none"/>
///   <circle cx="20" cy="20" r="5"/></svg>"#;
/// let shapes = tracery_core::curve::svg_shapes(svg, 0.01).unwrap();
/// assert_eq!(shapes.len(), 2);
/// assert!(shapes[0].stroked && !shapes[0].filled && !shapes[0].closed);
/// assert!(shapes[1].filled && shapes[1].closed);
/// ```
pub fn svg_shapes(data: &[u8], tolerance_mm: f64) -> Result<Vec<SvgShape>, CurveError> {
    let tree = crate::svg_input::parse(data).map_err(CurveError::NotSvg)?;
    let scale = if has_physical_size(data) { MM_PER_PX } else { 1.0 };
    // The tolerance is absolute: a drawing kilometres across would be
    // flattened into billions of points. Checked before flattening.
    let bbox = tree.root().abs_bounding_box();
    let reach_mm = [bbox.left(), bbox.right(), bbox.top(), bbox.bottom()]
        .iter()
        .map(|c| f64::from(c.abs()) * scale)
        .fold(0.0, f64::max);
    if reach_mm.is_nan() || reach_mm > crate::setting::WORLD_EXTENT_MM {
        return Err(CurveError::TooFar(reach_mm));
    }
    let tolerance = (tolerance_mm / scale).max(1e-9);
    let mut shapes = Vec::new();
    fn walk(group: &usvg::Group, tolerance: f64, scale: f64, shapes: &mut Vec<SvgShape>, elements: &mut usize) {
        for node in group.children() {
            match node {
                usvg::Node::Group(g) => walk(g, tolerance, scale, shapes, elements),
                usvg::Node::Path(path) => {
                    let element = *elements;
                    *elements += 1;
                    let fill_rule = path.fill().map(|f| f.rule().into()).unwrap_or_default();
                    for sub in flatten_subpaths(path.data(), path.abs_transform(), tolerance) {
                        let mut points_mm: Vec<DVec2> = sub.points.iter().map(|p| *p * scale).collect();
                        points_mm.dedup_by(|a, b| a.distance(*b) < 1e-9);
                        if sub.closed
                            && points_mm.len() > 2
                            && points_mm[0].distance(points_mm[points_mm.len() - 1]) < 1e-9
                        {
                            points_mm.pop();
                        }
                        shapes.push(SvgShape {
                            points_mm,
                            closed: sub.closed,
                            filled: path.fill().is_some(),
                            stroked: path.stroke().is_some(),
                            element,
                            fill_rule,
                        });
                    }
                }
                _ => {}
            }
        }
    }
    walk(tree.root(), tolerance, scale, &mut shapes, &mut 0);
    if shapes.iter().flat_map(|s| &s.points_mm).any(|p| !p.is_finite()) {
        return Err(CurveError::NotFinite);
    }
    Ok(shapes)
}
