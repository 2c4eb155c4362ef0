//! The graph cut that decides which triangles of an element stay (the
//! paper's section 2.7): a minimum cut on the dual graph, through
//! `pathfinding`'s Edmonds–Karp.

use std::collections::{HashMap, VecDeque};

use pathfinding::directed::edmonds_karp::edmonds_karp_sparse;

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
    let mut caps: HashMap<(usize, usize), i64> = HashMap::new();
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
    let nodes: Vec<usize> = (0..triangles + 2).collect();
    let edges: Vec<((usize, usize), i64)> = {
        let mut e: Vec<_> = caps.iter().map(|(&k, &c)| (k, c)).collect();
        e.sort_unstable();
        e
    };
    let (flows, total, _) = edmonds_karp_sparse(&nodes, &source, &sink, edges);
    if total >= FORCED {
        return None;
    }
    let mut net: HashMap<(usize, usize), i64> = HashMap::new();
    for ((u, v), f) in flows {
        *net.entry((u, v)).or_default() += f;
        *net.entry((v, u)).or_default() -= f;
    }
    let mut adjacent: Vec<Vec<usize>> = vec![Vec::new(); triangles + 2];
    for &(u, v) in caps.keys() {
        adjacent[u].push(v);
        adjacent[v].push(u);
    }
    let residual =
        |u: usize, v: usize| caps.get(&(u, v)).copied().unwrap_or(0) - net.get(&(u, v)).copied().unwrap_or(0);
    let mut reached = vec![false; triangles + 2];
    reached[source] = true;
    let mut queue = VecDeque::from([source]);
    while let Some(u) = queue.pop_front() {
        for &v in &adjacent[u] {
            if !reached[v] && residual(u, v) > 0 {
                reached[v] = true;
                queue.push_back(v);
            }
        }
    }
    reached.truncate(triangles);
    Some(reached)
}
