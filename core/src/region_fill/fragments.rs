//! Stray fragments (section 4.4 of the curve-texture paper asks for clean
//! output): short spurs that stick out of a junction and short loose bits
//! that the exemplar never has. What counts as short is learned from the
//! exemplar itself: its shortest spur and its shortest loose path away from
//! its edges, where its drawing was cut off.

use glam::DVec2;
use rustc_hash::FxHashMap;

use super::CurvePath;
use crate::geom::Rect;

/// What the exemplar's paths look like at their loose ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FragmentLimits {
    /// Spurs (from a junction to a free end) shorter than this go, mm.
    pub min_spur_mm: f64,
    /// Loose paths (free at both ends, or closed) shorter than this go, mm.
    pub min_loose_mm: f64,
}

/// A point as a key, to the nanometre.
pub(super) type Place = (i64, i64);

/// Points are one endpoint when they round to the same nanometre: paths
/// from one graph share their junction samples exactly.
pub(super) fn key(p: DVec2) -> Place {
    ((p.x * 1e6).round() as i64, (p.y * 1e6).round() as i64)
}

/// How many path ends meet at each endpoint.
pub(super) fn degrees(paths: &[CurvePath]) -> FxHashMap<Place, usize> {
    let mut degree: FxHashMap<(i64, i64), usize> = FxHashMap::default();
    for p in paths.iter().filter(|p| !p.closed && p.points_mm.len() >= 2) {
        *degree.entry(key(p.points_mm[0])).or_default() += 1;
        *degree.entry(key(p.points_mm[p.points_mm.len() - 1])).or_default() += 1;
    }
    degree
}

impl FragmentLimits {
    /// Learned from the exemplar's `paths` (as the graph gives them: cut at
    /// junctions). Only free ends farther than `margin_mm` inside the
    /// exemplar's bounds count: nearer ones are where the drawing stops.
    /// Half the shortest of each kind; where the exemplar has none, a spur
    /// or a loose bit shorter than `fallback_mm`.
    pub fn learn(paths: &[CurvePath], margin_mm: f64, fallback_mm: f64) -> FragmentLimits {
        let bounds = Rect::from_points(paths.iter().flat_map(|p| p.points_mm.iter().copied()));
        let inner = |p: DVec2| {
            bounds.is_some_and(|b| {
                p.x > b.min.x + margin_mm
                    && p.x < b.max.x - margin_mm
                    && p.y > b.min.y + margin_mm
                    && p.y < b.max.y - margin_mm
            })
        };
        let degree = degrees(paths);
        let (mut spur, mut loose) = (f64::INFINITY, f64::INFINITY);
        for p in paths {
            let length = p.length_mm();
            if p.closed {
                loose = loose.min(length);
                continue;
            }
            let (Some(&a), Some(&b)) = (p.points_mm.first(), p.points_mm.last()) else { continue };
            let (da, db) = (degree[&key(a)], degree[&key(b)]);
            match (da == 1, db == 1) {
                (true, true) if inner(a) && inner(b) => loose = loose.min(length),
                (true, false) if inner(a) => spur = spur.min(length),
                (false, true) if inner(b) => spur = spur.min(length),
                _ => {}
            }
        }
        let half = |x: f64| if x.is_finite() { 0.5 * x } else { fallback_mm };
        FragmentLimits { min_spur_mm: half(spur), min_loose_mm: half(loose) }
    }

    /// The limits, each at most `max_mm`. An exemplar drawn as one large
    /// outline (an ornament's filled shape) would otherwise ask for loose
    /// bits hundreds of millimetres long, and the fill would keep nothing.
    ///
    /// ```
    /// use tracery_core::region_fill::FragmentLimits;
    /// let l = FragmentLimits { min_spur_mm: 6.0, min_loose_mm: 390.0 }.capped(37.0);
    /// assert_eq!((l.min_spur_mm, l.min_loose_mm), (6.0, 37.0));
    /// ```
    pub fn capped(self, max_mm: f64) -> FragmentLimits {
        FragmentLimits { min_spur_mm: self.min_spur_mm.min(max_mm), min_loose_mm: self.min_loose_mm.min(max_mm) }
    }

    /// `paths` without spurs and loose bits shorter than the limits, the
    /// paths left meeting two at a point joined into one. An end where
    /// `anchored` is true (near the edge of the synthesized area, where the
    /// pattern goes on past the region) is never free. Repeats until
    /// nothing changes, since removing a spur can leave another.
    pub fn remove_from(&self, mut paths: Vec<CurvePath>, anchored: impl Fn(DVec2) -> bool) -> Vec<CurvePath> {
        loop {
            let degree = degrees(&paths);
            let free = |p: DVec2| degree[&key(p)] == 1 && !anchored(p);
            let before = paths.len();
            paths.retain(|p| {
                let length = p.length_mm();
                if p.closed {
                    return length >= self.min_loose_mm;
                }
                let (a, b) = (p.points_mm[0], p.points_mm[p.points_mm.len() - 1]);
                match (free(a), free(b)) {
                    (true, true) => length >= self.min_loose_mm,
                    (true, false) | (false, true) => length >= self.min_spur_mm,
                    _ => true,
                }
            });
            paths = join_at_twos(paths);
            if paths.len() == before {
                return paths;
            }
        }
    }
}

/// Paths that meet two at a point (where a spur was removed) joined into
/// one; a path that comes back to its own start is closed.
fn join_at_twos(mut paths: Vec<CurvePath>) -> Vec<CurvePath> {
    loop {
        let degree = degrees(&paths);
        let mut at: FxHashMap<(i64, i64), Vec<usize>> = FxHashMap::default();
        for (i, p) in paths.iter().enumerate().filter(|(_, p)| !p.closed && p.points_mm.len() >= 2) {
            for end in [p.points_mm[0], p.points_mm[p.points_mm.len() - 1]] {
                if degree[&key(end)] == 2 {
                    at.entry(key(end)).or_default().push(i);
                }
            }
        }
        let Some((point, pair)) = at.into_iter().find(|(_, v)| v.len() == 2) else {
            return paths;
        };
        let (i, j) = (pair[0], pair[1]);
        if i == j {
            // Both ends of one path meet each other only: it closes.
            paths[i].points_mm.pop();
            paths[i].closed = true;
            continue;
        }
        let mut second = paths.swap_remove(j.max(i));
        let mut first = paths.swap_remove(j.min(i));
        if key(first.points_mm[0]) == point {
            first.points_mm.reverse();
        }
        if key(second.points_mm[second.points_mm.len() - 1]) == point {
            second.points_mm.reverse();
        }
        first.points_mm.extend(second.points_mm.into_iter().skip(1));
        paths.push(first);
    }
}
