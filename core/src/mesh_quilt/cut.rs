//! The graph cut that decides which triangles of an element stay (the
//! paper's section 2.7): a minimum cut on the dual graph, through
//! `petgraph`'s Dinic maximum flow.

use rustc_hash::FxHashMap;
use std::collections::VecDeque;

use petgraph::algo::dinics;
use petgraph::graph::{DiGraph, NodeIndex};
use petgraph::visit::EdgeRef;

/// Capacity that stands for "never cut": larger than any sum of edge weights.
pub const FORCED: i64 = 1 << 40;

/// Which triangles keep to the source side of a minimum cut. `weights` are
/// the dual edges (triangle, triangle, weight), `keep` and `drop` the
/// triangles tied to either side with a capacity ([`FORCED`] for a tie that
/// must hold; less for an edge to a triangle left out of the graph, which
/// stays). `None` when no cut can honour the forced ties (a triangle tied to
/// both, or a path of tied triangles).
///
/// ```
/// use tracery_core::mesh_quilt::{FORCED, min_cut_keep};
/// // A strip of four triangles, cheapest to cut between 1 and 2.
/// let kept = min_cut_keep(4, &[(0, 1, 5), (1, 2, 1), (2, 3, 5)], &[(0, FORCED)], &[(3, FORCED)]).unwrap();
/// assert_eq!(kept, vec![true, true, false, false]);
/// ```
pub fn min_cut_keep(
    triangles: usize,
    weights: &[(u32, u32, i64)],
    keep: &[(u32, i64)],
    drop: &[(u32, i64)],
) -> Option<Vec<bool>> {
    let (source, sink) = (triangles, triangles + 1);
    let mut caps: FxHashMap<(usize, usize), i64> = FxHashMap::default();
    for &(a, b, w) in weights {
        *caps.entry((a as usize, b as usize)).or_default() += w;
        *caps.entry((b as usize, a as usize)).or_default() += w;
    }
    for &(t, w) in keep {
        let cap = caps.entry((source, t as usize)).or_default();
        *cap = (*cap + w).min(FORCED);
    }
    for &(t, w) in drop {
        let cap = caps.entry((t as usize, sink)).or_default();
        *cap = (*cap + w).min(FORCED);
    }
    // Capacities as petgraph's measures, which are unsigned; in a fixed
    // order, so the cut is the same on every run.
    let mut edges: Vec<((usize, usize), i64)> = caps.into_iter().collect();
    edges.sort_unstable();
    let mut graph: DiGraph<(), u64> = DiGraph::with_capacity(triangles + 2, edges.len());
    for _ in 0..triangles + 2 {
        graph.add_node(());
    }
    for &((u, v), c) in &edges {
        graph.add_edge(NodeIndex::new(u), NodeIndex::new(v), c.max(0) as u64);
    }
    let (total, flows) = dinics(&graph, NodeIndex::new(source), NodeIndex::new(sink));
    if total >= FORCED as u64 {
        return None;
    }
    // The source's side: what it still reaches through edges with room
    // left, or back along edges carrying flow.
    let mut reached = vec![false; triangles + 2];
    reached[source] = true;
    let mut queue = VecDeque::from([source]);
    while let Some(u) = queue.pop_front() {
        let node = NodeIndex::new(u);
        let forward = graph
            .edges_directed(node, petgraph::Direction::Outgoing)
            .filter(|e| flows[e.id().index()] < *e.weight())
            .map(|e| e.target().index());
        let backward = graph
            .edges_directed(node, petgraph::Direction::Incoming)
            .filter(|e| flows[e.id().index()] > 0)
            .map(|e| e.source().index());
        for v in forward.chain(backward) {
            if !reached[v] {
                reached[v] = true;
                queue.push_back(v);
            }
        }
    }
    reached.truncate(triangles);
    Some(reached)
}
