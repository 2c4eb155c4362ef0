//! Loose ends of drawn strokes met by new paths: where the synthesis left
//! a new path's end just short of a drawn stroke's free end, the new path
//! is carried on to it, so the stroke reads as continued, not as two
//! strokes with a gap a printer may or may not close.

use glam::DVec2;

use super::{CurvePath, JOIN_TOLERANCE_MM};

/// Joins free ends of `drawn` paths to the nearest end of a `new` path
/// within `reach_mm`: the path's end point moves onto the drawn end when
/// the gap is short beside the path's last segment, and a segment is added
/// otherwise, so no sliver of a segment makes a kink. A drawn end that a new path already touches is left alone, and
/// each new end joins at most one drawn end. Returns how many were joined.
///
/// A new path that runs on through a drawn end is cut there first, and a
/// piece of it shorter than `reach_mm` beyond the end goes: the synthesis
/// grew the drawn stroke on through its end, and the stub overshoots it.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, join_drawn_ends};
/// let drawn = [CurvePath { points_mm: vec![DVec2::ZERO, DVec2::new(10.0, 0.0)], closed: false }];
/// let mut new = vec![CurvePath { points_mm: vec![DVec2::new(10.8, 0.3), DVec2::new(20.0, 0.0)], closed: false }];
/// assert_eq!(join_drawn_ends(&mut new, &drawn, 1.5), 1);
/// assert_eq!(new[0].points_mm[0], DVec2::new(10.0, 0.0));
/// ```
pub fn join_drawn_ends(new: &mut Vec<CurvePath>, drawn: &[CurvePath], reach_mm: f64) -> usize {
    split_at_drawn_ends(new, drawn, reach_mm);
    let mut taken = vec![[false; 2]; new.len()];
    let mut joined = 0;
    for end in drawn.iter().filter_map(CurvePath::free_ends).flatten() {
        // Another drawn stroke, or a new path through it: already met.
        let met = |p: &CurvePath| p.distance_to(end) <= JOIN_TOLERANCE_MM;
        if new.iter().any(met) || drawn.iter().filter(|p| !is_end_of(p, end)).any(met) {
            continue;
        }
        let nearest = new
            .iter()
            .enumerate()
            .filter_map(|(k, p)| p.free_ends().map(|[a, b]| [(k, 0, a), (k, 1, b)]))
            .flatten()
            .filter(|&(k, side, q)| !taken[k][side] && q.distance(end) <= reach_mm)
            .min_by(|a, b| a.2.distance(end).total_cmp(&b.2.distance(end)));
        let Some((k, side, _)) = nearest else { continue };
        let points = &mut new[k].points_mm;
        if side == 1 {
            points.reverse();
        }
        if points[0].distance(end) < 0.5 * points[0].distance(points[1]) {
            points[0] = end;
        } else {
            points.insert(0, end);
        }
        if side == 1 {
            points.reverse();
        }
        taken[k][side] = true;
        joined += 1;
    }
    joined
}

/// Whether `end` is one of `path`'s own ends.
fn is_end_of(path: &CurvePath, end: DVec2) -> bool {
    path.points_mm.first() == Some(&end) || path.points_mm.last() == Some(&end)
}

/// Cuts new paths where they pass through a drawn free end, dropping
/// pieces shorter than `stub_mm`.
fn split_at_drawn_ends(new: &mut Vec<CurvePath>, drawn: &[CurvePath], stub_mm: f64) {
    let ends: Vec<DVec2> = drawn.iter().filter_map(CurvePath::free_ends).flatten().collect();
    let on_end = |q: DVec2| ends.iter().any(|e| e.distance(q) <= JOIN_TOLERANCE_MM);
    let mut out = Vec::with_capacity(new.len());
    for path in new.drain(..) {
        let points = &path.points_mm;
        let cuts: Vec<usize> = (1..points.len().saturating_sub(1)).filter(|&i| on_end(points[i])).collect();
        if cuts.is_empty() || path.closed {
            out.push(path);
            continue;
        }
        let mut start = 0;
        for cut in cuts.into_iter().chain([points.len() - 1]) {
            let piece = CurvePath { points_mm: points[start..=cut].to_vec(), closed: false };
            if piece.length_mm() >= stub_mm {
                out.push(piece);
            }
            start = cut;
        }
    }
    *new = out;
}
