//! The rings of a band-space pattern, mapped along a curve, made into a
//! clean region without a boolean: where the curve is a loop, the outlines
//! that meet at the band's two ends are joined there.
//!
//! A union of the mapped rings gives the same region, but on a dense
//! pattern it is most of the mapping's time (28–38 of 36–55 ms for 55 k
//! vertices) and changes almost nothing: stitching already made the band
//! region clean, and a mapping that does not fold keeps it so. Only the
//! loop's closing seam needs joining, and there the two ends' points are
//! the same to the last bit. Anything this cannot vouch for (an outline
//! that crosses or touches another once mapped, ends that do not meet
//! exactly) is left to the union.

use glam::DVec2;
use rustc_hash::FxHashMap;

use crate::disjoint_sets::DisjointSets;
use crate::geom::{Polygon, Region, rings_meet, signed_area};

/// One band ring mapped into the plane: its points, and for each of the band
/// ring's own vertices its index among them (as
/// [`crate::geom::refine_mapped_indexed`] gives).
#[derive(Clone, Debug)]
pub(crate) struct MappedRing {
    pub points: Vec<DVec2>,
    pub origins: Vec<usize>,
}

/// Where a band vertex lies: on the band's start line, on its end line, or
/// neither. A loop's two ends are the same line in the plane.
pub(crate) struct Ends<S: Fn(f64) -> bool, E: Fn(f64) -> bool> {
    pub at_start: S,
    pub at_end: E,
}

/// A point's exact bits: the key two runs' ends are matched by.
type PointKey = (u64, u64);

/// A maximal run of a ring's band vertices on one end line: mapped indices
/// `first` and `last` of ring `ring`, whose points are its two ends.
#[derive(Clone, Copy, Debug)]
struct Run {
    ring: usize,
    first: usize,
    last: usize,
}

/// The region made of `mapped` (per polygon of `band`: its outer ring then
/// its holes), with each run of outline on the band's start line joined to
/// the run on its end line that has the same two end points, reversed.
/// `None` where the result would not be clean: rings that cross or touch
/// once mapped, a component with more or fewer than one outer ring, or
/// joins that do not fit together. The caller then takes the union.
///
/// Rings keep their orientation when the mapping keeps it, and all are
/// reversed when it mirrors (the material's total area says which).
pub(crate) fn closed_without_union<S: Fn(f64) -> bool, E: Fn(f64) -> bool>(
    band: &Region,
    mapped: &[Vec<MappedRing>],
    ends: Option<Ends<S, E>>,
) -> Option<Region> {
    // Every ring, with its polygon and the offset of its first vertex.
    let mut rings: Vec<(usize, &[DVec2], &MappedRing)> = Vec::new();
    for (p, (polygon, mapped)) in band.polygons.iter().zip(mapped).enumerate() {
        if mapped.len() != 1 + polygon.holes.len() {
            return None;
        }
        for (band_ring, ring) in std::iter::once(&polygon.outer).chain(&polygon.holes).zip(mapped) {
            if band_ring.len() != ring.origins.len() || ring.points.len() < 3 {
                return None;
            }
            rings.push((p, band_ring, ring));
        }
    }
    let mut offset = Vec::with_capacity(rings.len() + 1);
    offset.push(0);
    for (_, _, ring) in &rings {
        offset.push(offset.last().copied().unwrap_or(0) + ring.points.len());
    }
    let total = *offset.last()?;
    let ring_of: Vec<usize> = (0..rings.len()).flat_map(|r| std::iter::repeat_n(r, rings[r].2.points.len())).collect();
    let mut next: Vec<usize> =
        (0..total).map(|g| if g + 1 == offset[ring_of[g] + 1] { offset[ring_of[g]] } else { g + 1 }).collect();
    let mut dropped = vec![false; total];
    let mut groups = DisjointSets::new(band.polygons.len());

    if let Some(ends) = ends {
        let starts = runs(&rings, &ends.at_start)?;
        let finishes = runs(&rings, &ends.at_end)?;
        let point = |r: usize, i: usize| rings[r].2.points[i];
        let key = |p: DVec2| -> PointKey { (p.x.to_bits(), p.y.to_bits()) };
        let mut by_ends: FxHashMap<(PointKey, PointKey), Run> = FxHashMap::default();
        for run in finishes {
            let ends = (key(point(run.ring, run.first)), key(point(run.ring, run.last)));
            if by_ends.insert(ends, run).is_some() {
                return None;
            }
        }
        let mut changed = vec![false; total];
        let mut kept = Vec::new();
        for a in starts {
            // The end's run goes the other way: from the start run's last point to its first.
            let Some(b) = by_ends.remove(&(key(point(a.ring, a.last)), key(point(a.ring, a.first)))) else {
                continue;
            };
            let (na, nb) = (rings[a.ring].2.points.len(), rings[b.ring].2.points.len());
            let (ga, gb) = (offset[a.ring], offset[b.ring]);
            // The start run's inner points and the whole end run go; the
            // outline comes in along the end's side and leaves along the
            // start's, at the points both runs share.
            let mut i = (a.first + 1) % na;
            while i != a.last {
                dropped[ga + i] = true;
                i = (i + 1) % na;
            }
            let mut k = b.first;
            loop {
                dropped[gb + k] = true;
                if k == b.last {
                    break;
                }
                k = (k + 1) % nb;
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
            groups.join(rings[a.ring].0, rings[b.ring].0);
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
            let p = rings[r].2.points[local];
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
        traced.push((groups.find(rings[ring_of[start]].0), ring));
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
    let region = Region { polygons };
    let all: Vec<Vec<DVec2>> = region.rings().cloned().collect();
    if rings_meet(&all) {
        return None;
    }
    Some(region)
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

/// Every ring's maximal runs of two or more band vertices on the line
/// `on(x)`, as mapped indices. `None` for a ring lying wholly on it.
fn runs(rings: &[(usize, &[DVec2], &MappedRing)], on: &impl Fn(f64) -> bool) -> Option<Vec<Run>> {
    let mut out = Vec::new();
    for (r, (_, band_ring, ring)) in rings.iter().enumerate() {
        let n = band_ring.len();
        let flags: Vec<bool> = band_ring.iter().map(|p| on(p.x)).collect();
        if flags.iter().all(|&f| f) {
            return None;
        }
        let Some(off) = flags.iter().position(|&f| !f) else { continue };
        // Positions after `off`, which is off the line, so no run wraps past it.
        let mut k = 1;
        while k < n {
            let first = (off + k) % n;
            if !flags[first] {
                k += 1;
                continue;
            }
            let mut last = first;
            while k + 1 < n && flags[(off + k + 1) % n] {
                k += 1;
                last = (off + k) % n;
            }
            if last != first {
                out.push(Run { ring: r, first: ring.origins[first], last: ring.origins[last] });
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

    fn mapped(band: &Region, map: &dyn Fn(DVec2) -> DVec2) -> Vec<Vec<MappedRing>> {
        band.polygons
            .iter()
            .map(|p| {
                std::iter::once(&p.outer)
                    .chain(&p.holes)
                    .map(|ring| {
                        let (points, origins) = refine_mapped_indexed(ring, map, 0.5, 1e-4);
                        MappedRing { points, origins }
                    })
                    .collect()
            })
            .collect()
    }

    fn ends(length: f64) -> Option<Ends<impl Fn(f64) -> bool, impl Fn(f64) -> bool>> {
        Some(Ends { at_start: |x: f64| x == 0.0, at_end: move |x: f64| (x - length).abs() <= 1e-9 * length })
    }

    #[test]
    fn a_strip_round_a_loop_closes_into_a_ring_with_its_holes() {
        let length = 40.0;
        let band = strip(length, 6);
        let region = closed_without_union(&band, &mapped(&band, &around(length)), ends(length)).expect("welded");
        // One part, whose outline is the loop's outside; its inside and the six holes are holes.
        assert_eq!(region.polygons.len(), 1);
        assert_eq!(region.polygons[0].holes.len(), 7);
        assert!(region.sanity_check().is_ok(), "{:?}", region.sanity_check());
        // The same as the union, counted independently.
        let union = crate::geom::union(&[&Region::new(
            mapped(&band, &around(length))
                .into_iter()
                .map(|rings| Polygon {
                    outer: rings[0].points.clone(),
                    holes: rings[1..].iter().map(|r| r.points.clone()).collect(),
                })
                .collect(),
        )]);
        assert_eq!(union.polygons.len(), 1);
        assert_eq!(union.polygons[0].holes.len(), 7);
        assert!((union.area() - region.area()).abs() < 1e-6 * union.area());
    }

    #[test]
    fn an_open_band_keeps_its_polygons() {
        let band = strip(20.0, 3);
        let bend = |p: DVec2| DVec2::new(p.x, p.y + 0.01 * p.x * p.x);
        type Line = fn(f64) -> bool;
        let none: Option<Ends<Line, Line>> = None;
        let region = closed_without_union(&band, &mapped(&band, &bend), none).expect("clean");
        assert_eq!(region.polygons.len(), 1);
        assert_eq!(region.polygons[0].holes.len(), 3);
    }

    #[test]
    fn outlines_that_overlap_once_mapped_are_left_to_the_union() {
        // Longer than the loop: the band's end runs over its start.
        let band = strip(40.0, 2);
        assert!(closed_without_union(&band, &mapped(&band, &around(30.0)), ends(40.0)).is_none());
    }

    #[test]
    fn ends_that_do_not_meet_exactly_are_left_to_the_union() {
        // The end line a hair higher than the start: the runs do not pair, and the outlines touch.
        let length = 40.0;
        let mut band = strip(length, 2);
        band.polygons[0].outer[2].y += 1e-3;
        band.polygons[0].outer[1].y += 1e-3;
        assert!(closed_without_union(&band, &mapped(&band, &around(length)), ends(length)).is_none());
    }
}
