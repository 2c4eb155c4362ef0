//! New paths that run along a drawn stroke. The synthesis pins what a
//! person drew, and now and then grows a path of its own beside it: a
//! second line on top of the first, which a plotter draws twice and a
//! printer merges into one thick stroke. Such runs are cut out of the new
//! paths; a new path that only meets a drawn stroke (a stalk on a stem)
//! keeps its junction.

use glam::DVec2;

use super::CurvePath;
use crate::geom::closest_on_segment;

/// A new path's point nearer a drawn stroke than this many spacings δ lies
/// on it: the exemplar's own paths are sampled every δ and do not run this
/// close side by side.
pub const ALONG_DRAWN_SPACINGS: f64 = 0.5;

/// A stretch on a drawn stroke at least this many spacings long is a path
/// running along it, not a junction: a path ending on a stroke at an angle
/// θ lies on it for `0.5 δ / sin θ`, so junctions steeper than 30° are
/// never cut.
pub const ALONG_DRAWN_MIN_RUN_SPACINGS: f64 = 1.0;

/// Cuts out of `paths` every stretch that runs along one of the `drawn`
/// strokes (within [`ALONG_DRAWN_SPACINGS`] of it over
/// [`ALONG_DRAWN_MIN_RUN_SPACINGS`] or more), ending the pieces on either
/// side on the drawn stroke, and drops pieces shorter than `min_mm`.
/// Returns the paths and how many stretches were cut.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, cut_runs_along_drawn};
/// let line = |a: DVec2, b: DVec2| CurvePath { points_mm: vec![a, b], closed: false };
/// let drawn = [line(DVec2::ZERO, DVec2::new(10.0, 0.0))];
/// // Runs 6 mm along the drawn stroke, 0.3 mm beside it, then leaves it.
/// let new = CurvePath {
///     points_mm: vec![DVec2::new(2.0, 0.3), DVec2::new(8.0, 0.3), DVec2::new(8.0, 6.0)],
///     closed: false,
/// };
/// let (kept, cut) = cut_runs_along_drawn(vec![new], &drawn, 1.5, 1.0);
/// assert_eq!(cut, 1);
/// assert_eq!(kept.len(), 1);
/// assert!(kept[0].points_mm.iter().all(|p| p.x >= 7.9));
/// // A stalk that only ends on the stroke stays whole.
/// let stalk = line(DVec2::new(5.0, 0.0), DVec2::new(5.0, 4.0));
/// assert_eq!(cut_runs_along_drawn(vec![stalk.clone()], &drawn, 1.5, 1.0), (vec![stalk], 0));
/// ```
pub fn cut_runs_along_drawn(
    paths: Vec<CurvePath>,
    drawn: &[CurvePath],
    delta_mm: f64,
    min_mm: f64,
) -> (Vec<CurvePath>, usize) {
    let near_mm = ALONG_DRAWN_SPACINGS * delta_mm;
    let min_run_mm = ALONG_DRAWN_MIN_RUN_SPACINGS * delta_mm;
    let drawn: Vec<&CurvePath> = drawn.iter().filter(|d| d.points_mm.len() >= 2).collect();
    let mut out = Vec::with_capacity(paths.len());
    let mut cut = 0;
    for path in paths {
        if drawn.is_empty() || path.points_mm.len() < 2 {
            out.push(path);
            continue;
        }
        // Dense enough that no stretch on a stroke hides between two points.
        let points = densified(&path, 0.25 * near_mm);
        let nearest: Vec<Nearest> = points.iter().map(|&p| nearest_on(&drawn, p)).collect();
        let on: Vec<bool> = nearest.iter().map(|n| n.distance_mm <= near_mm).collect();
        let runs = long_runs(&points, &on, min_run_mm);
        if runs.is_empty() {
            out.push(path);
            continue;
        }
        cut += runs.len();
        let run_edge = |i: usize| runs.iter().any(|&(start, end)| i == start || i == end);
        for piece in pieces_between(points.len(), &runs, path.closed) {
            let mut points_mm: Vec<DVec2> = piece.iter().map(|&i| points[i]).collect();
            // Ends cut on a stroke join it exactly.
            let (first, last) = (piece[0], piece[piece.len() - 1]);
            if run_edge(first) {
                points_mm[0] = nearest[first].point_mm;
            }
            if run_edge(last) {
                let end = points_mm.len() - 1;
                points_mm[end] = nearest[last].point_mm;
            }
            let piece = CurvePath { points_mm, closed: false };
            if piece.length_mm() >= min_mm {
                out.push(piece);
            }
        }
    }
    (out, cut)
}

/// Where a drawn stroke comes nearest a point.
#[derive(Clone, Copy)]
struct Nearest {
    distance_mm: f64,
    point_mm: DVec2,
}

/// The nearest point of the `drawn` strokes to `p`.
fn nearest_on(drawn: &[&CurvePath], p: DVec2) -> Nearest {
    let mut best = Nearest { distance_mm: f64::INFINITY, point_mm: p };
    for d in drawn {
        let pts = &d.points_mm;
        let n = pts.len();
        let segments = if d.closed { n } else { n - 1 };
        for i in 0..segments {
            let q = closest_on_segment(p, pts[i], pts[(i + 1) % n]).1;
            let distance_mm = q.distance(p);
            if distance_mm < best.distance_mm {
                best = Nearest { distance_mm, point_mm: q };
            }
        }
    }
    best
}

/// The path's points with more put in where two lie farther apart than
/// `step_mm`; a loop's first point is repeated at the end.
fn densified(path: &CurvePath, step_mm: f64) -> Vec<DVec2> {
    let pts = &path.points_mm;
    let mut out = vec![pts[0]];
    let ends = pts.iter().skip(1).chain(path.closed.then_some(&pts[0]));
    for (&a, &b) in pts.iter().zip(ends) {
        let k = (a.distance(b) / step_mm.max(1e-6)).ceil().max(1.0) as usize;
        out.extend((1..=k).map(|j| a.lerp(b, j as f64 / k as f64)));
    }
    out
}

/// Index ranges (inclusive) of the stretches of points marked `on` whose
/// length is at least `min_mm`.
fn long_runs(points: &[DVec2], on: &[bool], min_mm: f64) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut i = 0;
    while i < points.len() {
        if !on[i] {
            i += 1;
            continue;
        }
        let start = i;
        while i + 1 < points.len() && on[i + 1] {
            i += 1;
        }
        let length: f64 = points[start..=i].windows(2).map(|w| w[0].distance(w[1])).sum();
        if length >= min_mm {
            runs.push((start, i));
        }
        i += 1;
    }
    runs
}

/// The pieces outside the `runs` of a path of `count` points, as indices,
/// each including the run's first or last point where it meets one. A loop
/// cut at least once is opened so that the piece across its start is one
/// piece.
fn pieces_between(count: usize, runs: &[(usize, usize)], closed: bool) -> Vec<Vec<usize>> {
    let last = count - 1;
    let mut pieces: Vec<Vec<usize>> = Vec::new();
    let mut from = 0;
    for &(start, end) in runs {
        if start > from {
            pieces.push((from..=start).collect());
        }
        from = end;
    }
    if from < last {
        pieces.push((from..=last).collect());
    }
    // Across a loop's start (its last point is its first again), the last
    // piece runs on into the first.
    if closed && pieces.len() >= 2 && runs[0].0 > 0 && runs[runs.len() - 1].1 < last {
        let first = pieces.remove(0);
        pieces.last_mut().expect("two pieces").extend(first.into_iter().skip(1));
    }
    pieces.retain(|p| p.len() >= 2);
    pieces
}
