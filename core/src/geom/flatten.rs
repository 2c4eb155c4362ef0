//! Flattening SVG paths (through `usvg`'s path data) into polylines with
//! `lyon`, at an explicit tolerance: one flattener serves exemplar fills and
//! curves taken from drawings.

use glam::DVec2;
use lyon::geom::{CubicBezierSegment, LineSegment, QuadraticBezierSegment, point};
use usvg::tiny_skia_path::{self, PathSegment};

/// One subpath of a flattened path: its points in `(u, v)` (SVG `y`
/// flipped), as computed (not yet checked for finiteness), and whether it
/// ended with a `Z`.
pub struct Subpath {
    /// The points, `(u, v)` with SVG `y` flipped.
    pub points: Vec<DVec2>,
    /// Whether the subpath ended with a `Z`.
    pub closed: bool,
}

/// Flattens every subpath of `path`, transformed by `t`, within `tolerance`.
pub fn flatten_subpaths(path: &tiny_skia_path::Path, t: usvg::Transform, tolerance: f64) -> Vec<Subpath> {
    let map = |p: tiny_skia_path::Point| {
        let (x, y) = (f64::from(p.x), f64::from(p.y));
        let (sx, kx, ky, sy) = (f64::from(t.sx), f64::from(t.kx), f64::from(t.ky), f64::from(t.sy));
        point(sx * x + kx * y + f64::from(t.tx), ky * x + sy * y + f64::from(t.ty))
    };
    let flip = |p: lyon::geom::Point<f64>| DVec2::new(p.x, -p.y);
    let mut subpaths: Vec<Subpath> = Vec::new();
    let mut current: Vec<DVec2> = Vec::new();
    let mut last = point(0.0, 0.0);
    for segment in path.segments() {
        match segment {
            PathSegment::MoveTo(p) => {
                if !current.is_empty() {
                    subpaths.push(Subpath { points: std::mem::take(&mut current), closed: false });
                }
                last = map(p);
                current.push(flip(last));
            }
            PathSegment::LineTo(p) => {
                last = map(p);
                current.push(flip(last));
            }
            PathSegment::QuadTo(c, p) => {
                let seg = QuadraticBezierSegment { from: last, ctrl: map(c), to: map(p) };
                seg.for_each_flattened(tolerance, &mut |l: &LineSegment<f64>| current.push(flip(l.to)));
                last = seg.to;
            }
            PathSegment::CubicTo(c1, c2, p) => {
                let seg = CubicBezierSegment { from: last, ctrl1: map(c1), ctrl2: map(c2), to: map(p) };
                seg.for_each_flattened(tolerance, &mut |l: &LineSegment<f64>| current.push(flip(l.to)));
                last = seg.to;
            }
            PathSegment::Close => {
                if !current.is_empty() {
                    subpaths.push(Subpath { points: std::mem::take(&mut current), closed: true });
                }
            }
        }
    }
    if !current.is_empty() {
        subpaths.push(Subpath { points: current, closed: false });
    }
    subpaths
}

/// Flattens a path into closed polylines for filling: points that are not
/// numbers and repeated points dropped, open subpaths closed implicitly (as
/// fills do), and rings of fewer than three points left out.
pub fn flatten(path: &tiny_skia_path::Path, t: usvg::Transform, tolerance: f64) -> Vec<Vec<DVec2>> {
    flatten_subpaths(path, t, tolerance)
        .into_iter()
        .filter_map(|Subpath { mut points, .. }| {
            points.retain(|p| p.is_finite());
            points.dedup();
            if points.len() > 1 && points.first() == points.last() {
                points.pop();
            }
            (points.len() >= 3).then_some(points)
        })
        .collect()
}
