//! Whether closed rings cross or touch, found through a grid of cells
//! rather than a sweep: a sweep along `x` compares every pair of edges whose
//! `x` spans overlap, which on a loop's steep flanks is thousands per edge.

use glam::DVec2;

use super::clip::segments_cross;

/// Most grid entries per edge before the grid is given up for the sweep
/// ([`super::crossing_rings`]): a few very long edges would fill it.
const MAX_CELLS_PER_EDGE: usize = 8;

/// Bits of each cell coordinate in a grid entry: at most 4096 cells along
/// a side, so that entries are grouped by cell in two counting passes.
const CELL_BITS: u32 = 12;

/// Bits of an edge's index in a grid entry, below its cell's coordinates.
const EDGE_BITS: u32 = 64 - 2 * CELL_BITS;

/// Whether any of `rings` (closed) crosses or touches itself or another:
/// two edges that are not neighbours in one ring share a point. The answer
/// of `crossing_rings(rings).contains(&true)`, found by comparing only edges
/// that share a grid cell, on both halves of the grid at once.
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
    match EdgeGrid::new(rings) {
        Some(grid) => {
            let (a, b) = grid.on_halves(|entries| grid.meeting_in(entries, |_, _| true));
            a || b
        }
        None => super::crossing_rings(rings).contains(&true),
    }
}

/// Which of `rings` (closed) cross or touch themselves or another: the
/// answer of [`super::crossing_rings`], found through the grid of
/// [`rings_meet`].
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::meeting_rings;
/// let square = |x: f64| vec![DVec2::new(x, 0.0), DVec2::new(x + 1.0, 0.0), DVec2::new(x + 1.0, 1.0), DVec2::new(x, 1.0)];
/// assert_eq!(meeting_rings(&[square(0.0), square(0.5), square(3.0)]), vec![true, true, false]);
/// ```
pub fn meeting_rings<R: AsRef<[DVec2]> + Sync>(rings: &[R]) -> Vec<bool> {
    let Some(grid) = EdgeGrid::new(rings) else {
        return super::crossing_rings(rings);
    };
    let ring_of = |e: usize| grid.first_edge.partition_point(|&first| first <= e) - 1;
    let meeting_in = |entries: &[u64]| {
        let mut meeting = vec![false; rings.len()];
        grid.meeting_in(entries, |e, f| {
            meeting[ring_of(e)] = true;
            meeting[ring_of(f)] = true;
            false
        });
        meeting
    };
    let (a, b) = grid.on_halves(meeting_in);
    a.iter().zip(b).map(|(&a, b)| a || b).collect()
}

/// The cell of a grid entry: its x and y.
fn cell_of(entry: u64) -> u64 {
    entry >> EDGE_BITS
}

/// The edge of a grid entry.
fn edge_of(entry: u64) -> usize {
    (entry & ((1 << EDGE_BITS) - 1)) as usize
}

/// Every ring edge, and the cells of a grid each edge's box covers.
struct EdgeGrid {
    /// Each edge's two ends, in the rings' order.
    ends: Vec<[DVec2; 2]>,
    /// The index of the edge after each one in its ring.
    next: Vec<usize>,
    /// The index of each ring's first edge.
    first_edge: Vec<usize>,
    /// One word per cell an edge covers, the cell's x and y above the
    /// edge's index, grouped by cell.
    entries: Vec<u64>,
}

impl EdgeGrid {
    /// The grid of `rings`, or `None` where a grid does not suit them
    /// (a few very long edges, no extent) and the sweep is used instead.
    fn new<R: AsRef<[DVec2]>>(rings: &[R]) -> Option<EdgeGrid> {
        let edges: usize = rings.iter().map(|r| r.as_ref().len()).sum();
        if edges >= 1 << EDGE_BITS {
            return None;
        }
        let mut ends: Vec<[DVec2; 2]> = Vec::with_capacity(edges);
        let mut next: Vec<usize> = Vec::with_capacity(edges);
        let mut first_edge = Vec::with_capacity(rings.len());
        let (mut min, mut max, mut length) = (DVec2::INFINITY, DVec2::NEG_INFINITY, 0.0);
        for ring in rings {
            let ring = ring.as_ref();
            let (n, first) = (ring.len(), ends.len());
            first_edge.push(first);
            for i in 0..n {
                let (a, b) = (ring[i], ring[(i + 1) % n]);
                ends.push([a, b]);
                next.push(first + (i + 1) % n);
                (min, max, length) = (min.min(a), max.max(a), length + a.distance(b));
            }
        }
        // Cells about two mean edges across, but never more than 4096 along a side.
        let side = (1u64 << CELL_BITS) - 1;
        let cell = (2.0 * length / edges.max(1) as f64).max((max - min).max_element() / side as f64);
        if !(cell.is_finite() && cell > 0.0) {
            return None;
        }
        let index = |p: DVec2| {
            let at = |t: f64| ((t / cell) as u64).min(side);
            (at(p.x - min.x), at(p.y - min.y))
        };
        let mut entries: Vec<u64> = Vec::with_capacity(2 * edges);
        for (e, &[a, b]) in ends.iter().enumerate() {
            let (lo, hi) = (index(a.min(b)), index(a.max(b)));
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    entries.push(x << (EDGE_BITS + CELL_BITS) | y << EDGE_BITS | e as u64);
                }
            }
            if entries.len() > MAX_CELLS_PER_EDGE * edges {
                return None;
            }
        }
        // Grouped by cell in two stable counting passes (y, then x): linear,
        // where a comparison sort of the entries was a third of the time.
        let mut sorted = vec![0u64; entries.len()];
        for shift in [EDGE_BITS, EDGE_BITS + CELL_BITS] {
            let bucket = |entry: u64| ((entry >> shift) & side) as usize;
            let mut at = vec![0usize; side as usize + 2];
            for &entry in &entries {
                at[bucket(entry) + 1] += 1;
            }
            for b in 0..=side as usize {
                at[b + 1] += at[b];
            }
            for &entry in &entries {
                let b = bucket(entry);
                sorted[at[b]] = entry;
                at[b] += 1;
            }
            std::mem::swap(&mut entries, &mut sorted);
        }
        Some(EdgeGrid { ends, next, first_edge, entries })
    }

    /// `work` on the entries cut in two halves between cells, one half
    /// per core.
    fn on_halves<T: Send>(&self, work: impl Fn(&[u64]) -> T + Sync) -> (T, T) {
        let entries = &self.entries;
        let mut half = entries.len() / 2;
        while half > 0 && half < entries.len() && cell_of(entries[half]) == cell_of(entries[half - 1]) {
            half += 1;
        }
        let (low, high) = entries.split_at(half);
        rayon::join(|| work(low), || work(high))
    }

    /// Calls `found` with every two edges that share a cell of `entries`
    /// (a run of whole cells of [`Self::entries`]) and a point, and are
    /// not neighbours in one ring, until it returns `true`; whether it did.
    fn meeting_in(&self, entries: &[u64], mut found: impl FnMut(usize, usize) -> bool) -> bool {
        let meet = |e: usize, f: usize| {
            let ([a, b], [c, d]) = (self.ends[e], self.ends[f]);
            // Boxes apart rule out most pairs before the exact test.
            let apart = a.x.max(b.x) < c.x.min(d.x)
                || c.x.max(d.x) < a.x.min(b.x)
                || a.y.max(b.y) < c.y.min(d.y)
                || c.y.max(d.y) < a.y.min(b.y);
            !apart && self.next[e] != f && self.next[f] != e && segments_cross([a, b], [c, d])
        };
        entries.chunk_by(|&p, &q| cell_of(p) == cell_of(q)).any(|cell| {
            cell.iter().enumerate().any(|(k, &p)| {
                cell[k + 1..].iter().any(|&q| {
                    let (e, f) = (edge_of(p), edge_of(q));
                    meet(e, f) && found(e, f)
                })
            })
        })
    }
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

    /// Rings of a few random points each round random centres, some
    /// crossing, some touching at a shared vertex, most apart.
    fn random_rings(seed: u64) -> Vec<Vec<DVec2>> {
        let mut random = crate::random::SplitMix64::new(seed);
        let count = 2 + random.below(12) as usize;
        let mut rings: Vec<Vec<DVec2>> = (0..count)
            .map(|_| {
                let centre = DVec2::new(random.next_unit() * 20.0, random.next_unit() * 3.0);
                let n = 3 + random.below(40) as usize;
                (0..n)
                    .map(|k| {
                        let r = 0.2 + random.next_unit();
                        centre + r * DVec2::from_angle(k as f64 * std::f64::consts::TAU / n as f64)
                    })
                    .collect()
            })
            .collect();
        if random.below(3) == 0 {
            // A vertex of one ring put on a vertex of another: touching.
            let (a, b) = (random.below(count as u64) as usize, random.below(count as u64) as usize);
            if a != b {
                let p = rings[a][0];
                rings[b][0] = p;
            }
        }
        rings
    }

    #[test]
    fn agrees_with_the_sweep_on_random_rings() {
        let mut meeting = 0;
        for seed in 0..400 {
            let rings = random_rings(seed);
            let crossing = crossing_rings(&rings);
            let expected = crossing.contains(&true);
            assert_eq!(rings_meet(&rings), expected, "seed {seed}");
            assert_eq!(meeting_rings(&rings), crossing, "seed {seed}");
            meeting += usize::from(expected);
        }
        // Both answers are common, so the comparison means something.
        assert!((40..360).contains(&meeting), "{meeting} of 400 meet");
    }

    #[test]
    fn edges_in_the_last_cell_of_a_long_grid_are_compared() {
        // A long thin frame sets the grid at its most cells along x; two
        // small squares touching at its far end meet there.
        let long = vec![DVec2::new(0.0, -1.0), DVec2::new(1e5, -1.0), DVec2::new(1e5, -0.5), DVec2::new(0.0, -0.5)];
        let square = |x: f64| {
            vec![DVec2::new(x, 0.0), DVec2::new(x + 1e-3, 0.0), DVec2::new(x + 1e-3, 1e-3), DVec2::new(x, 1e-3)]
        };
        let x = 1e5 - 2e-3;
        assert!(rings_meet(&[long.clone(), square(x), square(x + 1e-3)]));
        assert!(!rings_meet(&[long, square(x), square(x + 2e-3)]));
    }
}
