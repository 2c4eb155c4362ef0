//! The 1-rings of a triangle mesh's vertices.

/// For each of `vertex_count` vertices, the vertices sharing an edge with
/// it in `triangles`, sorted.
///
/// ```
/// use tracery_core::mesh::vertex_rings;
/// let rings = vertex_rings(4, &[[0, 1, 2], [0, 2, 3]]);
/// assert_eq!(rings[0], vec![1, 2, 3]);
/// assert_eq!(rings[1], vec![0, 2]);
/// ```
pub fn vertex_rings(vertex_count: usize, triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let mut ring: Vec<Vec<u32>> = vec![Vec::new(); vertex_count];
    for t in triangles {
        for k in 0..3 {
            ring[t[k] as usize].push(t[(k + 1) % 3]);
            ring[t[(k + 1) % 3] as usize].push(t[k]);
        }
    }
    for r in &mut ring {
        r.sort_unstable();
        r.dedup();
    }
    ring
}
