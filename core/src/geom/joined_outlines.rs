//! Outlines that meet along shared runs, made into a clean region without
//! a boolean: where two outlines run along the same line between the same
//! two points in opposite directions (the two sides of a cut), they are
//! joined there.
//!
//! A union of the outlines gives the same region, but on a dense pattern
//! it is most of a stage's time (28–38 of 36–55 ms for the mapping along a
//! curve of 55 k vertices) and changes almost nothing: stitching and mapping
//! keep outlines apart but at their cuts, where both sides have the same
//! points to the last bit. Where joined outlines cross or touch, only the
//! polygons they belong to go through a union; anything else this cannot
//! vouch for (cuts whose sides do not meet exactly, a part with two outer
//! outlines) is left to a union of the whole.

use glam::DVec2;
use rustc_hash::FxHashMap;

use super::{Polygon, Region, meeting_rings, signed_area, union};
use crate::disjoint_sets::DisjointSets;

/// One outline: the polygon it came from, its points, and for each point
/// the cut line it lies on, if any. Points on one line in a row make a run.
#[derive(Clone, Debug)]
pub(crate) struct Outline {
    pub polygon: usize,
    pub points: Vec<DVec2>,
    pub lines: Vec<Option<u32>>,
}

/// A point's exact bits: the key two runs' ends are matched by.
type PointKey = (u64, u64);

/// A maximal run of an outline's points on one line: indices `first` and
/// `last` of outline `ring`, whose points are its two ends.
#[derive(Clone, Copy, Debug)]
struct Run {
    ring: usize,
    first: usize,
    last: usize,
}

/// The region made of the outlines `rings` (from `polygons` clean, disjoint
/// polygons), each run joined to the run that has the same two end points
/// in the other order, with the polygons whose outlines then cross or
/// touch resolved by a union of just those. `None` where joining cannot
/// vouch for the result: a component with more or fewer than one outer
/// ring, or joins that do not fit together. The caller then takes the
/// union of the whole.
///
/// Outlines keep their orientation when the sum of their areas is
/// positive, and are all reversed when it is negative (a mirroring map).
///
/// `ends` gives the `x` of a band's two ends where they are a loop's
/// closing seam, which is joined later by the exact bits of its points:
/// the polygons reaching either end then go through a union together or
/// not at all, so that its grid rounds both sides' points alike.
pub(crate) fn joined_without_union(polygons: usize, rings: &[Outline], ends: Option<[f64; 2]>) -> Option<Region> {
    if rings.iter().any(|r| r.points.len() < 3 || r.lines.len() != r.points.len() || r.polygon >= polygons) {
        return None;
    }
    let mut offset = Vec::with_capacity(rings.len() + 1);
    offset.push(0);
    for ring in rings {
        offset.push(offset.last().copied().unwrap_or(0) + ring.points.len());
    }
    let total = *offset.last()?;
    let ring_of: Vec<usize> = (0..rings.len()).flat_map(|r| std::iter::repeat_n(r, rings[r].points.len())).collect();
    let mut next: Vec<usize> =
        (0..total).map(|g| if g + 1 == offset[ring_of[g] + 1] { offset[ring_of[g]] } else { g + 1 }).collect();
    let mut dropped = vec![false; total];
    let mut groups = DisjointSets::new(polygons);

    let runs = runs(rings)?;
    if !runs.is_empty() {
        let point = |run: &Run, i: usize| rings[run.ring].points[i];
        let key = |p: DVec2| -> PointKey { (p.x.to_bits(), p.y.to_bits()) };
        let mut by_ends: FxHashMap<(PointKey, PointKey), usize> = FxHashMap::default();
        for (k, run) in runs.iter().enumerate() {
            if by_ends.insert((key(point(run, run.first)), key(point(run, run.last))), k).is_some() {
                return None;
            }
        }
        let mut used = vec![false; runs.len()];
        let mut changed = vec![false; total];
        let mut kept = Vec::new();
        for (k, a) in runs.iter().enumerate() {
            // The other side runs the other way: from this run's last point to its first.
            let Some(&m) = by_ends.get(&(key(point(a, a.last)), key(point(a, a.first)))) else {
                continue;
            };
            if used[k] || used[m] || m == k {
                continue;
            }
            (used[k], used[m]) = (true, true);
            let b = &runs[m];
            let (na, nb) = (rings[a.ring].points.len(), rings[b.ring].points.len());
            let (ga, gb) = (offset[a.ring], offset[b.ring]);
            // This run's inner points and the whole other run go; the
            // outline comes in along the other side and leaves along this
            // one, at the points both runs share.
            let mut i = (a.first + 1) % na;
            while i != a.last {
                dropped[ga + i] = true;
                i = (i + 1) % na;
            }
            let mut i = b.first;
            loop {
                dropped[gb + i] = true;
                if i == b.last {
                    break;
                }
                i = (i + 1) % nb;
            }
            let (after_b, before_b) = (gb + (b.last + 1) % nb, gb + (b.first + nb - 1) % nb);
            let (a_first, a_last) = (ga + a.first, ga + a.last);
            for from in [a_first, before_b] {
                if std::mem::replace(&mut changed[from], true) {
                    return None;
                }
            }
            next[a_first] = after_b;
            next[before_b] = a_last;
            kept.extend([a_first, a_last, after_b, before_b]);
            groups.join(rings[a.ring].polygon, rings[b.ring].polygon);
        }
        if kept.iter().any(|&g| dropped[g]) {
            return None;
        }
    }

    // The outlines, followed from every vertex still in one.
    let mut visited = vec![false; total];
    let mut traced: Vec<(usize, Vec<DVec2>)> = Vec::new();
    for start in 0..total {
        if dropped[start] || visited[start] {
            continue;
        }
        let mut ring = Vec::new();
        let mut g = start;
        loop {
            if dropped[g] || visited[g] {
                return None;
            }
            visited[g] = true;
            let (r, local) = (ring_of[g], g - offset[ring_of[g]]);
            let p = rings[r].points[local];
            if ring.last() != Some(&p) {
                ring.push(p);
            }
            g = next[g];
            if g == start {
                break;
            }
        }
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        let ring = without_straight_points(ring);
        if ring.len() < 3 {
            return None;
        }
        traced.push((groups.find(rings[ring_of[start]].polygon), ring));
    }

    // Counter-clockwise outer rings, as the union gives them.
    let areas: Vec<f64> = traced.iter().map(|(_, ring)| signed_area(ring)).collect();
    let sum: f64 = areas.iter().sum();
    if !(sum.is_finite() && sum != 0.0) {
        return None;
    }
    let mirrored = sum < 0.0;
    // One component per group, so one outer ring each.
    let mut polygon_of_group: FxHashMap<usize, usize> = FxHashMap::default();
    let mut polygons: Vec<Polygon> = Vec::new();
    let mut holes: Vec<(usize, Vec<DVec2>)> = Vec::new();
    for ((group, mut ring), area) in traced.into_iter().zip(areas) {
        let area = if mirrored { -area } else { area };
        if mirrored {
            ring.reverse();
        }
        if area > 0.0 {
            if polygon_of_group.insert(group, polygons.len()).is_some() {
                return None;
            }
            polygons.push(Polygon { outer: ring, holes: Vec::new() });
        } else if area < 0.0 {
            holes.push((group, ring));
        } else {
            return None;
        }
    }
    for (group, ring) in holes {
        polygons[*polygon_of_group.get(&group)?].holes.push(ring);
    }
    Some(resolved(polygons, ends))
}

/// `polygons` as a clean region: those whose rings cross or touch (their
/// own or another's) resolved by a union of just them, the others kept
/// as they are. One bad seam on a pattern of thousands of rings costs a
/// union of the few polygons at it, not of the whole pattern. Where one
/// of them reaches one of the `ends` (see [`joined_without_union`]), every
/// polygon reaching an end goes into the union with it.
fn resolved(polygons: Vec<Polygon>, ends: Option<[f64; 2]>) -> Region {
    let all: Vec<&Vec<DVec2>> = polygons.iter().flat_map(Polygon::rings).collect();
    let meeting = meeting_rings(&all);
    if !meeting.contains(&true) {
        return Region { polygons };
    }
    let mut ring = 0;
    let (mut apart, mut crossed) = (Vec::new(), Vec::new());
    for polygon in polygons {
        let count = 1 + polygon.holes.len();
        let crosses = meeting[ring..ring + count].contains(&true);
        ring += count;
        if crosses { crossed.push(polygon) } else { apart.push(polygon) }
    }
    if let Some([a, b]) = ends {
        let reaches_end = |polygon: &Polygon| polygon.rings().flatten().any(|p| p.x == a || p.x == b);
        if crossed.iter().any(reaches_end) {
            let (at_ends, others): (Vec<Polygon>, Vec<Polygon>) = apart.into_iter().partition(reaches_end);
            crossed.extend(at_ends);
            apart = others;
        }
    }
    apart.extend(union(&[&Region::new(crossed)]).polygons);
    Region { polygons: apart }
}

/// Largest `|sin|` of the turn at a vertex that is taken as no turn: far
/// below any angle a mapping or a stitch makes, about where a union's
/// integer grid puts three points on one line.
const STRAIGHT_SINE: f64 = 1e-12;

/// `ring` without the vertices where it goes straight on (a cut's inner
/// points along the band's end, mapped onto one normal line), as a union
/// leaves it: points on a line carry no shape, and the meshes made from the
/// outline would hold them as slivers.
fn without_straight_points(ring: Vec<DVec2>) -> Vec<DVec2> {
    let n = ring.len();
    let straight = |a: DVec2, b: DVec2, c: DVec2| {
        let (ab, bc) = (b - a, c - b);
        ab.perp_dot(bc).abs() <= STRAIGHT_SINE * ab.length() * bc.length() && ab.dot(bc) > 0.0
    };
    let keep: Vec<bool> = (0..n).map(|i| !straight(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n])).collect();
    if keep.iter().all(|&k| k) {
        return ring;
    }
    ring.into_iter().zip(keep).filter_map(|(p, k)| k.then_some(p)).collect()
}

/// Every outline's maximal runs of two or more points on one line. `None`
/// for an outline lying wholly on one.
fn runs(rings: &[Outline]) -> Option<Vec<Run>> {
    let mut out = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        let (n, lines) = (ring.points.len(), &ring.lines);
        // Start after a point that ends a run (off every line, or on
        // another line than the next), so no run wraps past it.
        let off = (0..n).find(|&i| lines[i].is_none() || lines[i] != lines[(i + 1) % n])?;
        let mut k = 1;
        while k <= n {
            let first = (off + k) % n;
            let Some(line) = lines[first] else {
                k += 1;
                continue;
            };
            let mut last = first;
            while k < n && lines[(off + k + 1) % n] == Some(line) {
                k += 1;
                last = (off + k) % n;
            }
            if last != first {
                out.push(Run { ring: r, first, last });
            }
            k += 1;
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::refine_mapped_indexed;

    /// A band strip `[0, length] × [-1, 1]` with square holes, mapped onto a
    /// circle of circumference `length` (radius `length / 2π`).
    fn strip(length: f64, holes: usize) -> Region {
        let outer =
            vec![DVec2::new(0.0, -1.0), DVec2::new(length, -1.0), DVec2::new(length, 1.0), DVec2::new(0.0, 1.0)];
        let holes = (0..holes)
            .map(|k| {
                let x = (k as f64 + 0.25) * length / holes as f64;
                vec![DVec2::new(x, -0.5), DVec2::new(x, 0.5), DVec2::new(x + 0.5, 0.5), DVec2::new(x + 0.5, -0.5)]
            })
            .collect();
        Region::new(vec![Polygon { outer, holes }])
    }

    fn around(length: f64) -> impl Fn(DVec2) -> DVec2 {
        let radius = length / std::f64::consts::TAU;
        move |p: DVec2| {
            let u = if (p.x - length).abs() <= 1e-9 * length { 0.0 } else { p.x };
            let angle = u / radius;
            DVec2::new(angle.cos(), angle.sin()) * (radius + p.y)
        }
    }

    /// The outlines of `band` mapped by `map`, with the points from the
    /// band's start and end lines (`x = 0` and `x = length`) on lines 0 and 1.
    fn outlines(band: &Region, map: &dyn Fn(DVec2) -> DVec2, length: Option<f64>) -> Vec<Outline> {
        let mut out = Vec::new();
        for (p, polygon) in band.polygons.iter().enumerate() {
            for ring in polygon.rings() {
                let (points, origins) = refine_mapped_indexed(ring, map, 0.5, 1e-4);
                let mut lines = vec![None; points.len()];
                if let Some(length) = length {
                    for (q, &i) in ring.iter().zip(&origins) {
                        lines[i] = if q.x == 0.0 {
                            Some(0)
                        } else if (q.x - length).abs() <= 1e-9 * length {
                            Some(1)
                        } else {
                            None
                        };
                    }
                }
                out.push(Outline { polygon: p, points, lines });
            }
        }
        out
    }

    fn joined(band: &Region, map: &dyn Fn(DVec2) -> DVec2, length: Option<f64>) -> Option<Region> {
        joined_without_union(band.polygons.len(), &outlines(band, map, length), None)
    }

    #[test]
    fn a_strip_round_a_loop_closes_into_a_ring_with_its_holes() {
        let length = 40.0;
        let band = strip(length, 6);
        let region = joined(&band, &around(length), Some(length)).expect("joined");
        // One part, whose outline is the loop's outside; its inside and the six holes are holes.
        assert_eq!(region.polygons.len(), 1);
        assert_eq!(region.polygons[0].holes.len(), 7);
        assert!(region.sanity_check().is_ok(), "{:?}", region.sanity_check());
        // The same as the union, counted independently.
        let mapped = outlines(&band, &around(length), None);
        let union = crate::geom::union(&[&Region::new(vec![Polygon {
            outer: mapped[0].points.clone(),
            holes: mapped[1..].iter().map(|r| r.points.clone()).collect(),
        }])]);
        assert_eq!(union.polygons.len(), 1);
        assert_eq!(union.polygons[0].holes.len(), 7);
        assert!((union.area() - region.area()).abs() < 1e-6 * union.area());
    }

    #[test]
    fn an_open_band_keeps_its_polygons() {
        let band = strip(20.0, 3);
        let bend = |p: DVec2| DVec2::new(p.x, p.y + 0.01 * p.x * p.x);
        let region = joined(&band, &bend, None).expect("clean");
        assert_eq!(region.polygons.len(), 1);
        assert_eq!(region.polygons[0].holes.len(), 3);
    }

    /// The union of `band`'s polygons mapped by `map`, each as one polygon
    /// whatever its outlines do: what joining must come to.
    fn union_of_mapped(band: &Region, map: &dyn Fn(DVec2) -> DVec2) -> Region {
        let mapped = outlines(band, map, None);
        let polygons = (0..band.polygons.len())
            .map(|p| {
                let mut rings = mapped.iter().filter(|o| o.polygon == p).map(|o| o.points.clone());
                let outer = rings.next().unwrap_or_default();
                Polygon { outer, holes: rings.collect() }
            })
            .collect();
        crate::geom::union(&[&Region::new(polygons)])
    }

    /// Parts, holes and area of `region` equal `expected`'s.
    fn assert_same_region(region: &Region, expected: &Region) {
        assert!(region.sanity_check().is_ok(), "{:?}", region.sanity_check());
        let holes = |r: &Region| r.polygons.iter().map(|p| p.holes.len()).sum::<usize>();
        assert_eq!(region.polygons.len(), expected.polygons.len());
        assert_eq!(holes(region), holes(expected));
        assert!(
            (region.area() - expected.area()).abs() < 1e-6 * expected.area(),
            "{} {}",
            region.area(),
            expected.area()
        );
    }

    #[test]
    fn outlines_that_overlap_once_mapped_go_through_a_union() {
        // Longer than the loop: the band's end runs over its start.
        let band = strip(40.0, 2);
        let region = joined(&band, &around(30.0), Some(40.0)).expect("resolved by a union");
        assert_same_region(&region, &union_of_mapped(&band, &around(30.0)));
        // The overlap is gone: the band covers less than its polygons did.
        assert!(region.area() < band.area());
    }

    #[test]
    fn ends_that_do_not_meet_exactly_go_through_a_union() {
        // The end line a hair higher than the start: the runs do not pair, and the outlines touch.
        let length = 40.0;
        let mut band = strip(length, 2);
        band.polygons[0].outer[2].y += 1e-3;
        band.polygons[0].outer[1].y += 1e-3;
        let region = joined(&band, &around(length), Some(length)).expect("resolved by a union");
        assert_same_region(&region, &union_of_mapped(&band, &around(length)));
        assert_eq!(region.polygons.len(), 1);
    }

    #[test]
    fn only_the_polygons_that_cross_go_through_the_union() {
        // Three squares along a line: the first two overlap, the third is apart.
        let square = |x: f64, s: f64| {
            vec![DVec2::new(x, -s), DVec2::new(x + 2.0 * s, -s), DVec2::new(x + 2.0 * s, s), DVec2::new(x, s)]
        };
        let band = Region::new(vec![
            Polygon { outer: square(0.0, 1.0), holes: Vec::new() },
            Polygon { outer: square(1.5, 0.5), holes: Vec::new() },
            Polygon { outer: square(10.0, 1.0), holes: Vec::new() },
        ]);
        let bend = |p: DVec2| DVec2::new(p.x, p.y + 0.01 * p.x * p.x);
        let region = joined(&band, &bend, None).expect("resolved by a union");
        assert_same_region(&region, &union_of_mapped(&band, &bend));
        assert_eq!(region.polygons.len(), 2);
        // The square apart keeps its mapped points to the last bit.
        let apart = &outlines(&band, &bend, None)[2].points;
        assert!(region.polygons.iter().any(|p| &p.outer == apart));
    }

    #[test]
    fn a_union_at_one_end_of_a_loop_rounds_the_other_end_alike() {
        // The band's first part overlaps a second one, so both go through a
        // union, whose grid moves their points by an ulp or so; the part at
        // the band's other end, the other side of the loop's closing seam,
        // must come out with the very same heights there, or the seam
        // cannot weld. (Values the union's grid was seen to move.)
        let (start, low, high) = (560.472_230_563_426_6, -1.335_737_409_679_780_3, 0.825_631_061_718_810_4);
        let end = start + 40.0;
        let rect = |x0: f64, x1: f64, y0: f64, y1: f64| {
            vec![DVec2::new(x0, y0), DVec2::new(x1, y0), DVec2::new(x1, y1), DVec2::new(x0, y1)]
        };
        let band = Region::new(
            [
                rect(start, start + 3.0, low, high),
                rect(start + 2.0, start + 4.0, -0.3, 0.3),
                rect(start + 30.0, end, low, high),
            ]
            .into_iter()
            .map(|outer| Polygon { outer, holes: Vec::new() })
            .collect(),
        );
        let heights_at = |region: &Region, x: f64| {
            let mut ys: Vec<u64> =
                region.rings().flatten().filter(|p| (p.x - x).abs() < 1e-9).map(|p| p.y.to_bits()).collect();
            ys.sort_unstable();
            ys
        };
        let rings = outlines(&band, &|p| p, None);
        let region = joined_without_union(band.polygons.len(), &rings, Some([start, end])).expect("resolved");
        assert_eq!(region.polygons.len(), 2);
        assert_eq!(heights_at(&region, start).len(), 2);
        assert_eq!(heights_at(&region, start), heights_at(&region, end));
        // Without the ends, only the first part is rounded, and the two sides part.
        let apart = joined_without_union(band.polygons.len(), &rings, None).expect("resolved");
        assert_ne!(heights_at(&apart, start), heights_at(&apart, end));
    }
}
