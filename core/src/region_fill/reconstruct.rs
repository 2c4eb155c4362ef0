//! Reconstruction (section 4.4 of the curve-texture paper): the synthesized
//! graph's paths, which run through samples a spacing apart, made smooth.
//! Each stretch between corners is a centripetal Catmull–Rom spline through
//! the samples, written as cubic Béziers and flattened to a tolerance in
//! millimetres, so the SVG, the print and the canvas all show curves
//! rather than chords. Corners sharper than [`CORNER_TURN`] stay sharp
//! (a fret's keys), and path ends and junctions keep their places.

use glam::DVec2;
use lyon::geom::{CubicBezierSegment, LineSegment, point};

use super::{CurvePath, EdgeTangents};

/// Largest distance between a smoothed curve and the polyline it is drawn
/// with, mm: below what a pen or a nozzle shows.
pub const SMOOTH_TOLERANCE_MM: f64 = 0.01;

/// A turn sharper than this at a sample (radians) is a corner the curve
/// keeps, not a bend to round off.
pub const CORNER_TURN: f64 = 1.0;

/// `paths` made smooth: see the module notes.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, smooth_paths};
/// // Samples of a circle of radius 10, 1.5 mm apart: the smooth path stays
/// // much nearer the circle than the chords do.
/// let n = 42;
/// let ring: Vec<DVec2> = (0..n).map(|k| DVec2::from_angle(k as f64 / n as f64 * std::f64::consts::TAU) * 10.0).collect();
/// let smooth = smooth_paths(&[CurvePath { points_mm: ring, closed: true }]);
/// let worst = smooth[0].points_mm.iter().map(|p| (p.length() - 10.0).abs()).fold(0.0, f64::max);
/// assert!(worst < 0.005, "{worst}");
/// ```
pub fn smooth_paths(paths: &[CurvePath]) -> Vec<CurvePath> {
    smooth_paths_oriented(paths, &EdgeTangents::default())
}

/// As [`smooth_paths`], the curve leaving each sample in the direction the
/// synthesis assigned it ([`EdgeTangents::leaving`]) where it assigned
/// one: through a sample whose orientations are opposite, smoothly, even
/// where the samples turn sharply (a spiral's tight centre); at one whose
/// orientations are not, on a corner, even where the turn is slight; and
/// through a junction along the branch that continues the path. The
/// spline's reach along each direction is the Catmull–Rom one.
pub fn smooth_paths_oriented(paths: &[CurvePath], tangents: &EdgeTangents) -> Vec<CurvePath> {
    paths.iter().map(|p| smooth(p, tangents)).collect()
}

fn smooth(path: &CurvePath, tangents: &EdgeTangents) -> CurvePath {
    let p = &path.points_mm;
    let n = p.len();
    if n < 3 {
        return path.clone();
    }
    let closed = path.closed;
    let at = |i: isize| -> Option<DVec2> {
        if closed {
            Some(p[i.rem_euclid(n as isize) as usize])
        } else {
            (0..n as isize).contains(&i).then(|| p[i as usize])
        }
    };
    // Whether sample i is a corner (or an end of an open path).
    let corner = |i: isize| -> bool {
        match (at(i - 1), at(i), at(i + 1)) {
            (Some(a), Some(b), Some(c)) => {
                let (u, v) = (b - a, c - b);
                u.length() < 1e-12 || v.length() < 1e-12 || u.angle_to(v).abs() > CORNER_TURN
            }
            _ => true,
        }
    };
    let segments = if closed { n } else { n - 1 };
    let mut out = vec![p[0]];
    for i in 0..segments as isize {
        let (b, c) = (at(i).unwrap_or(p[0]), at(i + 1).unwrap_or(p[0]));
        // Neighbours across a corner are mirrored, so the tangent there
        // follows this segment alone.
        let a = if corner(i) { 2.0 * b - c } else { at(i - 1).unwrap_or(2.0 * b - c) };
        let d = if corner(i + 1) { 2.0 * c - b } else { at(i + 2).unwrap_or(2.0 * c - b) };
        let (c1, c2) = catmull_rom_controls(a, b, c, d);
        let c1 = tangents.leaving(at(i - 1), b, c).map_or(c1, |dir| b + dir * c1.distance(b));
        let c2 = tangents.leaving(at(i + 2), c, b).map_or(c2, |dir| c + dir * c2.distance(c));
        let to = |q: DVec2| point(q.x, q.y);
        let segment = CubicBezierSegment { from: to(b), ctrl1: to(c1), ctrl2: to(c2), to: to(c) };
        segment.for_each_flattened(SMOOTH_TOLERANCE_MM, &mut |l: &LineSegment<f64>| {
            out.push(DVec2::new(l.to.x, l.to.y));
        });
    }
    if closed {
        out.pop();
    }
    CurvePath { points_mm: out, closed }
}

/// The Bézier controls of the centripetal Catmull–Rom segment from `b` to
/// `c` (Yuksel, Schaefer and Keyser's parameterization, which neither
/// overshoots nor loops where samples bunch).
fn catmull_rom_controls(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> (DVec2, DVec2) {
    let knot = |p: DVec2, q: DVec2| p.distance(q).sqrt().max(1e-9);
    let (t01, t12, t23) = (knot(a, b), knot(b, c), knot(c, d));
    let m1 = (c - b + t12 * ((b - a) / t01 - (c - a) / (t01 + t12))) / 3.0;
    let m2 = (c - b + t12 * ((d - c) / t23 - (d - b) / (t12 + t23))) / 3.0;
    (b + m1, c - m2)
}
