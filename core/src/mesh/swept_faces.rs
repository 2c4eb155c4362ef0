//! The faces of an extruded outline from a sweep-line triangulation
//! ([`i_triangle`]), used only where the result can be vouched for.
//!
//! A constrained Delaunay triangulation (spade) took most of a pattern's
//! meshing: 45–55 ms of 55–60 ms for a 40 mm ring of 84 k vertices on two
//! cores. The faces of a flat solid need no Delaunay property, and a
//! sweep-line triangulation of the same rings takes 5 ms on one core. It
//! assumes rings that neither cross nor touch, outer rings counter-clockwise
//! and holes clockwise, so those are checked first, and its triangles are
//! checked after (see [`swept_faces`]); where anything fails, the caller
//! falls back on the constrained triangulation, which also repairs.

use glam::DVec2;
use i_triangle::i_overlay::i_float::int::point::IntPoint;
use i_triangle::int::triangulator::IntTriangulator;
use rayon::prelude::*;
use rustc_hash::FxHashMap;

use crate::geom::rings_meet;

/// Polygons triangulated together on one core: enough that a pattern of
/// thousands of small parts is a few dozen tasks, few enough that its
/// large parts spread over the cores.
const POLYGONS_PER_TASK: usize = 64;

/// Bits the largest coordinate takes on the integer grid: with the cross
/// products in `i128`, far from overflow, and fine enough that every `f32`
/// coordinate of a pattern (a multiple of `2^-23` of its own magnitude)
/// lands on the grid exactly unless it is within `2^-32` of the largest
/// coordinate's magnitude of zero, where it moves less than `2^-56` of it.
const GRID_BITS: i32 = 56;

/// The triangles filling `rings` (indices into `points`; outer rings
/// counter-clockwise, holes clockwise, `polygon_of` saying whose each
/// ring is, rings of a polygon in a row with its outer ring first), each
/// counter-clockwise, as indices into `points`. `None` where this cannot
/// vouch for them:
/// - rings that cross or touch, or run the wrong way round;
/// - rings nested the wrong way: a part inside another part's material
///   rather than in a hole of it, or a hole outside its own part;
/// - two points on one point of the integer grid it works on;
/// - triangles that are not all strictly counter-clockwise, or whose
///   unshared edges are not exactly the rings' edges, each once.
///
/// Triangles that all turn the same way and whose boundary is the rings
/// cover each point as often as the rings wind around it. With rings that
/// neither cross nor touch and are nested as a region's are, that is once
/// inside the material and nowhere else: so what passes is a triangulation
/// of the region, whatever the sweep did. (Rings that merely do not meet
/// can still wind twice round a point: a part lying whole inside another
/// part's material.)
pub(super) fn swept_faces(points: &[DVec2], rings: &[Vec<usize>], polygon_of: &[usize]) -> Option<Vec<[u32; 3]>> {
    if rings.is_empty() || polygon_of.len() != rings.len() {
        return None;
    }
    let grid = on_grid(points)?;
    // Rings in polygons: the first of each polygon its outer ring.
    let mut polygons: Vec<&[Vec<usize>]> = Vec::new();
    let mut start = 0;
    for r in 1..=rings.len() {
        if r == rings.len() || polygon_of[r] != polygon_of[start] {
            polygons.push(&rings[start..r]);
            start = r;
        }
    }
    let turns_right_way = polygons.iter().all(|polygon| {
        polygon.iter().enumerate().all(|(k, ring)| {
            let area = twice_area(&grid, ring);
            if k == 0 { area > 0 } else { area < 0 }
        })
    });
    if !turns_right_way {
        return None;
    }
    let outlines: Vec<Vec<DVec2>> = rings.iter().map(|ring| ring.iter().map(|&i| points[i]).collect()).collect();
    if rings_meet(&outlines) || !nested_as_a_region(&grid, rings, polygon_of) {
        return None;
    }
    let mut next = vec![u32::MAX; points.len()];
    for ring in rings {
        for (k, &i) in ring.iter().enumerate() {
            next[i] = ring[(k + 1) % ring.len()] as u32;
        }
    }
    let faces: Vec<Option<Vec<[u32; 3]>>> =
        polygons.par_chunks(POLYGONS_PER_TASK).map(|chunk| triangulated(&grid, &next, chunk)).collect();
    faces.into_iter().collect::<Option<Vec<_>>>().map(|f| f.concat())
}

/// The points on an integer grid, with the index of each grid point.
struct Grid {
    points: Vec<IntPoint<i64>>,
    index_of: FxHashMap<IntPoint<i64>, u32>,
}

/// `points` on the grid ([`GRID_BITS`]); `None` where two points share a
/// grid point.
fn on_grid(points: &[DVec2]) -> Option<Grid> {
    let largest = points.iter().map(|p| p.x.abs().max(p.y.abs())).fold(0.0_f64, f64::max);
    if !largest.is_finite() || points.len() > u32::MAX as usize {
        return None;
    }
    // A power of two, so that scaling loses nothing.
    let exponent = GRID_BITS - largest.max(f64::MIN_POSITIVE).log2().ceil() as i32 - 1;
    let scale = 2.0_f64.powi(exponent);
    let to_grid = |x: f64| {
        let scaled = (x * scale).round();
        (scaled.abs() < 2.0_f64.powi(GRID_BITS)).then_some(scaled as i64)
    };
    let mut grid = Grid { points: Vec::with_capacity(points.len()), index_of: FxHashMap::default() };
    grid.index_of.reserve(points.len());
    for (i, p) in points.iter().enumerate() {
        let q = IntPoint::new(to_grid(p.x)?, to_grid(p.y)?);
        if grid.index_of.insert(q, i as u32).is_some() {
            return None;
        }
        grid.points.push(q);
    }
    Some(grid)
}

/// Twice the signed area of `ring` on the grid, exactly.
fn twice_area(grid: &Grid, ring: &[usize]) -> i128 {
    let n = ring.len();
    (0..n)
        .map(|k| {
            let (a, b) = (grid.points[ring[k]], grid.points[ring[(k + 1) % n]]);
            i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y)
        })
        .sum()
}

/// Whether rings that neither cross nor touch wind once round the inside of
/// the material and nowhere else: the other rings wind round a point of an
/// outer ring no times, and round a point of a hole once. Each face between
/// the rings then has a winding of 0 or 1, since it lies just inside or just
/// outside some ring, the unbounded one at 0. (The sweep itself must not
/// see rings nested otherwise: it does not check what it is given.)
///
/// The winding at each ring's first point is counted exactly on the grid
/// (a ray towards `+x`, edges crossing its height half-open), over the
/// edges of the rings whose bounds hold some other ring's point, filed by
/// height: the others wind round no such point.
fn nested_as_a_region(grid: &Grid, rings: &[Vec<usize>], polygon_of: &[usize]) -> bool {
    let at = |i: usize| grid.points[i];
    // A polygon's first ring is its outer one.
    let outer = |r: usize| r == 0 || polygon_of[r] != polygon_of[r - 1];
    let mut queries: Vec<(i64, i64, usize)> =
        (0..rings.len()).map(|r| (at(rings[r][0]).x, at(rings[r][0]).y, r)).collect();
    queries.sort_unstable();
    let bounds = |ring: &[usize]| {
        ring.iter().map(|&i| at(i)).fold((i64::MAX, i64::MIN, i64::MAX, i64::MIN), |(x0, x1, y0, y1), p| {
            (x0.min(p.x), x1.max(p.x), y0.min(p.y), y1.max(p.y))
        })
    };
    let containers: Vec<usize> = (0..rings.len())
        .into_par_iter()
        .filter(|&r| {
            let (x0, x1, y0, y1) = bounds(&rings[r]);
            let from = queries.partition_point(|q| q.0 < x0);
            queries[from..].iter().take_while(|q| q.0 <= x1).any(|q| q.2 != r && (y0..=y1).contains(&q.1))
        })
        .collect();
    if containers.is_empty() {
        // No ring winds round another's point: every ring must be outer.
        return (0..rings.len()).all(outer);
    }
    let edges_of = |r: usize| {
        let ring = &rings[r];
        (0..ring.len()).map(move |k| (r as u32, ring[k] as u32, ring[(k + 1) % ring.len()] as u32))
    };
    let (low, high) = containers
        .iter()
        .flat_map(|&r| rings[r].iter())
        .map(|&i| at(i).y)
        .fold((i64::MAX, i64::MIN), |(l, h), y| (l.min(y), h.max(y)));
    // Rows about twice an edge's mean height: an edge is filed under every
    // row it spans, and a row holds the edges crossing its height.
    let edges: usize = containers.iter().map(|&r| rings[r].len()).sum();
    let rise: i128 = containers
        .iter()
        .flat_map(|&r| edges_of(r))
        .map(|(_, a, b)| i128::from(at(a as usize).y.abs_diff(at(b as usize).y)))
        .sum();
    let height = i128::from(high) - i128::from(low);
    let rows = (height * edges as i128 / (2 * rise).max(1)).clamp(1, edges as i128) as usize;
    // Any rule that never files a lower height in a later row will do: an
    // edge spanning a height is then filed in that height's row.
    let per_row = rows as f64 / (height as f64 + 1.0);
    let row_of = |y: i64| (((y - low) as f64 * per_row) as usize).min(rows - 1);
    let span_of = |(_, a, b): (u32, u32, u32)| {
        let (ya, yb) = (at(a as usize).y, at(b as usize).y);
        row_of(ya.min(yb))..=row_of(ya.max(yb))
    };
    // Filed in one array, row after row (counted first, then placed): a
    // list per row cost an allocation for every few edges.
    let mut first = vec![0_usize; rows + 1];
    for edge in containers.iter().flat_map(|&r| edges_of(r)) {
        for row in span_of(edge) {
            first[row + 1] += 1;
        }
    }
    for row in 0..rows {
        first[row + 1] += first[row];
    }
    let mut filled = first.clone();
    let mut filed = vec![(0_u32, 0_u32, 0_u32); first[rows]];
    for edge in containers.iter().flat_map(|&r| edges_of(r)) {
        for row in span_of(edge) {
            filed[filled[row]] = edge;
            filled[row] += 1;
        }
    }
    queries.par_iter().all(|&(x, y, r)| {
        let expected = if outer(r) { 0 } else { 1 };
        if y < low || y > high {
            return expected == 0;
        }
        let row = row_of(y);
        let winding: i64 = filed[first[row]..first[row + 1]]
            .iter()
            .filter(|&&(other, _, _)| other as usize != r)
            .map(|&(_, a, b)| {
                let (a, b) = (at(a as usize), at(b as usize));
                let side = i128::from(b.x - a.x) * i128::from(y - a.y) - i128::from(b.y - a.y) * i128::from(x - a.x);
                if a.y <= y && y < b.y && side > 0 {
                    1
                } else if b.y <= y && y < a.y && side < 0 {
                    -1
                } else {
                    0
                }
            })
            .sum();
        winding == expected
    })
}

/// The triangles of `polygons`, checked as [`swept_faces`] says. `next`
/// gives each point's successor on its ring: rings that do not meet
/// share no point, so each point has one.
fn triangulated(grid: &Grid, next: &[u32], polygons: &[&[Vec<usize>]]) -> Option<Vec<[u32; 3]>> {
    let shapes: Vec<Vec<Vec<IntPoint<i64>>>> = polygons
        .iter()
        .map(|polygon| polygon.iter().map(|ring| ring.iter().map(|&i| grid.points[i]).collect()).collect())
        .collect();
    let triangulation = IntTriangulator::<i64, u32>::default().uncheck_triangulate_shapes(&shapes);
    let (local_points, indices) = (&triangulation.points, &triangulation.indices);
    if indices.len() % 3 != 0 || indices.iter().any(|&i| i as usize >= local_points.len()) {
        return None;
    }
    // The triangulation's own points, in its order, as indices into ours.
    let ids: Vec<u32> = local_points.iter().map(|q| grid.index_of.get(q).copied()).collect::<Option<_>>()?;
    // Each point's outgoing triangle edges (counter-clockwise), as lists
    // in one array: a point has a handful, so looking one up is a scan.
    let n = local_points.len();
    let mut first = vec![0_u32; n + 1];
    for &i in indices {
        first[i as usize + 1] += 1;
    }
    for k in 0..n {
        first[k + 1] += first[k];
    }
    let mut filled = first.clone();
    let mut to = vec![0_u32; indices.len()];
    for t in indices.chunks_exact(3) {
        let [pa, pb, pc] = [t[0], t[1], t[2]].map(|i| local_points[i as usize]);
        let turn =
            i128::from(pb.x - pa.x) * i128::from(pc.y - pa.y) - i128::from(pb.y - pa.y) * i128::from(pc.x - pa.x);
        if turn <= 0 {
            return None;
        }
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            to[filled[a as usize] as usize] = b;
            filled[a as usize] += 1;
        }
    }
    let out_of = |a: u32| &to[first[a as usize] as usize..first[a as usize + 1] as usize];
    // No edge twice; every edge with nothing across it is a ring edge
    // (the next point on its ring), and there are as many as ring edges:
    // then the unshared edges are the ring edges, each once.
    let mut unshared = 0;
    for a in 0..n as u32 {
        let out = out_of(a);
        for (k, &b) in out.iter().enumerate() {
            if out[..k].contains(&b) {
                return None;
            }
            if !out_of(b).contains(&a) {
                if next[ids[a as usize] as usize] != ids[b as usize] {
                    return None;
                }
                unshared += 1;
            }
        }
    }
    let ring_edges: usize = polygons.iter().flat_map(|polygon| polygon.iter()).map(Vec::len).sum();
    (unshared == ring_edges)
        .then(|| indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]].map(|i| ids[i as usize])).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, side: f64) -> Vec<DVec2> {
        vec![DVec2::new(x, y), DVec2::new(x + side, y), DVec2::new(x + side, y + side), DVec2::new(x, y + side)]
    }

    /// Points and index rings of `polygons` (each its outer ring, then holes).
    fn indexed(polygons: &[Vec<Vec<DVec2>>]) -> (Vec<DVec2>, Vec<Vec<usize>>, Vec<usize>) {
        let (mut points, mut rings, mut polygon_of) = (Vec::new(), Vec::new(), Vec::new());
        for (p, polygon) in polygons.iter().enumerate() {
            for ring in polygon {
                rings.push((points.len()..points.len() + ring.len()).collect());
                points.extend(ring);
                polygon_of.push(p);
            }
        }
        (points, rings, polygon_of)
    }

    fn area(points: &[DVec2], triangles: &[[u32; 3]]) -> f64 {
        triangles.iter().map(|t| crate::geom::signed_area(&t.map(|i| points[i as usize]))).sum()
    }

    #[test]
    fn a_frame_and_an_island_are_filled_with_their_area() {
        let mut hole = square(1.0, 1.0, 2.0);
        hole.reverse();
        let (points, rings, polygon_of) = indexed(&[vec![square(0.0, 0.0, 4.0), hole], vec![square(10.0, 0.0, 1.0)]]);
        let triangles = swept_faces(&points, &rings, &polygon_of).expect("a valid outline");
        // Counted apart from the triangulation: 16 − 4 + 1.
        assert!((area(&points, &triangles) - 13.0).abs() < 1e-12);
        // n + 2h − 2 triangles for each polygon.
        assert_eq!(triangles.len(), (8 + 2 - 2) + (4 - 2));
    }

    #[test]
    fn outlines_it_cannot_vouch_for_are_refused() {
        // Two parts overlapping.
        let (points, rings, polygon_of) = indexed(&[vec![square(0.0, 0.0, 2.0)], vec![square(1.0, 1.0, 2.0)]]);
        assert!(swept_faces(&points, &rings, &polygon_of).is_none());
        // Touching at a corner.
        let (points, rings, polygon_of) = indexed(&[vec![square(0.0, 0.0, 1.0)], vec![square(1.0, 1.0, 1.0)]]);
        assert!(swept_faces(&points, &rings, &polygon_of).is_none());
        // A hole running the way of an outer ring.
        let (points, rings, polygon_of) = indexed(&[vec![square(0.0, 0.0, 4.0), square(1.0, 1.0, 2.0)]]);
        assert!(swept_faces(&points, &rings, &polygon_of).is_none());
        // A part whole inside another's material, not in a hole of it:
        // the rings do not meet, but wind twice round the inner part.
        let (points, rings, polygon_of) = indexed(&[vec![square(0.0, 0.0, 4.0)], vec![square(1.0, 1.0, 1.0)]]);
        assert!(swept_faces(&points, &rings, &polygon_of).is_none());
        // A hole outside its own part.
        let mut hole = square(6.0, 0.0, 1.0);
        hole.reverse();
        let (points, rings, polygon_of) = indexed(&[vec![square(0.0, 0.0, 4.0), hole]]);
        assert!(swept_faces(&points, &rings, &polygon_of).is_none());
        // An island in a hole, and a part beside the frame at the island's
        // height, are nested as a region's are.
        let mut hole = square(1.0, 1.0, 2.0);
        hole.reverse();
        let (points, rings, polygon_of) =
            indexed(&[vec![square(0.0, 0.0, 4.0), hole], vec![square(1.5, 1.5, 1.0)], vec![square(-3.0, 1.5, 1.0)]]);
        assert!(swept_faces(&points, &rings, &polygon_of).is_some());
        // A bow tie.
        let bow = vec![DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE];
        let (points, rings, polygon_of) = indexed(&[vec![bow]]);
        assert!(swept_faces(&points, &rings, &polygon_of).is_none());
    }
}
