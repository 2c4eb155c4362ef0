//! Measures of a result that people judge by eye, computed from the output
//! alone: how periodic a sequence looks, how far geometry strays from its
//! curve. The solver never optimizes these directly; tests and the corpus
//! sweep use them to check it.

mod curves;
mod elements;

pub use curves::{
    BEND_STEP_MM, CURVATURE_BIN, CURVATURE_BINS, CurveStatistics, MEET_TOLERANCE_MM, ORIENTATION_BINS, coverage,
    curve_statistics, curve_statistics_within, histogram_distance, histogram_emd, histogram_emd_circular,
};
pub use elements::{ElementStatistics, TOUCH_MM, element_statistics};

use glam::DVec2;

use crate::curve::Curve;
use crate::geom::{Region, closest_on_segment};

/// The tightest turn of a polyline, as the smallest radius of the circle
/// through three points `step` apart along it (arc length, the polyline's
/// units). On a closed polyline the points wrap round; on an open one the
/// first and last `step` are left out. Straight stretches read as infinite.
///
/// A polyline drawn in steps of angle `θ` and length `l` reads about
/// `l / θ` where the three points straddle a vertex and `step` is under
/// `l`: measure with a step longer than the segments to read the radius
/// of the arc they draw.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::quality::tightest_turn;
/// // A circle of radius 10 in 360 steps, a quarter of it open.
/// let arc: Vec<DVec2> = (0..=90).map(|k| DVec2::from_angle((k as f64).to_radians()) * 10.0).collect();
/// // Within a hundredth: the points between vertices lie on chords.
/// assert!((tightest_turn(&arc, false, 1.0) - 10.0).abs() < 0.1);
/// let line = [DVec2::ZERO, DVec2::new(10.0, 0.0)];
/// assert_eq!(tightest_turn(&line, false, 1.0), f64::INFINITY);
/// ```
pub fn tightest_turn(points: &[DVec2], closed: bool, step: f64) -> f64 {
    if step.is_nan() || step <= 0.0 {
        return f64::INFINITY;
    }
    let at = curves::resample(points, closed, step);
    let n = at.len();
    let middles = if closed { 0..n } else { 1..n.saturating_sub(1) };
    middles
        .map(|k| {
            let (a, b, c) = (at[(k + n - 1) % n], at[k], at[(k + 1) % n]);
            // Circumradius: abc / (4 · area).
            let area2 = (b - a).perp_dot(c - a).abs();
            if area2 < 1e-12 { f64::INFINITY } else { a.distance(b) * b.distance(c) * c.distance(a) / (2.0 * area2) }
        })
        .fold(f64::INFINITY, f64::min)
}

/// Fraction of positions that must agree for a shift to count as a period.
pub const PERIOD_AGREEMENT: f64 = 0.9;

/// The shortest shift `p` under which `sequence` looks periodic: at least
/// [`PERIOD_AGREEMENT`] of the positions `i` with `i + p < n` have
/// `sequence[i] == sequence[i + p]`, over at least two positions. Returns the
/// length of the sequence when no shift qualifies.
///
/// Unlike the solver's autocorrelation (a soft, windowed similarity of
/// piece indices), this counts exact agreement of shape classes at every
/// shift, so a cycle of period 13 is seen as readily as one of period 2.
///
/// ```
/// use tracery_core::quality::near_period;
/// assert_eq!(near_period(&[1, 2, 3, 1, 2, 3, 1, 2, 3]), 3);
/// assert_eq!(near_period(&[1, 2, 3, 4, 5, 6]), 6);
/// ```
pub fn near_period(sequence: &[usize]) -> usize {
    let n = sequence.len();
    (1..n)
        .find(|&p| {
            let span = n - p;
            if span < 2 {
                return false;
            }
            let agree = (0..span).filter(|&i| sequence[i] == sequence[i + p]).count();
            agree as f64 >= PERIOD_AGREEMENT * span as f64
        })
        .unwrap_or(n)
}

/// Length of the longest run of consecutive elements that occurs twice in
/// `sequence` (the two occurrences may overlap).
///
/// ```
/// use tracery_core::quality::longest_repeat;
/// assert_eq!(longest_repeat(&[1, 2, 3, 9, 1, 2, 3]), 3);
/// assert_eq!(longest_repeat(&[1, 1, 1, 1]), 3);
/// assert_eq!(longest_repeat(&[1, 2, 3]), 0);
/// ```
pub fn longest_repeat(sequence: &[usize]) -> usize {
    // Longest common prefix of every pair of suffixes, by dynamic programming
    // over shifts: O(n²) time, O(1) memory, plenty for sequences of pieces.
    let n = sequence.len();
    let mut best = 0;
    for shift in 1..n {
        let mut run = 0;
        for i in 0..n - shift {
            if sequence[i] == sequence[i + shift] {
                run += 1;
                best = usize::max(best, run);
            } else {
                run = 0;
            }
        }
    }
    best
}

/// The largest distance from any vertex of `region` to `curve`, mm.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::curve::Curve;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::quality::max_distance_from;
/// let square = vec![DVec2::new(1.0, -2.0), DVec2::new(3.0, -2.0), DVec2::new(3.0, 4.0), DVec2::new(1.0, 4.0)];
/// let region = Region::new(vec![Polygon { outer: square, holes: vec![] }]);
/// assert!((max_distance_from(&region, &Curve::line(10.0).unwrap()) - 4.0).abs() < 1e-9);
/// ```
pub fn max_distance_from(region: &Region, curve: &Curve) -> f64 {
    // Every vertex against the curve's segments, exactly, but a vertex
    // stops looking as soon as one segment is within the largest distance
    // found so far: it cannot raise the maximum. Checking first the segment
    // nearest to the vertex before it along the ring makes that the usual
    // case, so a large pattern costs a few segments a vertex instead of all
    // of them (every vertex against every segment took 40 % of a corpus
    // sweep's time on dense loops).
    let segments: Vec<[DVec2; 2]> = curve.points().windows(2).map(|w| [w[0], w[1]]).collect();
    let distance = |p: DVec2, s: &[DVec2; 2]| p.distance(closest_on_segment(p, s[0], s[1]).1);
    let mut largest: f64 = 0.0;
    let mut hint = 0;
    for ring in region.rings() {
        for &p in ring {
            let Some(first) = segments.get(hint) else { return f64::INFINITY };
            let mut nearest = distance(p, first);
            if nearest <= largest {
                continue;
            }
            for (k, s) in segments.iter().enumerate() {
                let d = distance(p, s);
                if d < nearest {
                    (nearest, hint) = (d, k);
                    if nearest <= largest {
                        break;
                    }
                }
            }
            largest = largest.max(nearest);
        }
    }
    largest
}

/// The kink of the outline where it crosses each seam, degrees: at every
/// vertex lying on a seam line `u = s` (band space) whose neighbours sit on
/// either side of it, the turning angle there less the mean turning of its
/// two neighbours, so that a smoothly curving outline scores about zero and
/// a corner scores its angle. Where the turn there is the smaller of the
/// two, it is the kink: a corner of the design one vertex from the seam
/// (a fret's square corner, a stroke's tip) turns at the neighbour, not at
/// the seam, and scored half its angle there before (2026-12-04).
/// Returns the kink of each seam crossing.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::quality::seam_kinks_deg;
/// // A roof: flat, then a 30° bend exactly on the seam at u = 2.
/// let outer = vec![
///     DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 1.0 + 2.0 * 30f64.to_radians().tan()),
///     DVec2::new(3.0, 1.0 + 30f64.to_radians().tan()), DVec2::new(2.0, 1.0), DVec2::new(1.0, 1.0), DVec2::new(0.0, 1.0),
/// ];
/// let region = Region::new(vec![Polygon { outer, holes: vec![] }]);
/// let kinks = seam_kinks_deg(&region, &[2.0], 1e-9);
/// assert_eq!(kinks.len(), 1);
/// assert!((kinks[0] - 30.0).abs() < 1e-6);
/// // A straight edge across the seam, with a square corner one vertex on.
/// let outer = vec![
///     DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 2.0), DVec2::new(3.0, 2.0),
///     DVec2::new(3.0, 1.0), DVec2::new(2.0, 1.0), DVec2::new(1.0, 1.0), DVec2::new(0.0, 1.0),
/// ];
/// let region = Region::new(vec![Polygon { outer, holes: vec![] }]);
/// let kinks = seam_kinks_deg(&region, &[2.0], 1e-9);
/// assert_eq!(kinks.len(), 1);
/// assert!(kinks[0] < 1e-6, "{kinks:?}");
/// ```
pub fn seam_kinks_deg(region: &Region, seams_u: &[f64], tolerance: f64) -> Vec<f64> {
    let mut kinks = Vec::new();
    let mut sorted = seams_u.to_vec();
    sorted.sort_by(f64::total_cmp);
    // The seam nearest to `x`, if within the tolerance.
    let seam_at = |x: f64| {
        let k = sorted.partition_point(|&s| s < x);
        [k.checked_sub(1), Some(k)]
            .into_iter()
            .flatten()
            .filter_map(|k| sorted.get(k).copied())
            .find(|s| (x - s).abs() <= tolerance)
    };
    let turn = |a: DVec2, b: DVec2, c: DVec2| {
        let (d1, d2) = (b - a, c - b);
        d1.perp_dot(d2).atan2(d1.dot(d2))
    };
    for ring in region.rings() {
        let n = ring.len();
        if n < 5 {
            continue;
        }
        for i in 0..n {
            let at = |k: isize| ring[(i as isize + k).rem_euclid(n as isize) as usize];
            let (p, prev, next) = (at(0), at(-1), at(1));
            let Some(s) = seam_at(p.x) else { continue };
            if (prev.x - s) * (next.x - s) >= 0.0 {
                continue;
            }
            let here = turn(prev, p, next);
            let around = 0.5 * (turn(at(-2), prev, p) + turn(p, next, at(2)));
            kinks.push((here - around).abs().min(here.abs()).to_degrees());
        }
    }
    kinks
}

/// How different two patterns look, from 0 (the same) to 1 (nowhere the
/// same): the share of the length along which the two show different
/// shapes. Each pattern is its pieces in order, as (shape class, width);
/// both are scaled to the same length and compared at 720 evenly spaced
/// places. On a loop (`closed`) the second is also turned all the way
/// round and the smallest share is kept, so a rotated copy counts as the
/// same pattern.
///
/// ```
/// use tracery_core::quality::distinctness;
/// let a = [(0, 1.0), (1, 1.0), (0, 1.0), (1, 1.0)];
/// let b = [(1, 1.0), (0, 1.0), (1, 1.0), (0, 1.0)];
/// assert_eq!(distinctness(&a, &a, false), 0.0);
/// assert_eq!(distinctness(&a, &b, false), 1.0);
/// assert_eq!(distinctness(&a, &b, true), 0.0);
/// ```
pub fn distinctness(a: &[(usize, f64)], b: &[(usize, f64)], closed: bool) -> f64 {
    const SAMPLES: usize = 720;
    let sample = |pieces: &[(usize, f64)]| -> Vec<usize> {
        let total: f64 = pieces.iter().map(|p| p.1).sum();
        let mut out = Vec::with_capacity(SAMPLES);
        let (mut k, mut end) = (0, pieces.first().map_or(0.0, |p| p.1));
        for s in 0..SAMPLES {
            let at = (s as f64 + 0.5) / SAMPLES as f64 * total;
            while at > end && k + 1 < pieces.len() {
                k += 1;
                end += pieces[k].1;
            }
            out.push(pieces.get(k).map_or(usize::MAX, |p| p.0));
        }
        out
    };
    let (sa, sb) = (sample(a), sample(b));
    let differing = |shift: usize| (0..SAMPLES).filter(|&i| sa[i] != sb[(i + shift) % SAMPLES]).count();
    let fewest = if closed { (0..SAMPLES).map(differing).min().unwrap_or(0) } else { differing(0) };
    fewest as f64 / SAMPLES as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Polygon;
    use crate::random::SplitMix64;

    /// The early stop finds the same largest distance as every vertex
    /// against every segment, on rings that wander about a wave.
    #[test]
    fn the_largest_distance_is_the_one_every_segment_gives() {
        let curve = Curve::wave(120.0).unwrap();
        let mut random = SplitMix64::new(7);
        for _ in 0..20 {
            let ring: Vec<DVec2> = (0..400)
                .map(|k| {
                    let u = 120.0 * k as f64 / 400.0;
                    curve.map(u, 6.0 * (random.next_unit() - 0.5)) + DVec2::new(0.0, 2.0 * random.next_unit())
                })
                .collect();
            let region = Region::new(vec![Polygon { outer: ring, holes: vec![] }]);
            let plain = region.rings().flatten().map(|&p| curve.distance(p)).fold(0.0, f64::max);
            assert_eq!(max_distance_from(&region, &curve), plain);
        }
    }
}
