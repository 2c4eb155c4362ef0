//! Smooth outlines: a polygon's rings as cubic Bézier curves through their
//! vertices, for output that should not show the facets of flattening (a
//! laser cuts exactly the path it is given).
//!
//! The rings the pipeline makes are chords of curves: exemplar curves
//! flattened, then bent along the stroke. Their vertices lie on the curves,
//! the chords cut across them. A cubic through each pair of neighbours,
//! leaving each vertex along the chord of its two neighbours (Catmull-Rom's
//! tangent), follows the curve much closer than the chord, and turns
//! smoothly. What is
//! not a chord of a curve stays as drawn:
//! - a vertex where the outline turns by more than a corner's angle stays a
//!   sharp corner (a cut, a spike, a rectangle's corner);
//! - an edge much longer than its neighbours is a straight run of the design
//!   (a rule, a bar), and stays straight; the curves either side meet it
//!   along its own direction, so the join is smooth where it was.
//!
//! Bending the chords moves the outline out by up to the flattening's
//! tolerance, so two outlines closer than that could touch or cross:
//! [`smooth_region`] finds the smoothed outlines, flattened finely, that
//! cross, keeps their straight chords, and checks the whole with the
//! independent topology count and the union's area.

use glam::DVec2;
use lyon::geom::{CubicBezierSegment, point};

use super::{Polygon, Region, Topology, count_topology, crossing_rings, signed_area, union};

/// One piece of a smoothed ring, from where the previous one ended.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum OutlineSegment {
    /// A straight edge to the point.
    Line(DVec2),
    /// A cubic Bézier curve: two control points, then its end.
    Cubic(DVec2, DVec2, DVec2),
}

impl OutlineSegment {
    /// Where the segment ends.
    pub fn end(&self) -> DVec2 {
        match *self {
            OutlineSegment::Line(p) | OutlineSegment::Cubic(_, _, p) => p,
        }
    }
}

/// A closed ring of lines and cubics, starting at `start`; the last
/// segment ends at `start`.
#[derive(Clone, Debug, PartialEq)]
pub struct SmoothRing {
    /// Where the ring starts and ends.
    pub start: DVec2,
    /// The segments, in order.
    pub segments: Vec<OutlineSegment>,
}

/// How rings are smoothed.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct SmoothOptions {
    /// A vertex where the outline turns by more than this (degrees) is a
    /// corner and stays sharp.
    pub corner_deg: f64,
    /// A vertex that turns by more than this (degrees) is a corner too,
    /// unless it is a facet of a coarsely flattened curve: of the nearest
    /// vertices on either side, within `facet_reach_mm` along the outline,
    /// that turn at least half as much, one turns the same way and none the
    /// other. A coarse circle's vertices do; a design's corner stands
    /// alone, or between turns the other way, as on a zigzag.
    pub lone_corner_deg: f64,
    /// How far along the outline (mm) a facet's fellows are looked for.
    pub facet_reach_mm: f64,
    /// An edge this many times longer than both of its neighbours is a
    /// straight run and stays straight.
    pub straight_ratio: f64,
    /// Largest turn (degrees) between successive segments when a smoothed
    /// ring is flattened again ([`SmoothRing::flattened`]) for the check.
    pub check_turn_deg: f64,
    /// Largest distance (mm) between a curve and its flattening in the check.
    pub check_tolerance_mm: f64,
}

impl Default for SmoothOptions {
    fn default() -> Self {
        SmoothOptions {
            corner_deg: 60.0,
            lone_corner_deg: 20.0,
            facet_reach_mm: 5.0,
            straight_ratio: 3.0,
            check_turn_deg: 5.0,
            check_tolerance_mm: 0.001,
        }
    }
}

/// `ring` (closed, without its first point repeated) as lines and cubics
/// through the same vertices, with corners and straight runs kept.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{OutlineSegment, SmoothOptions, smooth_ring};
/// // A decagon: every vertex on a circle of radius 1.5, no corner.
/// let decagon: Vec<DVec2> =
///     (0..10).map(|k| DVec2::from_angle(k as f64 * std::f64::consts::TAU / 10.0) * 1.5).collect();
/// let smooth = smooth_ring(&decagon, &SmoothOptions::default());
/// assert!(smooth.segments.iter().all(|s| matches!(s, OutlineSegment::Cubic(..))));
/// // Flattened again, the outline stays far closer to the circle than the
/// // decagon's chords (0.073 mm inside it at their middles).
/// let worst = smooth.flattened(&SmoothOptions::default()).iter().map(|p| (p.length() - 1.5).abs()).fold(0.0, f64::max);
/// assert!(worst < 0.002, "{worst}");
/// // A square keeps its corners and straight sides.
/// let square = vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
/// let all_lines = |ring: &[DVec2]| smooth_ring(ring, &SmoothOptions::default()).segments.iter().all(|s| matches!(s, OutlineSegment::Line(_)));
/// assert!(all_lines(&square));
/// // So does a zigzag edge turning 40° one way, then the other.
/// let mut zigzag: Vec<DVec2> = (0..9).map(|k| DVec2::new(k as f64, if k % 2 == 0 { 0.0 } else { 0.36 })).collect();
/// zigzag.extend([DVec2::new(8.0, -3.0), DVec2::new(0.0, -3.0)]);
/// assert!(all_lines(&zigzag));
/// ```
pub fn smooth_ring(ring: &[DVec2], options: &SmoothOptions) -> SmoothRing {
    let n = ring.len();
    let start = ring.first().copied().unwrap_or(DVec2::ZERO);
    if n < 3 {
        return chords(ring);
    }
    let at = |k: usize| ring[k % n];
    // Edge k runs from vertex k to vertex k + 1.
    let edge: Vec<DVec2> = (0..n).map(|k| at(k + 1) - at(k)).collect();
    let length: Vec<f64> = edge.iter().map(|e| e.length()).collect();
    let previous = |k: usize| (k + n - 1) % n;
    // How far the outline turns at each vertex, radians, left positive; an
    // edge with no length to say which way it goes makes a corner.
    let turn: Vec<f64> = (0..n)
        .map(|k| {
            let (a, b) = (edge[previous(k)], edge[k]);
            if length[previous(k)] <= 0.0 || length[k] <= 0.0 { std::f64::consts::PI } else { a.angle_to(b) }
        })
        .collect();
    let (hard, lone) = (options.corner_deg.to_radians(), options.lone_corner_deg.to_radians());
    // The nearest vertex from `k` in direction `step` (1 or n - 1) within
    // the reach that turns at least `least`, and which way it turns.
    let fellow = |k: usize, step: usize, least: f64| -> Option<f64> {
        let (mut j, mut travelled) = (k, 0.0);
        for _ in 1..n {
            travelled += if step == 1 { length[j] } else { length[previous(j)] };
            j = (j + step) % n;
            if travelled > options.facet_reach_mm || j == k {
                return None;
            }
            if turn[j].abs() >= least {
                return Some(turn[j]);
            }
        }
        None
    };
    let corner: Vec<bool> = (0..n)
        .map(|k| {
            let t = turn[k];
            if t.abs() > hard {
                return true;
            }
            if t.abs() <= lone {
                return false;
            }
            // A facet has a fellow turning its way, and none the other way
            // (an arc's last facet has nothing beyond it but the line).
            let ways = [fellow(k, 1, 0.5 * t.abs()), fellow(k, n - 1, 0.5 * t.abs())];
            let same = ways.iter().flatten().filter(|o| o.signum() == t.signum()).count();
            let other = ways.iter().flatten().count() - same;
            !(same >= 1 && other == 0)
        })
        .collect();
    // No curve leaves more than this off its chord: it would loop.
    let steepest_cos = hard.cos();
    let straight: Vec<bool> = (0..n)
        .map(|k| {
            let longest_neighbour = length[previous(k)].max(length[(k + 1) % n]);
            (corner[k] && corner[(k + 1) % n]) || length[k] > options.straight_ratio * longest_neighbour
        })
        .collect();
    // The tangent at each vertex, for the curves that meet there; `None` at
    // a corner, where each curve leaves along its own chord.
    let tangent: Vec<Option<DVec2>> = (0..n)
        .map(|k| {
            let p = previous(k);
            if corner[k] {
                None
            } else if straight[p] && !straight[k] {
                Some(edge[p] / length[p])
            } else if straight[k] && !straight[p] {
                Some(edge[k] / length[k])
            } else {
                // Along the neighbours' chord (Catmull-Rom's): the longer
                // edge weighs more, so a sliver of an edge where a cut met
                // the outline, whose direction is rounding noise, cannot
                // swing it (the parabola's tangent could, and bulged holes).
                (edge[p] + edge[k]).try_normalize()
            }
        })
        .collect();
    let segments = (0..n)
        .map(|k| {
            let (a, b) = (at(k), at(k + 1));
            if straight[k] {
                return OutlineSegment::Line(b);
            }
            let chord = edge[k] / length[k];
            let t0 = tangent[k].unwrap_or(chord);
            let t1 = tangent[(k + 1) % n].unwrap_or(chord);
            // A tangent pointing back along the chord would loop the curve.
            if t0.dot(chord) < steepest_cos || t1.dot(chord) < steepest_cos {
                return OutlineSegment::Line(b);
            }
            let handle = length[k] / 3.0;
            OutlineSegment::Cubic(a + t0 * handle, b - t1 * handle, b)
        })
        .collect();
    SmoothRing { start, segments }
}

impl SmoothRing {
    /// The ring as a polyline again: lines as they are, each cubic cut
    /// until its pieces turn by at most `check_turn_deg` and stay within
    /// `check_tolerance_mm` of it. The first point is not repeated.
    pub fn flattened(&self, options: &SmoothOptions) -> Vec<DVec2> {
        let mut out = vec![self.start];
        let mut from = self.start;
        for segment in &self.segments {
            match *segment {
                OutlineSegment::Line(p) => out.push(p),
                OutlineSegment::Cubic(c1, c2, p) => {
                    let curve = CubicBezierSegment {
                        from: point(from.x, from.y),
                        ctrl1: point(c1.x, c1.y),
                        ctrl2: point(c2.x, c2.y),
                        to: point(p.x, p.y),
                    };
                    // Pieces short enough to turn by at most the angle: the
                    // curve's whole turn is at most the angle between its
                    // end tangents plus their turns to the control polygon.
                    let turn = turn_of_control_polygon(from, c1, c2, p);
                    let pieces = (turn / options.check_turn_deg.to_radians()).ceil().max(1.0) as usize;
                    for k in 0..pieces {
                        let piece = curve.split_range(k as f64 / pieces as f64..(k + 1) as f64 / pieces as f64);
                        piece.for_each_flattened(options.check_tolerance_mm, &mut |l| {
                            out.push(DVec2::new(l.to.x, l.to.y))
                        });
                    }
                }
            }
            from = segment.end();
        }
        // The last segment ends where the ring started.
        out.pop();
        out
    }
}

/// The total turn (radians) along a control polygon: a bound on the turn
/// of its cubic, which lies in the polygon's hull and turns one way when
/// the polygon does.
fn turn_of_control_polygon(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> f64 {
    let legs = [b - a, c - b, d - c];
    let mut turn = 0.0;
    let mut last: Option<DVec2> = None;
    for leg in legs {
        if leg.length_squared() <= 0.0 {
            continue;
        }
        if let Some(prev) = last {
            turn += prev.angle_to(leg).abs();
        }
        last = Some(leg);
    }
    turn
}

/// Each ring of `region` smoothed ([`smooth_ring`]), polygon by polygon,
/// outer ring first. A ring whose smoothed outline (flattened again) would
/// cross or touch itself or another keeps its straight chords, as does
/// whatever it would have crossed; then the whole is checked once more:
/// the same topology as the region, and no overlap (the union's area is
/// the rings' signed area). `None` when that fails, and the chords must
/// stay everywhere.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{OutlineSegment, Polygon, Region, SmoothOptions, smooth_region};
/// let ring = |r: f64, n: usize, flip: bool| -> Vec<DVec2> {
///     let mut v: Vec<DVec2> = (0..n).map(|k| DVec2::from_angle(k as f64 * std::f64::consts::TAU / n as f64) * r).collect();
///     if flip { v.reverse() }
///     v
/// };
/// let is_curved = |rings: &[tracery_core::geom::SmoothRing]| -> Vec<bool> {
///     rings.iter().map(|r| r.segments.iter().any(|s| matches!(s, OutlineSegment::Cubic(..)))).collect()
/// };
/// // A washer: its outline and hole apart, both smoothed.
/// let washer = Region::new(vec![Polygon { outer: ring(3.0, 16, false), holes: vec![ring(1.5, 10, true)] }]);
/// assert_eq!(is_curved(&smooth_region(&washer, &SmoothOptions::default()).unwrap()[0]), vec![true, true]);
/// // Three decagons of radius 1, flat sides facing: the first two 0.02
/// // apart, closer than rounding bulges each (0.049), so they keep their
/// // chords; the third, apart, is rounded.
/// let decagon = |x: f64| -> Polygon {
///     let outer = (0..10).map(|k| DVec2::new(x, 0.0) + DVec2::from_angle((18.0 + 36.0 * k as f64).to_radians())).collect();
///     Polygon { outer, holes: vec![] }
/// };
/// let flat = 18f64.to_radians().cos();
/// let three = Region::new(vec![decagon(0.0), decagon(2.0 * flat + 0.02), decagon(6.0)]);
/// let smooth = smooth_region(&three, &SmoothOptions::default()).unwrap();
/// assert_eq!(smooth.iter().map(|p| is_curved(p)[0]).collect::<Vec<_>>(), vec![false, false, true]);
/// ```
pub fn smooth_region(region: &Region, options: &SmoothOptions) -> Option<Vec<Vec<SmoothRing>>> {
    let originals: Vec<&Vec<DVec2>> = region.rings().collect();
    let mut smoothed: Vec<SmoothRing> = originals.iter().map(|ring| smooth_ring(ring, options)).collect();
    let mut flattened: Vec<Vec<DVec2>> = smoothed.iter().map(|r| r.flattened(options)).collect();
    // Each round puts back the chords of the rings that cross; a ring that
    // only crossed a neighbour's curve may cross its chords, hence rounds.
    for _ in 0..CHORD_ROUNDS {
        let crossing = crossing_rings(&flattened);
        if !crossing.iter().any(|&c| c) {
            break;
        }
        for (k, _) in crossing.iter().enumerate().filter(|(_, c)| **c) {
            smoothed[k] = chords(originals[k]);
            flattened[k] = originals[k].clone();
        }
    }
    // Back into polygons, outer ring first.
    let mut rings = smoothed.into_iter();
    let mut flat = flattened.into_iter();
    let mut by_polygon = Vec::with_capacity(region.polygons.len());
    let mut polygons = Vec::with_capacity(region.polygons.len());
    for polygon in &region.polygons {
        let count = 1 + polygon.holes.len();
        by_polygon.push(rings.by_ref().take(count).collect::<Vec<_>>());
        let mut own = flat.by_ref().take(count);
        polygons.push(Polygon { outer: own.next().unwrap_or_default(), holes: own.collect() });
    }
    let flattened = Region::new(polygons);
    // Rings that cross themselves or each other make the union's area
    // differ from the rings' own signed areas; merged or split parts change
    // the count.
    let signed: f64 = flattened.rings().map(|r| signed_area(r)).sum();
    let merged = union(&[&flattened]);
    let counted = Topology { components: merged.component_count(), holes: merged.hole_count() };
    let agrees = (merged.area() - signed).abs() <= AREA_SLACK * signed.abs().max(f64::MIN_POSITIVE)
        && count_topology(region) == counted;
    agrees.then_some(by_polygon)
}

/// Rounds of putting chords back before the whole is checked.
const CHORD_ROUNDS: usize = 4;

/// `ring` as its own straight chords.
fn chords(ring: &[DVec2]) -> SmoothRing {
    SmoothRing {
        start: ring.first().copied().unwrap_or(DVec2::ZERO),
        segments: ring.iter().skip(1).chain(ring.first()).map(|&p| OutlineSegment::Line(p)).collect(),
    }
}

/// Relative difference allowed between the union's area and the smoothed
/// rings' signed areas: far below a crossing's share, above the union's
/// rounding to its integer grid.
const AREA_SLACK: f64 = 1e-6;
