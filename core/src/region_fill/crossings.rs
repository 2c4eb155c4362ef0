//! Crossings the exemplar never has: where its paths never pass through
//! each other, a fill's paths must not either (the paper's quality measure,
//! and what a pen plotter or a laser shows plainly). The synthesis avoids
//! most; the few left are cut: the shorter of the two paths is broken at
//! the crossing, its two new ends drawn back from the other path.

use glam::DVec2;

use super::CurvePath;

/// At most this many rounds of finding and cutting: each round cuts every
/// path at most once, and a cut never makes a new crossing, so rounds are
/// few; the cap only bounds pathological input.
const MAX_ROUNDS: usize = 64;

/// A proper crossing: two segments that pass through each other, each
/// named by its path and its first point's index, and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// Path and segment of the first.
    pub a: (usize, usize),
    /// Path and segment of the second.
    pub b: (usize, usize),
    /// Where they cross, mm.
    pub at_mm: DVec2,
}

/// The proper crossings among `paths` (touching is not crossing, nor are
/// a path's neighbouring segments). Segments are swept in order of their
/// left ends, so only those whose spans overlap in `x` are compared.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, crossings};
/// let line = |a: DVec2, b: DVec2| CurvePath { points_mm: vec![a, b], closed: false };
/// let plus = [line(DVec2::new(-1.0, 0.0), DVec2::X), line(DVec2::new(0.0, -1.0), DVec2::Y)];
/// assert_eq!(crossings(&plus).len(), 1);
/// let tee = [line(DVec2::new(-1.0, 0.0), DVec2::X), line(DVec2::ZERO, DVec2::Y)];
/// assert!(crossings(&tee).is_empty(), "a path ending on another is a junction");
/// ```
pub fn crossings(paths: &[CurvePath]) -> Vec<Crossing> {
    let mut segments: Vec<(usize, usize, DVec2, DVec2)> = Vec::new();
    for (p, path) in paths.iter().enumerate() {
        let n = path.points_mm.len();
        let count = if path.closed && n > 2 { n } else { n.saturating_sub(1) };
        for s in 0..count {
            segments.push((p, s, path.points_mm[s], path.points_mm[(s + 1) % n]));
        }
    }
    segments.sort_by(|x, y| x.2.x.min(x.3.x).total_cmp(&y.2.x.min(y.3.x)));
    let mut found = Vec::new();
    for (k, &(p, s, a, b)) in segments.iter().enumerate() {
        let right = a.x.max(b.x);
        for &(q, t, c, d) in &segments[k + 1..] {
            if c.x.min(d.x) > right {
                break;
            }
            if let Some(at_mm) = proper_crossing(a, b, c, d) {
                found.push(Crossing { a: (p, s), b: (q, t), at_mm });
            }
        }
    }
    found
}

/// Where segments `a`–`b` and `c`–`d` pass through each other, if they do.
fn proper_crossing(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Option<DVec2> {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2, d3, d4) = (side(c, d, a), side(c, d, b), side(a, b, c), side(a, b, d));
    (d1 * d2 < 0.0 && d3 * d4 < 0.0).then(|| a + (b - a) * (d1 / (d1 - d2)))
}

/// `paths` with every crossing cut: at each, the shorter path (a path that
/// crosses one of `fixed`, which are never cut, is the one cut) is broken,
/// and its two new ends drawn back `gap_mm` along it from the crossing.
/// Pieces shorter than `min_mm` go. Also how many cuts were made: the
/// synthesis's own count of crossings it could not avoid.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, crossings, cut_crossings};
/// let line = |a: DVec2, b: DVec2| CurvePath { points_mm: vec![a, b], closed: false };
/// let long = line(DVec2::new(-10.0, 0.0), DVec2::new(10.0, 0.0));
/// let short = line(DVec2::new(0.0, -4.0), DVec2::new(0.0, 4.0));
/// let (cut, cuts) = cut_crossings(vec![long.clone(), short], &[], 1.0, 0.5);
/// assert_eq!(cuts, 1);
/// assert!(crossings(&cut).is_empty());
/// assert_eq!(cut[0], long, "the longer path stays whole");
/// assert_eq!(cut[1].points_mm, vec![DVec2::new(0.0, -4.0), DVec2::new(0.0, -1.0)]);
/// assert_eq!(cut[2].points_mm, vec![DVec2::new(0.0, 1.0), DVec2::new(0.0, 4.0)]);
/// ```
pub fn cut_crossings(
    mut paths: Vec<CurvePath>,
    fixed: &[CurvePath],
    gap_mm: f64,
    min_mm: f64,
) -> (Vec<CurvePath>, usize) {
    let mut cuts = 0;
    for _ in 0..MAX_ROUNDS {
        let all: Vec<CurvePath> = paths.iter().chain(fixed).cloned().collect();
        let found = crossings(&all);
        if found.is_empty() {
            break;
        }
        let is_fixed = |p: usize| p >= paths.len();
        let lengths: Vec<f64> = paths.iter().map(CurvePath::length_mm).collect();
        // One cut per path a round: the indices of the others stay true.
        let mut cut_at: Vec<Option<(usize, DVec2)>> = vec![None; paths.len()];
        for c in &found {
            let cut = match (is_fixed(c.a.0), is_fixed(c.b.0)) {
                (true, true) => continue,
                (true, false) => c.b,
                (false, true) => c.a,
                _ if lengths[c.a.0] <= lengths[c.b.0] => c.a,
                _ => c.b,
            };
            cut_at[cut.0].get_or_insert((cut.1, c.at_mm));
        }
        cuts += cut_at.iter().flatten().count();
        let mut next = Vec::with_capacity(paths.len() + found.len());
        for (path, cut) in paths.into_iter().zip(cut_at) {
            match cut {
                None => next.push(path),
                Some((segment, at)) => next.extend(broken(&path, segment, at, gap_mm)),
            }
        }
        paths = next.into_iter().filter(|p| p.points_mm.len() >= 2 && p.length_mm() >= min_mm).collect();
    }
    (paths, cuts)
}

/// `path` broken at `at` on its segment `segment`, each side drawn back
/// `gap_mm` from there: two open paths, or one for a closed path.
fn broken(path: &CurvePath, segment: usize, at: DVec2, gap_mm: f64) -> Vec<CurvePath> {
    let points = &path.points_mm;
    let n = points.len();
    let open = |points_mm: Vec<DVec2>| CurvePath { points_mm, closed: false };
    if path.closed {
        // Around the loop from the crossing back to it, both ends drawn back.
        let around: Vec<DVec2> =
            std::iter::once(at).chain((1..=n).map(|k| points[(segment + k) % n])).chain([at]).collect();
        let mut back = trim_start(&around, gap_mm);
        back.reverse();
        let mut both = trim_start(&back, gap_mm);
        both.reverse();
        return vec![open(both)];
    }
    // Each side, walking away from the crossing.
    let before: Vec<DVec2> = std::iter::once(at).chain(points[..=segment].iter().rev().copied()).collect();
    let after: Vec<DVec2> = std::iter::once(at).chain(points[segment + 1..].iter().copied()).collect();
    let mut first = trim_start(&before, gap_mm);
    first.reverse();
    vec![open(first), open(trim_start(&after, gap_mm))]
}

/// `points` less their first `length_mm` of length; empty when shorter.
fn trim_start(points: &[DVec2], length_mm: f64) -> Vec<DVec2> {
    let mut left = length_mm;
    for k in 1..points.len() {
        let step = points[k - 1].distance(points[k]);
        if step > left {
            let start = points[k - 1] + (points[k] - points[k - 1]) * (left / step);
            return std::iter::once(start).chain(points[k..].iter().copied()).collect();
        }
        left -= step;
    }
    Vec::new()
}
