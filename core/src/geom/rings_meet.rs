//! Whether closed rings cross or touch, found through a grid of cells
//! rather than a sweep: a sweep along `x` compares every pair of edges whose
//! `x` spans overlap, which on a loop's steep flanks is thousands per edge.

use glam::DVec2;
use rayon::prelude::*;

use super::clip::segments_cross;

/// Most grid entries per edge before the grid is given up for the sweep
/// ([`super::crossing_rings`]): a few very long edges would fill it.
const MAX_CELLS_PER_EDGE: usize = 8;

/// Whether any of `rings` (closed) crosses or touches itself or another:
/// two edges that are not neighbours in one ring share a point. The answer
/// of `crossing_rings(rings).contains(&true)`, found by comparing only edges
/// that share a grid cell, on every core.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::rings_meet;
/// let square = |x: f64| vec![DVec2::new(x, 0.0), DVec2::new(x + 1.0, 0.0), DVec2::new(x + 1.0, 1.0), DVec2::new(x, 1.0)];
/// assert!(!rings_meet(&[square(0.0), square(3.0)]));
/// assert!(rings_meet(&[square(0.0), square(0.5)]));
/// // Touching at a corner counts.
/// assert!(rings_meet(&[square(0.0), square(1.0)]));
/// ```
pub fn rings_meet<R: AsRef<[DVec2]> + Sync>(rings: &[R]) -> bool {
    let edges: usize = rings.iter().map(|r| r.as_ref().len()).sum();
    let points = || rings.iter().flat_map(|r| r.as_ref());
    let (Some(min), Some(max)) = (points().copied().reduce(DVec2::min), points().copied().reduce(DVec2::max)) else {
        return false;
    };
    let length: f64 = rings.iter().map(|r| super::ring_perimeter(r.as_ref())).sum();
    // Cells about two mean edges across, but never more than 4096 along a side.
    let cell = (2.0 * length / edges.max(1) as f64).max((max - min).max_element() / 4096.0);
    if !(cell.is_finite() && cell > 0.0) {
        return super::crossing_rings(rings).contains(&true);
    }
    let index = |p: DVec2| (((p.x - min.x) / cell) as u64, ((p.y - min.y) / cell) as u64);
    let mut entries: Vec<(u64, u32, u32)> = Vec::with_capacity(2 * edges);
    for (r, ring) in rings.iter().enumerate() {
        let ring = ring.as_ref();
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let (lo, hi) = (index(a.min(b)), index(a.max(b)));
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    entries.push((x << 32 | y, r as u32, i as u32));
                }
            }
            if entries.len() > MAX_CELLS_PER_EDGE * edges {
                return super::crossing_rings(rings).contains(&true);
            }
        }
    }
    entries.par_sort_unstable();
    let edge = |r: u32, i: u32| {
        let ring = rings[r as usize].as_ref();
        [ring[i as usize], ring[(i as usize + 1) % ring.len()]]
    };
    entries.par_chunk_by(|a, b| a.0 == b.0).any(|cell| {
        cell.iter().enumerate().any(|(k, &(_, r, i))| {
            let n = rings[r as usize].as_ref().len() as u32;
            cell[k + 1..].iter().any(|&(_, s, j)| {
                let neighbours = r == s && ((i + 1) % n == j || (j + 1) % n == i);
                !neighbours && segments_cross(edge(r, i), edge(s, j))
            })
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::crossing_rings;

    /// Rings of many short edges: circles of radius `r` round `c`.
    fn circle(c: DVec2, r: f64, n: usize) -> Vec<DVec2> {
        (0..n).map(|k| c + r * DVec2::from_angle(k as f64 * std::f64::consts::TAU / n as f64)).collect()
    }

    #[test]
    fn agrees_with_the_sweep_on_rings_near_and_apart() {
        for gap in [-0.3, -1e-3, 0.0, 1e-9, 1e-3, 0.5] {
            let rings = vec![circle(DVec2::ZERO, 1.0, 400), circle(DVec2::new(2.0 + gap, 0.0), 1.0, 257)];
            assert_eq!(rings_meet(&rings), crossing_rings(&rings).contains(&true), "gap {gap}");
        }
    }

    #[test]
    fn finds_a_ring_crossing_itself() {
        let mut ring = circle(DVec2::ZERO, 1.0, 300);
        // A spike from one side of the circle across to the other.
        ring[150] = DVec2::new(1.5, 0.01);
        assert!(rings_meet(&[ring.clone()]));
        assert!(crossing_rings(&[ring]).contains(&true));
    }
}
