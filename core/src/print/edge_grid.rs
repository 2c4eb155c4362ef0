//! A region's outline edges in a uniform grid: nearest-point queries for
//! the shrinking balls, and the edges near a seam for the bridges.

use glam::DVec2;
use rustc_hash::FxHashMap;

use crate::geom::{Region, closest_on_segment};

pub(super) struct Edge {
    pub(super) a: DVec2,
    pub(super) b: DVec2,
    ring: usize,
    /// Index of `a` in its ring.
    k: usize,
    /// Arc length along the ring at `a`, mm.
    arc_a: f64,
}

/// The outline's edges, each listed in every cell its box overlaps.
pub(super) struct EdgeGrid<'a> {
    rings: Vec<&'a [DVec2]>,
    pub(super) edges: Vec<Edge>,
    ring_lengths: Vec<f64>,
    cell_mm: f64,
    cells: FxHashMap<(i64, i64), Vec<u32>>,
}

impl<'a> EdgeGrid<'a> {
    pub(super) fn new(region: &'a Region, cell_mm: f64) -> Self {
        let rings: Vec<&[DVec2]> = region.rings().map(|r| r.as_slice()).collect();
        let mut edges = Vec::new();
        let mut ring_lengths = Vec::new();
        for (ring_index, ring) in rings.iter().enumerate() {
            let mut arc = 0.0;
            for k in 0..ring.len() {
                let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                edges.push(Edge { a, b, ring: ring_index, k, arc_a: arc });
                arc += a.distance(b);
            }
            ring_lengths.push(arc);
        }
        let mut grid = EdgeGrid { rings, edges, ring_lengths, cell_mm, cells: FxHashMap::default() };
        for (i, e) in grid.edges.iter().enumerate() {
            let (lo, hi) = (grid.cell_of(e.a.min(e.b)), grid.cell_of(e.a.max(e.b)));
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    grid.cells.entry((x, y)).or_default().push(i as u32);
                }
            }
        }
        grid
    }

    pub(super) fn cell_mm(&self) -> f64 {
        self.cell_mm
    }

    fn cell_of(&self, p: DVec2) -> (i64, i64) {
        ((p.x / self.cell_mm).floor() as i64, (p.y / self.cell_mm).floor() as i64)
    }

    /// Edges listed in the cells that overlap the box `lo`–`hi` (some twice).
    fn listed_in(&self, lo: DVec2, hi: DVec2) -> impl Iterator<Item = usize> + '_ {
        let (lo, hi) = (self.cell_of(lo), self.cell_of(hi));
        (lo.0..=hi.0)
            .flat_map(move |x| (lo.1..=hi.1).map(move |y| (x, y)))
            .flat_map(|cell| self.cells.get(&cell).into_iter().flatten().map(|&i| i as usize))
    }

    /// Edges whose cells overlap the box around `a`–`b`, each once.
    pub(super) fn near(&self, a: DVec2, b: DVec2) -> Vec<usize> {
        let mut out: Vec<usize> = self.listed_in(a.min(b), a.max(b)).collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// The vertex before edge `e`, its two ends and the vertex after it.
    pub(super) fn with_neighbours(&self, e: usize) -> (DVec2, DVec2, DVec2, DVec2) {
        let (ring, k) = (self.rings[self.edges[e].ring], self.edges[e].k);
        let n = ring.len();
        (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n], ring[(k + 2) % n])
    }

    /// The nearest outline point to `c` closer than `radius`, if any,
    /// ignoring `skip` (the edge the disc is tangent to), as (edge, point).
    pub(super) fn nearest_within(&self, c: DVec2, radius: f64, skip: usize) -> Option<(usize, DVec2)> {
        let reach = DVec2::splat(radius);
        let mut best: Option<(f64, usize, DVec2)> = None;
        for i in self.listed_in(c - reach, c + reach).filter(|&i| i != skip) {
            let e = &self.edges[i];
            let (_, q) = closest_on_segment(c, e.a, e.b);
            let d = q.distance_squared(c);
            if d < radius * radius && best.is_none_or(|(bd, _, _)| d < bd) {
                best = Some((d, i, q));
            }
        }
        best.map(|(_, i, q)| (i, q))
    }

    /// Distance along the ring between two outline points (the shorter way),
    /// or infinity when they are on different rings.
    pub(super) fn arc_between(&self, e1: usize, p1: DVec2, e2: usize, p2: DVec2) -> f64 {
        let (a, b) = (&self.edges[e1], &self.edges[e2]);
        if a.ring != b.ring {
            return f64::INFINITY;
        }
        let s1 = a.arc_a + a.a.distance(p1);
        let s2 = b.arc_a + b.a.distance(p2);
        let d = (s1 - s2).abs();
        d.min(self.ring_lengths[a.ring] - d)
    }
}
