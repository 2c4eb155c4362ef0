//! Measures of a curve pattern (a region fill, or its exemplar) from its
//! polylines alone, by geometry: where paths end, meet and cross, how they
//! bend and which way they run, and how much of a region they reach. None
//! of this reads the synthesis's sample graph, and the synthesis optimizes
//! none of it; tests and `docs/quality.md` compare a fill with its exemplar
//! by these.

use glam::DVec2;
use rustc_hash::FxHashMap;

use crate::geom::{Rect, Region, closest_on_segment};

/// Points nearer than this are one place: a path ending on another meets it, mm.
pub const MEET_TOLERANCE_MM: f64 = 0.05;

/// Spacing at which paths are resampled to measure bending, mm.
pub const BEND_STEP_MM: f64 = 0.5;

/// Bins of the curvature histogram, each [`CURVATURE_BIN`] wide (1/mm), the last open.
pub const CURVATURE_BINS: usize = 40;

/// Width of a curvature bin, 1/mm.
pub const CURVATURE_BIN: f64 = 0.02;

/// Bins of the orientation histogram over half a turn (a path runs both ways).
pub const ORIENTATION_BINS: usize = 36;

/// What a curve pattern is like, per length of curve so patterns of any
/// size compare.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CurveStatistics {
    /// Length of all paths, mm.
    pub length_mm: f64,
    /// Free ends (touching nothing) per 100 mm of curve.
    pub ends_per_100mm: f64,
    /// Junctions (an end on another path, or ends meeting three or more at
    /// a place) per 100 mm of curve.
    pub junctions_per_100mm: f64,
    /// Proper crossings (two paths passing through each other) per 100 mm.
    pub crossings_per_100mm: f64,
    /// Share of the length in each curvature bin.
    pub curvature: Vec<f64>,
    /// Share of the length in each orientation bin (0 to π).
    pub orientation: Vec<f64>,
}

/// Half the sum of absolute differences of two histograms of shares: 0
/// when alike, 1 when they share nothing.
///
/// ```
/// use tracery_core::quality::histogram_distance;
/// assert_eq!(histogram_distance(&[0.5, 0.5], &[0.5, 0.5]), 0.0);
/// assert_eq!(histogram_distance(&[1.0, 0.0], &[0.0, 1.0]), 1.0);
/// ```
pub fn histogram_distance(a: &[f64], b: &[f64]) -> f64 {
    0.5 * a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum::<f64>()
}

/// The earth mover's distance between two histograms of shares over
/// ordered bins `bin_width` wide: how far, in the bins' unit, the length
/// of one must move to make the other. Unlike bin-by-bin differences it
/// does not jump when a pattern's one curvature sits on a bin's edge.
///
/// ```
/// use tracery_core::quality::histogram_emd;
/// assert_eq!(histogram_emd(&[1.0, 0.0, 0.0], &[1.0, 0.0, 0.0], 0.1), 0.0);
/// assert!((histogram_emd(&[1.0, 0.0, 0.0], &[0.0, 0.0, 1.0], 0.1) - 0.2).abs() < 1e-12);
/// ```
pub fn histogram_emd(a: &[f64], b: &[f64], bin_width: f64) -> f64 {
    let (mut carried, mut total) = (0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        carried += x - y;
        total += carried.abs();
    }
    total * bin_width
}

/// [`histogram_emd`] for bins round a circle (directions), where the last
/// bin is next to the first: the cumulative differences less their median,
/// which is the cheapest way round.
///
/// ```
/// use tracery_core::quality::histogram_emd_circular;
/// // All in the last bin against all in the first: one bin apart round the circle.
/// assert!((histogram_emd_circular(&[1.0, 0.0, 0.0, 0.0], &[0.0, 0.0, 0.0, 1.0], 5.0) - 5.0).abs() < 1e-12);
/// ```
pub fn histogram_emd_circular(a: &[f64], b: &[f64], bin_width: f64) -> f64 {
    let mut carried = 0.0;
    let mut cumulative: Vec<f64> = a
        .iter()
        .zip(b)
        .map(|(x, y)| {
            carried += x - y;
            carried
        })
        .collect();
    let mut sorted = cumulative.clone();
    sorted.sort_by(f64::total_cmp);
    let median = sorted.get(sorted.len() / 2).copied().unwrap_or(0.0);
    cumulative.iter_mut().map(|c| (*c - median).abs()).sum::<f64>() * bin_width
}

/// A segment of a path: which path, and its ends.
struct Segment {
    path: usize,
    index: usize,
    a: DVec2,
    b: DVec2,
}

/// Segments on a grid of square cells, for finding those near a point.
struct SegmentGrid {
    cell: f64,
    cells: FxHashMap<(i64, i64), Vec<usize>>,
    segments: Vec<Segment>,
}

impl SegmentGrid {
    fn new(paths: &[(Vec<DVec2>, bool)], cell: f64) -> SegmentGrid {
        let mut segments = Vec::new();
        for (path, (points, closed)) in paths.iter().enumerate() {
            let n = points.len();
            let count = if *closed && n > 2 { n } else { n.saturating_sub(1) };
            for index in 0..count {
                segments.push(Segment { path, index, a: points[index], b: points[(index + 1) % n] });
            }
        }
        let mut cells: FxHashMap<(i64, i64), Vec<usize>> = FxHashMap::default();
        let of = |p: DVec2| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
        for (s, seg) in segments.iter().enumerate() {
            let (lo, hi) = (of(seg.a.min(seg.b)), of(seg.a.max(seg.b)));
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    cells.entry((x, y)).or_default().push(s);
                }
            }
        }
        SegmentGrid { cell, cells, segments }
    }

    /// Segments whose cells lie within `reach` of `p` (a superset of those that do).
    fn near(&self, p: DVec2, reach: f64) -> impl Iterator<Item = usize> + '_ {
        let of = |q: DVec2| ((q.x / self.cell).floor() as i64, (q.y / self.cell).floor() as i64);
        let (lo, hi) = (of(p - DVec2::splat(reach)), of(p + DVec2::splat(reach)));
        let mut found: Vec<usize> = Vec::new();
        for x in lo.0..=hi.0 {
            for y in lo.1..=hi.1 {
                found.extend(self.cells.get(&(x, y)).into_iter().flatten().copied());
            }
        }
        found.sort_unstable();
        found.dedup();
        found.into_iter()
    }
}

/// Whether segments `ab` and `cd` cross properly (each one's ends strictly
/// on either side of the other).
fn cross_properly(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2, d3, d4) = (side(c, d, a), side(c, d, b), side(a, b, c), side(a, b, d));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

/// The statistics of `paths` (polylines, each open or closed), mm.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::quality::curve_statistics;
/// // A T: the stem ends on the bar; three free ends, one junction, 30 mm.
/// let bar = (vec![DVec2::new(-10.0, 0.0), DVec2::new(10.0, 0.0)], false);
/// let stem = (vec![DVec2::new(0.0, 0.0), DVec2::new(0.0, -10.0)], false);
/// let s = curve_statistics(&[bar, stem]);
/// assert!((s.length_mm - 30.0).abs() < 1e-9);
/// assert!((s.ends_per_100mm - 300.0 / 30.0).abs() < 1e-9);
/// assert!((s.junctions_per_100mm - 100.0 / 30.0).abs() < 1e-9);
/// assert_eq!(s.crossings_per_100mm, 0.0);
/// ```
pub fn curve_statistics(paths: &[(Vec<DVec2>, bool)]) -> CurveStatistics {
    statistics(paths, &|_| true)
}

/// [`curve_statistics`] counting only ends and junctions farther than
/// `margin_mm` inside `bounds` (where a drawing or a fill was cut off,
/// ends are the cut's, not the pattern's); the length still counts all.
pub fn curve_statistics_within(paths: &[(Vec<DVec2>, bool)], bounds: &Rect, margin_mm: f64) -> CurveStatistics {
    let inner = bounds.inflate(-margin_mm);
    let mut s = statistics(paths, &|p| p.cmpgt(inner.min).all() && p.cmplt(inner.max).all());
    // Per length of the inner part, which is where the counted places are.
    let share = (inner.width().max(0.0) * inner.height().max(0.0)) / (bounds.width() * bounds.height()).max(1e-12);
    if share > 0.0 {
        s.ends_per_100mm /= share;
        s.junctions_per_100mm /= share;
    }
    s
}

fn statistics(paths: &[(Vec<DVec2>, bool)], counted: &dyn Fn(DVec2) -> bool) -> CurveStatistics {
    let grid = SegmentGrid::new(paths, 2.0);
    let length_mm: f64 = grid.segments.iter().map(|s| s.a.distance(s.b)).sum();
    if length_mm <= 0.0 {
        return CurveStatistics::default();
    }
    // Ends: each open path's two ends. An end touching another path's
    // interior is a T-junction; ends meeting at one place are counted
    // together there.
    let mut places: Vec<(DVec2, usize, bool)> = Vec::new(); // (where, ends there, touches a path's interior)
    for (path, (points, closed)) in paths.iter().enumerate() {
        if *closed || points.len() < 2 {
            continue;
        }
        for (k, end) in [(0, points[0]), (points.len() - 1, points[points.len() - 1])] {
            // Touching another path away from that path's own ends (ends
            // meeting are counted by place below).
            let touches = grid.near(end, MEET_TOLERANCE_MM).any(|s| {
                let seg = &grid.segments[s];
                let own_end = seg.path == path && (seg.index == k || seg.index + 1 == k);
                let (other, other_closed) = (&paths[seg.path].0, paths[seg.path].1);
                let near = closest_on_segment(end, seg.a, seg.b).1;
                let at_its_end = !other_closed
                    && (near.distance(other[0]) < MEET_TOLERANCE_MM
                        || near.distance(other[other.len() - 1]) < MEET_TOLERANCE_MM);
                !own_end && !at_its_end && near.distance(end) < MEET_TOLERANCE_MM
            });
            match places.iter_mut().find(|(p, _, _)| p.distance(end) < MEET_TOLERANCE_MM) {
                Some(place) => {
                    place.1 += 1;
                    place.2 |= touches;
                }
                None => places.push((end, 1, touches)),
            }
        }
    }
    let (mut ends, mut junctions) = (0usize, 0usize);
    for (at, count, touches) in &places {
        if !counted(*at) {
            continue;
        }
        match (count, touches) {
            (1, false) => ends += 1,
            (2, false) => {} // two paths continuing each other
            _ => junctions += 1,
        }
    }
    let mut crossings = 0usize;
    for (s, seg) in grid.segments.iter().enumerate() {
        let reach = 0.5 * seg.a.distance(seg.b);
        for t in grid.near(0.5 * (seg.a + seg.b), reach) {
            let other = &grid.segments[t];
            if t > s && cross_properly(seg.a, seg.b, other.a, other.b) {
                crossings += 1;
            }
        }
    }
    let per_100 = |n: usize| 100.0 * n as f64 / length_mm;
    let (curvature, orientation) = bends_and_directions(paths);
    CurveStatistics {
        length_mm,
        ends_per_100mm: per_100(ends),
        junctions_per_100mm: per_100(junctions),
        crossings_per_100mm: per_100(crossings),
        curvature,
        orientation,
    }
}

/// The curvature and orientation histograms, by length, from each path
/// resampled every [`BEND_STEP_MM`].
fn bends_and_directions(paths: &[(Vec<DVec2>, bool)]) -> (Vec<f64>, Vec<f64>) {
    let (mut curvature, mut orientation) = (vec![0.0; CURVATURE_BINS], vec![0.0; ORIENTATION_BINS]);
    for (points, closed) in paths {
        let resampled = resample(points, *closed, BEND_STEP_MM);
        let n = resampled.len();
        for i in 1..n {
            let d = resampled[i] - resampled[i - 1];
            let angle = d.y.atan2(d.x).rem_euclid(std::f64::consts::PI);
            let bin = ((angle / std::f64::consts::PI * ORIENTATION_BINS as f64) as usize).min(ORIENTATION_BINS - 1);
            orientation[bin] += d.length();
        }
        for i in 1..n.saturating_sub(1) {
            let (u, v) = (resampled[i] - resampled[i - 1], resampled[i + 1] - resampled[i]);
            let kappa = u.angle_to(v).abs() / BEND_STEP_MM;
            let bin = ((kappa / CURVATURE_BIN) as usize).min(CURVATURE_BINS - 1);
            curvature[bin] += BEND_STEP_MM;
        }
    }
    let normalize = |h: &mut [f64]| {
        let total: f64 = h.iter().sum();
        if total > 0.0 {
            h.iter_mut().for_each(|x| *x /= total);
        }
    };
    normalize(&mut curvature);
    normalize(&mut orientation);
    (curvature, orientation)
}

/// Points every `step` along a polyline (closed: back to its start).
pub(super) fn resample(points: &[DVec2], closed: bool, step: f64) -> Vec<DVec2> {
    let mut chain: Vec<DVec2> = points.to_vec();
    if closed && let Some(&first) = points.first() {
        chain.push(first);
    }
    let mut out = Vec::new();
    let mut carried = 0.0;
    for w in chain.windows(2) {
        let length = w[0].distance(w[1]);
        let mut at = carried;
        while at <= length {
            out.push(w[0] + (w[1] - w[0]) * (at / length.max(1e-12)));
            at += step;
        }
        carried = at - length;
    }
    out
}

/// The share of `region` within `reach_mm` of some path, on a grid of
/// points `reach_mm / 2` apart: 1 when no part of the region is farther
/// than `reach_mm` from the pattern.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::quality::coverage;
/// let square = Region::new(vec![Polygon {
///     outer: vec![DVec2::ZERO, DVec2::new(10.0, 0.0), DVec2::new(10.0, 10.0), DVec2::new(0.0, 10.0)],
///     holes: vec![],
/// }]);
/// let middle = (vec![DVec2::new(0.0, 5.0), DVec2::new(10.0, 5.0)], false);
/// assert!(coverage(&[middle.clone()], &square, 6.0) > 0.99);
/// assert!((coverage(&[middle], &square, 2.5) - 0.5).abs() < 0.1);
/// ```
pub fn coverage(paths: &[(Vec<DVec2>, bool)], region: &Region, reach_mm: f64) -> f64 {
    let Some(bounds) = region.bounds() else { return 0.0 };
    let grid = SegmentGrid::new(paths, reach_mm.max(0.1));
    let step = 0.5 * reach_mm;
    let (mut inside, mut reached) = (0usize, 0usize);
    let Rect { min, max } = bounds;
    let mut y = min.y + 0.5 * step;
    while y < max.y {
        let mut x = min.x + 0.5 * step;
        while x < max.x {
            let p = DVec2::new(x, y);
            if region.contains(p) {
                inside += 1;
                let near = grid.near(p, reach_mm).any(|s| {
                    let seg = &grid.segments[s];
                    closest_on_segment(p, seg.a, seg.b).1.distance(p) <= reach_mm
                });
                reached += usize::from(near);
            }
            x += step;
        }
        y += step;
    }
    if inside == 0 { 0.0 } else { reached as f64 / inside as f64 }
}
