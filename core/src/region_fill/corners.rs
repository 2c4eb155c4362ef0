//! Corners of an exemplar's paths: where a path turns sharply within a
//! short reach, as a fret's keys do. A corner is cut like a junction, so a
//! sample sits on it and its two orientations (the path leaving each way)
//! keep the corner, which samples a spacing either side of it could not.

use super::CurvePath;
use crate::curve::Curve;

/// Vertices of `path` where it turns by more than `min_turn` radians
/// between the points `reach_mm` of arc before and after: the sharpest of
/// any such vertices within `reach_mm` of each other, so a corner drawn
/// with a few short segments (a rounded or smoothed corner) is one corner.
/// The ends of an open path are not corners.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, corner_vertices};
/// // An L, and the same L with its corner cut by a short chamfer.
/// let l = CurvePath { points_mm: vec![DVec2::new(0.0, 5.0), DVec2::ZERO, DVec2::new(5.0, 0.0)], closed: false };
/// assert_eq!(corner_vertices(&l, 0.4, 1.0), vec![1]);
/// let chamfer = CurvePath { points_mm: vec![DVec2::new(0.0, 5.0), DVec2::new(0.0, 0.1), DVec2::new(0.1, 0.0), DVec2::new(5.0, 0.0)], closed: false };
/// assert_eq!(corner_vertices(&chamfer, 0.4, 1.0).len(), 1);
/// // A circle of radius 5 turns 0.16 radians over 0.4 mm each way: no corner.
/// let ring: Vec<DVec2> = (0..64).map(|k| DVec2::from_angle(k as f64 / 64.0 * std::f64::consts::TAU) * 5.0).collect();
/// assert!(corner_vertices(&CurvePath { points_mm: ring, closed: true }, 0.4, 1.0).is_empty());
/// ```
pub fn corner_vertices(path: &CurvePath, reach_mm: f64, min_turn: f64) -> Vec<usize> {
    let n = path.points_mm.len();
    let Ok(curve) = Curve::from_polyline(&path.points_mm, path.closed) else { return Vec::new() };
    let lengths = path.cumulative_lengths();
    let total = *lengths.last().unwrap_or(&0.0);
    let interior = if path.closed { 0..n } else { 1..n.saturating_sub(1) };
    let turns: Vec<(usize, f64)> = interior
        .filter_map(|j| {
            let (at, p) = (lengths[j], path.points_mm[j]);
            if !path.closed && (at < reach_mm || at > total - reach_mm) {
                return None;
            }
            let (before, after) = (p - curve.point(at - reach_mm), curve.point(at + reach_mm) - p);
            if before.length() < 1e-9 || after.length() < 1e-9 {
                return None;
            }
            let turn = before.angle_to(after).abs();
            (turn > min_turn).then_some((j, turn))
        })
        .collect();
    // Arc distance between two vertices, the short way round a loop.
    let apart = |a: usize, b: usize| {
        let d = (lengths[a] - lengths[b]).abs();
        if path.closed { d.min(total - d) } else { d }
    };
    turns
        .iter()
        .filter(|&&(j, turn)| {
            turns.iter().all(|&(k, other)| k == j || apart(j, k) > reach_mm || other < turn || (other == turn && j < k))
        })
        .map(|&(j, _)| j)
        .collect()
}
