//! A curve taken from a drawing: the first path of an SVG document.

use glam::DVec2;

use super::CurveError;
use crate::geom::flatten::{Subpath, flatten_subpaths};

/// The first path of an SVG document (in document order) as a polyline in
/// user units, `y` flipped to point up; a closed path repeats its first point
/// at the end. Used to take a curve from a drawing.
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
    Ok(points)
}
