//! T-junctions: a vertex of one ring lying exactly on an edge of another
//! once coordinates are rounded to `f32`. The triangulation cannot keep such
//! an edge as one constraint, so the vertex is inserted into the edge too:
//! the rings then share a point, which meshing knows how to separate.

use std::collections::HashMap;

use glam::DVec2;

use crate::geom::ring_perimeter;

/// The rings with every vertex that lies exactly inside another edge (of any
/// ring) inserted into that edge. Coordinates are expected to be `f32`
/// values, so the collinearity test below is exact in `f64`.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::mesh::split_t_junctions;
/// let square = vec![DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)];
/// // A triangle whose tip lies on the square's top edge.
/// let tip = vec![DVec2::new(2.0, 4.0), DVec2::new(1.0, 6.0), DVec2::new(3.0, 6.0)];
/// let rings = split_t_junctions(&[square, tip]);
/// assert_eq!(rings[0].len(), 5);
/// assert!(rings[0].contains(&DVec2::new(2.0, 4.0)));
/// ```
pub fn split_t_junctions(rings: &[Vec<DVec2>]) -> Vec<Vec<DVec2>> {
    let points: Vec<DVec2> = rings.iter().flatten().copied().collect();
    let edges = rings.iter().map(|r| r.len()).sum::<usize>().max(1);
    let perimeter: f64 = rings.iter().map(|r| ring_perimeter(r)).sum();
    // Cells about as large as an edge: each edge looks at a few cells.
    let cell = (perimeter / edges as f64).max(f64::MIN_POSITIVE);
    let cell_of = |p: DVec2| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    for (i, &p) in points.iter().enumerate() {
        grid.entry(cell_of(p)).or_default().push(i);
    }
    rings
        .iter()
        .map(|ring| {
            let n = ring.len();
            let mut out = Vec::with_capacity(n);
            for k in 0..n {
                let (a, b) = (ring[k], ring[(k + 1) % n]);
                out.push(a);
                let (lo, hi) = (cell_of(a.min(b)), cell_of(a.max(b)));
                if (hi.0 - lo.0 + 1) * (hi.1 - lo.1 + 1) > 4096 {
                    // An edge across much of the drawing: rare, and too costly to scan.
                    continue;
                }
                let mut inside: Vec<(f64, DVec2)> = Vec::new();
                for x in lo.0..=hi.0 {
                    for y in lo.1..=hi.1 {
                        for &i in grid.get(&(x, y)).into_iter().flatten() {
                            let p = points[i];
                            let t = (p - a).dot(b - a);
                            if (b - a).perp_dot(p - a) == 0.0 && t > 0.0 && t < (b - a).length_squared() {
                                inside.push((t, p));
                            }
                        }
                    }
                }
                inside.sort_by(|x, y| x.0.total_cmp(&y.0));
                inside.dedup_by(|x, y| x.1 == y.1);
                out.extend(inside.into_iter().map(|(_, p)| p));
            }
            out
        })
        .collect()
}
