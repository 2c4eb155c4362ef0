//! Vertices that lie on another ring's edge, made into shared vertices.
//!
//! Meshing needs it where rounding to `f32` put a vertex exactly on another
//! ring's edge (a T-junction). The pattern stages need it where two parts
//! touch: one ring's vertex can sit on the middle of the other's edge
//! instead of on one of its vertices, because stitching thins the
//! points of a deformed outline, and may thin away the vertex that the other
//! part's tip touched. [`super::separate_touching_rings`] only sees points
//! that several rings share, so such a contact stayed, and a union merged
//! the two parts that the plan keeps apart. Inserting the point into the
//! edge turns the contact into a shared point, which is then separated like
//! any other.

use std::collections::HashMap;

use glam::DVec2;

use super::ring_perimeter;

/// Most grid cells an edge looks at: an edge across much of the drawing is
/// rare, and too costly to scan, so it is left as it is.
const MAX_CELLS_PER_EDGE: i64 = 4096;

/// Inserts into each ring's edges the vertices of `rings` (of any ring) that
/// lie within `tolerance` of the edge's interior, at exactly the vertex's
/// position, in order along the edge. With a tolerance of 0 only vertices
/// exactly on the edge count: meshing uses that on coordinates rounded to
/// `f32`, where the test is exact in `f64` (T-junctions, which the
/// triangulation cannot keep as one constraint).
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::insert_edge_contacts;
/// // A triangle whose tip touches the middle of a square's top edge.
/// let square = vec![DVec2::new(0.0, 0.0), DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)];
/// let tip = vec![DVec2::new(1.0, 2.0), DVec2::new(2.0, 3.0), DVec2::new(0.0, 3.0)];
/// let mut rings = vec![square, tip];
/// insert_edge_contacts(&mut rings, 0.0);
/// assert_eq!(rings[0].len(), 5);
/// assert!(rings[0].contains(&DVec2::new(1.0, 2.0)));
/// ```
pub fn insert_edge_contacts(rings: &mut [Vec<DVec2>], tolerance: f64) {
    let points: Vec<DVec2> = rings.iter().flatten().copied().collect();
    let edges = points.len().max(1);
    let perimeter: f64 = rings.iter().map(|r| ring_perimeter(r)).sum();
    // Cells about as large as an edge: each edge looks at a few cells.
    let cell = (perimeter / edges as f64).max(f64::MIN_POSITIVE);
    let cell_of = |p: DVec2| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    for (i, &p) in points.iter().enumerate() {
        grid.entry(cell_of(p)).or_default().push(i);
    }
    let pad = DVec2::splat(tolerance);
    for ring in rings.iter_mut() {
        let n = ring.len();
        let mut out = Vec::with_capacity(n);
        for k in 0..n {
            let (a, b) = (ring[k], ring[(k + 1) % n]);
            out.push(a);
            let (lo, hi) = (cell_of(a.min(b) - pad), cell_of(a.max(b) + pad));
            if (hi.0 - lo.0 + 1) * (hi.1 - lo.1 + 1) > MAX_CELLS_PER_EDGE {
                continue;
            }
            let d = b - a;
            // Off the line by at most `tolerance`: `|d × (p − a)| ≤ tolerance·|d|`,
            // which at 0 is the exact test.
            let off_line = tolerance * d.length();
            let mut inside: Vec<(f64, DVec2)> = Vec::new();
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    for &i in grid.get(&(x, y)).into_iter().flatten() {
                        let p = points[i];
                        let t = (p - a).dot(d);
                        if d.perp_dot(p - a).abs() <= off_line && t > 0.0 && t < d.length_squared() {
                            inside.push((t, p));
                        }
                    }
                }
            }
            inside.sort_by(|x, y| x.0.total_cmp(&y.0));
            inside.dedup_by(|x, y| x.1 == y.1);
            out.extend(inside.into_iter().map(|(_, p)| p));
        }
        *ring = out;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_vertex_near_but_off_an_edge_is_left_alone() {
        let square = vec![DVec2::new(0.0, 0.0), DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)];
        let tip = vec![DVec2::new(1.0, 2.001), DVec2::new(2.0, 3.0), DVec2::new(0.0, 3.0)];
        let mut rings = vec![square.clone(), tip.clone()];
        insert_edge_contacts(&mut rings, 1e-6);
        assert_eq!(rings, vec![square, tip]);
    }

    #[test]
    fn several_contacts_on_one_edge_go_in_order_along_it() {
        let bar = vec![DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0), DVec2::new(10.0, 1.0), DVec2::new(0.0, 1.0)];
        let tip = |x: f64| vec![DVec2::new(x, 1.0), DVec2::new(x + 0.5, 2.0), DVec2::new(x - 0.5, 2.0)];
        let mut rings = vec![bar, tip(7.0), tip(2.0), tip(5.0)];
        insert_edge_contacts(&mut rings, 1e-9);
        let top: Vec<f64> = rings[0].iter().filter(|p| p.y == 1.0).map(|p| p.x).collect();
        assert_eq!(top, vec![10.0, 7.0, 5.0, 2.0, 0.0]);
    }

    #[test]
    fn a_ring_pinched_against_its_own_edge_gets_the_point_too() {
        // A square with a notch from the top whose tip touches the bottom edge.
        let notched = vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(4.0, 0.0),
            DVec2::new(4.0, 4.0),
            DVec2::new(3.0, 4.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(1.0, 4.0),
            DVec2::new(0.0, 4.0),
        ];
        let mut rings = vec![notched];
        insert_edge_contacts(&mut rings, 1e-9);
        assert_eq!(rings[0].len(), 8);
        assert_eq!(rings[0][1], DVec2::new(2.0, 0.0));
    }
}
