//! Gaps narrower than a width closed, where they are: a local morphological
//! closing.
//!
//! Real ornaments are full of strokes that graze: a tapered tip laid on
//! another stroke, two curls drawn tangent. The drawing's union joins them
//! through a neck a thousandth of a millimetre wide, or leaves a gap as
//! narrow. Every later step that moves points (stitching, mapping onto a
//! curve, each within its own chord tolerance) can then pinch such a neck
//! shut or bridge such a gap, and the pattern comes out in a different
//! number of parts or holes than planned. Closing the gaps first, before
//! anything is planned, settles them once: what is closer than the width is
//! joined by real material, at least the width across, in the plan and in
//! the result alike, and what stays apart is at least the width apart.
//!
//! A morphological closing of the whole region (grow by the radius, shrink
//! back) does the same, but multiplies the vertex count by three, takes
//! 60 ms on a dense ornament and rounds every concave corner; here only the
//! places where two outlines come that close are filled, 2–11 ms.

use glam::DVec2;
use rustc_hash::FxHashMap;

use super::{Polygon, Region, closest_on_segment, union};

/// How much longer than their distance apart the outline between two close
/// points must be for them to count as two outlines meeting, rather than one
/// outline turning: a notch sharper than about 29°.
const DETOUR: f64 = 4.0;

/// At most this many pieces of outline are compared; past it they grow
/// longer than the radius, and close places are found more coarsely.
const MAX_SAMPLES: usize = 2_000_000;

/// `region` with every gap narrower than `2 · radius` closed: where two
/// outlines (or two stretches of one outline, far apart along it) face
/// each other across empty space closer than that, the space between is
/// filled. Elsewhere the region is unchanged. Gaps between parts close,
/// joining them; a curl that grazes another stroke is joined to it along
/// the stretch where they are that close; a hole narrower than that fills
/// but for specks at its ends, about as thin as the radius.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{Polygon, Region, close_narrow_gaps};
/// let square = |x: f64| Polygon {
///     outer: vec![DVec2::new(x, 0.0), DVec2::new(x + 1.0, 0.0), DVec2::new(x + 1.0, 1.0), DVec2::new(x, 1.0)],
///     holes: vec![],
/// };
/// // Two squares 0.01 apart are joined; 0.5 apart, they are left alone.
/// let near = Region::new(vec![square(0.0), square(1.01)]);
/// assert_eq!(close_narrow_gaps(&near, 0.02).component_count(), 1);
/// let far = Region::new(vec![square(0.0), square(1.5)]);
/// assert_eq!(close_narrow_gaps(&far, 0.02), far);
/// ```
pub fn close_narrow_gaps(region: &Region, radius: f64) -> Region {
    if !(radius > 0.0 && radius.is_finite()) || region.is_empty() {
        return region.clone();
    }
    let places = close_places(region, radius);
    if places.is_empty() {
        return region.clone();
    }
    // Each place is bridged by the hull of its two short stretches of
    // outline: together they fill the gap wherever it is narrower than the
    // width, as a closing would, with straight edges instead of arcs.
    let bridges: Vec<Polygon> = places.iter().filter_map(|&[a, b, c, d]| convex_quad(a, b, c, d)).collect();
    union(&[region, &Region::new(bridges)])
}

/// A short stretch of outline: its ends, its ring and where it starts
/// along the ring.
struct Sample {
    a: DVec2,
    b: DVec2,
    ring: u32,
    along: f64,
}

/// The places where two outlines face each other across a gap narrower
/// than `2 · radius`: the ends of the two short stretches of outline there.
fn close_places(region: &Region, radius: f64) -> Vec<[DVec2; 4]> {
    let width = 2.0 * radius;
    let perimeter: f64 = region.rings().map(|r| super::ring_perimeter(r)).sum();
    let step = width.max(perimeter / MAX_SAMPLES as f64);
    let mut samples = Vec::new();
    let mut ring_length = Vec::new();
    for (k, ring) in region.rings().enumerate() {
        let mut along = 0.0;
        for i in 0..ring.len() {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            let length = a.distance(b);
            let pieces = (length / step).ceil().max(1.0) as usize;
            for s in 0..pieces {
                let (t0, t1) = (s as f64 / pieces as f64, (s + 1) as f64 / pieces as f64);
                samples.push(Sample { a: a.lerp(b, t0), b: a.lerp(b, t1), ring: k as u32, along: along + t0 * length });
            }
            along += length;
        }
        ring_length.push(along);
    }
    // Samples at most `step` long whose midpoints are in the same or a
    // neighbouring cell: any two closer than the width are compared.
    let cell = width + step;
    let key = |p: DVec2| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: FxHashMap<(i64, i64), Vec<u32>> = FxHashMap::default();
    for (i, s) in samples.iter().enumerate() {
        grid.entry(key(0.5 * (s.a + s.b))).or_default().push(i as u32);
    }
    let mut places = Vec::new();
    for (i, s) in samples.iter().enumerate() {
        let (ci, cj) = key(0.5 * (s.a + s.b));
        for di in -1..=1 {
            for dj in -1..=1 {
                let Some(others) = grid.get(&(ci + di, cj + dj)) else { continue };
                for &j in others {
                    let o = &samples[j as usize];
                    if (j as usize) <= i {
                        continue;
                    }
                    let (d, p, q) = segment_distance(s, o);
                    if d >= width {
                        continue;
                    }
                    // Material lies left of every outline: where each
                    // outline sees the other on its right, the space
                    // between is a gap; otherwise it is material (a thin
                    // stroke, a tip), which a closing leaves alone.
                    if d > 0.0 && ((s.b - s.a).perp_dot(q - p) >= 0.0 || (o.b - o.a).perp_dot(p - q) >= 0.0) {
                        continue;
                    }
                    if s.ring == o.ring {
                        let (pa, qa) = (s.along + p.distance(s.a), o.along + q.distance(o.a));
                        let length = ring_length[s.ring as usize];
                        let apart = (pa - qa).abs();
                        if apart.min(length - apart) <= DETOUR * d.max(0.25 * radius) {
                            continue;
                        }
                    }
                    places.push([s.a, s.b, o.a, o.b]);
                }
            }
        }
    }
    places
}

/// Distance between two samples that do not cross, with the nearest points.
fn segment_distance(s: &Sample, o: &Sample) -> (f64, DVec2, DVec2) {
    let candidates = [
        (s.a, closest_on_segment(s.a, o.a, o.b).1),
        (s.b, closest_on_segment(s.b, o.a, o.b).1),
        (closest_on_segment(o.a, s.a, s.b).1, o.a),
        (closest_on_segment(o.b, s.a, s.b).1, o.b),
    ];
    candidates
        .into_iter()
        .map(|(p, q)| (p.distance(q), p, q))
        .min_by(|x, y| x.0.total_cmp(&y.0))
        .expect("four candidates")
}

/// The convex hull of four points, counter-clockwise; `None` when it has no area.
fn convex_quad(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Option<Polygon> {
    let mut points = [a, b, c, d];
    points.sort_by(|p, q| p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y)));
    let mut hull: Vec<DVec2> = Vec::with_capacity(8);
    for pass in 0..2 {
        let start = hull.len();
        for &p in points.iter() {
            while hull.len() >= start + 2
                && (hull[hull.len() - 1] - hull[hull.len() - 2]).perp_dot(p - hull[hull.len() - 2]) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
        if pass == 0 {
            points.reverse();
        }
    }
    (hull.len() >= 3 && super::signed_area(&hull) > 0.0).then(|| Polygon { outer: hull, holes: Vec::new() })
}
