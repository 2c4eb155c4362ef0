//! Boundary loops of an open triangle mesh.

use std::collections::{HashMap, HashSet};

/// The boundary loops of `triangles`, each in the direction its triangles
/// run along it: the edges used in one direction only, chained.
///
/// ```
/// use tracery_core::mesh::boundary_loops;
/// let loops = boundary_loops(&[[0, 1, 2], [0, 2, 3]]);
/// assert_eq!(loops, vec![vec![0, 1, 2, 3]]);
/// ```
pub fn boundary_loops(triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let directed: HashSet<(u32, u32)> =
        triangles.iter().flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3]))).collect();
    let mut next: HashMap<u32, u32> = HashMap::new();
    for &(a, b) in &directed {
        if !directed.contains(&(b, a)) {
            next.insert(a, b);
        }
    }
    let mut loops = Vec::new();
    let mut starts: Vec<u32> = next.keys().copied().collect();
    starts.sort_unstable();
    let mut seen = HashSet::new();
    for start in starts {
        if seen.contains(&start) {
            continue;
        }
        let mut ring = vec![start];
        seen.insert(start);
        let mut at = next[&start];
        while at != start && seen.insert(at) {
            ring.push(at);
            match next.get(&at) {
                Some(&n) => at = n,
                None => break,
            }
        }
        loops.push(ring);
    }
    loops
}
