//! Vertices that lie on another ring's edge, made into shared vertices.
//!
//! Where two parts touch, one ring's vertex can sit on the middle of the
//! other's edge instead of on one of its vertices: stitching thins the
//! points of a deformed outline, and may thin away the vertex that the other
//! part's tip touched. [`super::separate_touching_rings`] only sees points
//! that several rings share, so such a contact stayed, and a union merged
//! the two parts that the plan keeps apart. Inserting the point into the
//! edge turns the contact into a shared point, which is then separated like
//! any other.

use glam::DVec2;
use rayon::prelude::*;

/// Most grid entries per edge, and per vertex in all: longer edges (long
/// diagonals, mostly) are checked against every vertex instead, so a few
/// of them do not fill the grid.
const MAX_CELLS_PER_EDGE: usize = 256;
const MAX_CELLS_PER_VERTEX: usize = 16;

/// Inserts into each ring's edges the vertices of `rings` (of other rings,
/// or of the same ring away from that edge) that lie within `tolerance` of
/// the edge's interior, at exactly the vertex's position.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::insert_edge_contacts;
/// // A triangle whose tip touches the middle of a square's top edge.
/// let square = vec![DVec2::new(0.0, 0.0), DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)];
/// let tip = vec![DVec2::new(1.0, 2.0), DVec2::new(2.0, 3.0), DVec2::new(0.0, 3.0)];
/// let mut rings = vec![square, tip];
/// insert_edge_contacts(&mut rings, 1e-9);
/// assert_eq!(rings[0].len(), 5);
/// assert!(rings[0].contains(&DVec2::new(1.0, 2.0)));
/// ```
pub fn insert_edge_contacts(rings: &mut [Vec<DVec2>], tolerance: f64) {
    let vertices: usize = rings.iter().map(Vec::len).sum();
    let points = || rings.iter().flatten();
    let (Some(min), Some(max)) = (points().copied().reduce(DVec2::min), points().copied().reduce(DVec2::max)) else {
        return;
    };
    let length: f64 = rings.iter().map(|r| super::ring_perimeter(r)).sum();
    // Cells about two mean edges across, never more than 4096 along a side.
    let cell = (2.0 * length / vertices.max(1) as f64).max((max - min).max_element() / 4096.0);
    if !(cell.is_finite() && cell > 0.0) {
        return;
    }
    let index = |p: DVec2| (((p.x - min.x) / cell).max(0.0) as u64, ((p.y - min.y) / cell).max(0.0) as u64);
    let pad = DVec2::splat(tolerance);
    // (cell, ring, edge), and the edges too long for the grid.
    let mut entries: Vec<(u64, u32, u32)> = Vec::with_capacity(2 * vertices);
    let mut long: Vec<(u32, u32)> = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let (lo, hi) = (index(a.min(b) - pad), index(a.max(b) + pad));
            let cells = (hi.0 - lo.0 + 1) * (hi.1 - lo.1 + 1);
            if cells > MAX_CELLS_PER_EDGE as u64 || entries.len() + cells as usize > MAX_CELLS_PER_VERTEX * vertices {
                long.push((r as u32, i as u32));
                continue;
            }
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    entries.push((x << 32 | y, r as u32, i as u32));
                }
            }
        }
    }
    entries.par_sort_unstable();
    let in_cell = |key: u64| {
        let start = entries.partition_point(|e| e.0 < key);
        entries[start..].iter().take_while(move |e| e.0 == key).map(|&(_, r, i)| (r, i))
    };
    // (ring, edge, position along the edge, point) of every contact, the
    // vertices looked at on every core.
    let rings_read: &[Vec<DVec2>] = rings;
    let contacts_of = |(r, k): (usize, usize)| {
        let p = rings_read[r][k];
        let (x, y) = index(p);
        let mut hits: Vec<(u32, u32, f64, DVec2)> = Vec::new();
        for (s, j) in in_cell(x << 32 | y).chain(long.iter().copied()) {
            let other = &rings_read[s as usize];
            let m = other.len();
            let j = j as usize;
            // An edge of the vertex's own corner meets it by construction.
            if s as usize == r && (j == k || (j + 1) % m == k) {
                continue;
            }
            let (a, b) = (other[j], other[(j + 1) % m]);
            if p == a || p == b {
                continue;
            }
            let d = b - a;
            let t = (p - a).dot(d) / d.length_squared();
            if t > 0.0 && t < 1.0 && (a + d * t).distance(p) <= tolerance {
                hits.push((s, j as u32, t, p));
            }
        }
        hits
    };
    let mut found: Vec<(u32, u32, f64, DVec2)> = rings_read
        .par_iter()
        .enumerate()
        .flat_map_iter(|(r, ring)| (0..ring.len()).map(move |k| (r, k)))
        .flat_map_iter(contacts_of)
        .collect();
    if found.is_empty() {
        return;
    }
    found.sort_by(|x, y| (x.0, x.1).cmp(&(y.0, y.1)).then(x.2.total_cmp(&y.2)));
    found.dedup_by(|x, y| x.0 == y.0 && x.1 == y.1 && x.3 == y.3);
    for group in found.chunk_by(|x, y| x.0 == y.0) {
        let ring = &mut rings[group[0].0 as usize];
        let mut out = Vec::with_capacity(ring.len() + group.len());
        let mut next = group.iter().peekable();
        for (i, &v) in ring.iter().enumerate() {
            out.push(v);
            while let Some(&&(_, _, _, p)) = next.peek().filter(|c| c.1 as usize == i) {
                out.push(p);
                next.next();
            }
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
