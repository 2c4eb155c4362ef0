//! Open paths cut to a region (`i_overlay`'s string clipping), and the
//! test for a ring that crosses itself.

use glam::DVec2;
use i_overlay::core::fill_rule::FillRule as OverlayFill;
use i_overlay::float::clip::FloatClip;
use i_overlay::string::clip::ClipRule;

use super::Region;

/// Points of a clipped path closer than this are one point, mm.
const SAME_POINT_MM: f64 = 1e-9;

/// The parts of the polylines `paths_mm` (each open, or closed when its
/// flag says so) that lie inside `region`. A closed path wholly inside
/// comes back closed; every other part comes back open. Parts on the
/// region's boundary count as outside.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region, clip_polylines};
/// let square = Region::new(vec![Polygon {
///     outer: vec![DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)],
///     holes: vec![],
/// }]);
/// let across = vec![DVec2::new(-1.0, 1.0), DVec2::new(3.0, 1.0)];
/// let parts = clip_polylines(&[(across, false)], &square);
/// assert_eq!(parts.len(), 1);
/// assert!((parts[0].0[0].x.min(parts[0].0[1].x) - 0.0).abs() < 1e-9);
/// // A path wholly inside that turns back along x stays one part.
/// let hook = vec![DVec2::new(1.5, 0.2), DVec2::new(1.0, 1.0), DVec2::new(1.1, 1.8)];
/// assert_eq!(clip_polylines(&[(hook, false)], &square).len(), 1);
/// ```
pub fn clip_polylines(paths_mm: &[(Vec<DVec2>, bool)], region: &Region) -> Vec<(Vec<DVec2>, bool)> {
    let shape: Vec<Vec<[f64; 2]>> = region.rings().map(|r| r.iter().map(|p| [p.x, p.y]).collect()).collect();
    if shape.is_empty() {
        return Vec::new();
    }
    let rule = ClipRule { invert: false, boundary_included: false };
    let mut out = Vec::new();
    for (points, closed) in paths_mm {
        if points.len() < 2 {
            continue;
        }
        if *closed && points.iter().all(|p| region.contains(*p)) && !crosses_boundary(points, region) {
            out.push((points.clone(), true));
            continue;
        }
        let mut string: Vec<[f64; 2]> = points.iter().map(|p| [p.x, p.y]).collect();
        if *closed {
            string.push(string[0]);
        }
        let parts: Vec<Vec<DVec2>> = string
            .clip_by_as::<i64>(&shape, OverlayFill::EvenOdd, rule)
            .into_iter()
            .map(|part| {
                let mut part: Vec<DVec2> = part.into_iter().map(|[x, y]| DVec2::new(x, y)).collect();
                part.dedup_by(|a, b| a.distance(*b) < SAME_POINT_MM);
                part
            })
            .filter(|part| part.len() >= 2)
            .collect();
        out.extend(joined_at_shared_ends(parts).into_iter().map(|part| (part, false)));
    }
    out
}

/// Ends of two parts of one path nearer than this are where the clipping
/// split it, not where the region cut it, mm: the snapping to integers
/// moves a point by about 1e-15 mm.
const SPLIT_POINT_MM: f64 = 1e-6;

/// `parts` of one clipped path, with parts that share an end joined. The
/// string clipping also splits a path inside the region at some of its
/// vertices (where it turns back along `x`); left split, the piece's ends
/// would read as loose ends, and a short piece would go as a stub.
fn joined_at_shared_ends(mut parts: Vec<Vec<DVec2>>) -> Vec<Vec<DVec2>> {
    let first_last = |p: &Vec<DVec2>| (p[0], p[p.len() - 1]);
    'again: loop {
        for i in 0..parts.len() {
            for j in i + 1..parts.len() {
                let ((a0, a1), (b0, b1)) = (first_last(&parts[i]), first_last(&parts[j]));
                let near = |p: DVec2, q: DVec2| p.distance(q) < SPLIT_POINT_MM;
                let (reverse_a, reverse_b) = if near(a1, b0) {
                    (false, false)
                } else if near(a1, b1) {
                    (false, true)
                } else if near(a0, b1) {
                    (true, true)
                } else if near(a0, b0) {
                    (true, false)
                } else {
                    continue;
                };
                let mut b = parts.swap_remove(j);
                let a = &mut parts[i];
                if reverse_a {
                    a.reverse();
                }
                if reverse_b {
                    b.reverse();
                }
                a.extend(b.into_iter().skip(1));
                continue 'again;
            }
        }
        return parts;
    }
}

/// Whether a segment of the loop `points` crosses a ring of `region`.
fn crosses_boundary(points: &[DVec2], region: &Region) -> bool {
    let edges = |ring: &[DVec2]| -> Vec<[DVec2; 2]> {
        (0..ring.len()).map(|i| [ring[i], ring[(i + 1) % ring.len()]]).collect()
    };
    let path = edges(points);
    region.rings().any(|ring| edges(ring).iter().any(|a| path.iter().any(|b| segments_cross(*a, *b))))
}

/// Whether two segments share a point (touching counts).
pub(super) fn segments_cross([a, b]: [DVec2; 2], [c, d]: [DVec2; 2]) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        return true;
    }
    let on = |p: DVec2, q: DVec2, r: DVec2, s: f64| {
        s == 0.0 && r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4)
}

/// A point where the closed ring `ring` crosses or touches itself (two
/// edges that are not neighbours share a point), or `None` for a simple
/// ring. Edges are swept in order of their left ends, so only edges whose
/// spans overlap in `x` are compared.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::ring_crossing;
/// let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
/// assert!(ring_crossing(&square).is_none());
/// let bow_tie = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE];
/// assert!((ring_crossing(&bow_tie).unwrap() - DVec2::splat(0.5)).length() < 1e-9);
/// ```
pub fn ring_crossing(ring: &[DVec2]) -> Option<DVec2> {
    let mut at = None;
    sweep_crossings(&[ring], |_, _, [a, b], [c, d]| {
        // Where they meet: the lines' intersection, or a shared end.
        let denominator = (b - a).perp_dot(d - c);
        let t = if denominator.abs() > 0.0 { (c - a).perp_dot(d - c) / denominator } else { 0.0 };
        at = Some(a + (b - a) * t.clamp(0.0, 1.0));
        true
    });
    at
}

/// Sweeps the edges of the closed `rings` in order of their left ends,
/// comparing only edges whose spans overlap, and calls `found` with the
/// two rings and edges of each pair that share a point and are not
/// neighbours on one ring; stops when `found` says so (true).
fn sweep_crossings<R: AsRef<[DVec2]>>(
    rings: &[R],
    mut found: impl FnMut(usize, usize, [DVec2; 2], [DVec2; 2]) -> bool,
) {
    let ring = |r: usize| rings[r].as_ref();
    let edge = |r: usize, i: usize| [ring(r)[i], ring(r)[(i + 1) % ring(r).len()]];
    // (ring, edge, left end) of every edge, by its left end.
    let mut order: Vec<(usize, usize, f64)> = (0..rings.len())
        .filter(|&r| ring(r).len() >= 2)
        .flat_map(|r| (0..ring(r).len()).map(move |i| (r, i, edge(r, i)[0].x.min(edge(r, i)[1].x))))
        .collect();
    order.sort_by(|a, b| a.2.total_cmp(&b.2));
    for (k, &(r, i, _)) in order.iter().enumerate() {
        let [a, b] = edge(r, i);
        let (right, low, high) = (a.x.max(b.x), a.y.min(b.y), a.y.max(b.y));
        for &(s, j, left) in &order[k + 1..] {
            if left > right {
                break;
            }
            let [c, d] = edge(s, j);
            if c.y.max(d.y) < low || c.y.min(d.y) > high {
                continue;
            }
            let n = ring(r).len();
            let neighbours = r == s && ((i + 1) % n == j || (j + 1) % n == i);
            if !neighbours && segments_cross([a, b], [c, d]) && found(r, s, [a, b], [c, d]) {
                return;
            }
        }
    }
}

/// Which of `rings` (closed) cross or touch themselves or another: every
/// ring with an edge that shares a point with an edge not its neighbour.
/// Edges of all rings are swept in order of their left ends, as
/// [`ring_crossing`] sweeps one ring's.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::crossing_rings;
/// let square = |x: f64| vec![DVec2::new(x, 0.0), DVec2::new(x + 1.0, 0.0), DVec2::new(x + 1.0, 1.0), DVec2::new(x, 1.0)];
/// // The second square overlaps the first; the third is apart.
/// assert_eq!(crossing_rings(&[square(0.0), square(0.5), square(3.0)]), vec![true, true, false]);
/// ```
pub fn crossing_rings<R: AsRef<[DVec2]>>(rings: &[R]) -> Vec<bool> {
    let mut crossing = vec![false; rings.len()];
    sweep_crossings(rings, |r, s, _, _| {
        crossing[r] = true;
        crossing[s] = true;
        false
    });
    crossing
}
