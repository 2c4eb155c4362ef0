//! An STL check written apart from the mesh code: parse the binary file,
//! weld vertices by their exact coordinates, and look at every edge.

#![allow(dead_code)]

use std::collections::HashMap;
use std::path::Path;

/// What the STL check finds, computed from the file alone.
#[derive(Debug)]
pub struct StlCheck {
    pub triangles: usize,
    pub shells: usize,
    /// Edges not shared by exactly two triangles.
    pub open_edges: usize,
    /// Edges whose two triangles run the same way along them.
    pub misoriented_edges: usize,
    /// Vertices less edges plus triangles: 2 per shell less 2 per handle
    /// (a hole through a pattern is a handle of its solid).
    pub euler: i64,
}

pub fn check_stl(path: &Path) -> StlCheck {
    let data = std::fs::read(path).unwrap();
    assert!(data.len() >= 84, "STL too short");
    let count = u32::from_le_bytes(data[80..84].try_into().unwrap()) as usize;
    assert_eq!(data.len(), 84 + 50 * count, "binary STL size does not match its triangle count");
    let mut ids: HashMap<[u32; 3], u32> = HashMap::new();
    let mut triangles = Vec::with_capacity(count);
    for t in 0..count {
        let base = 84 + 50 * t + 12;
        let mut tri = [0u32; 3];
        for (k, slot) in tri.iter_mut().enumerate() {
            let at = base + 12 * k;
            let key: [u32; 3] =
                std::array::from_fn(|c| u32::from_le_bytes(data[at + 4 * c..at + 4 * c + 4].try_into().unwrap()));
            let next = ids.len() as u32;
            *slot = *ids.entry(key).or_insert(next);
        }
        triangles.push(tri);
    }
    // Directed edge counts: a closed, consistently oriented 2-manifold uses
    // each edge once in each direction.
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    for tri in &triangles {
        for k in 0..3 {
            *directed.entry((tri[k], tri[(k + 1) % 3])).or_default() += 1;
        }
    }
    let mut open_edges = 0;
    let mut misoriented_edges = 0;
    for (&(a, b), &n) in &directed {
        let back = directed.get(&(b, a)).copied().unwrap_or(0);
        if n > 1 {
            misoriented_edges += 1;
        }
        if back != 1 || n != 1 {
            open_edges += 1;
        }
    }
    // Shells: triangles connected through shared edges.
    let mut parent: Vec<usize> = (0..triangles.len()).collect();
    fn find(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    let mut owner: HashMap<(u32, u32), usize> = HashMap::new();
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            match owner.get(&(a.min(b), a.max(b))) {
                Some(&o) => {
                    let (x, y) = (find(&mut parent, t), find(&mut parent, o));
                    parent[x] = y;
                }
                None => {
                    owner.insert((a.min(b), a.max(b)), t);
                }
            }
        }
    }
    let shells = (0..triangles.len()).filter(|&t| find(&mut parent, t) == t).count();
    let euler = ids.len() as i64 - owner.len() as i64 + count as i64;
    StlCheck { triangles: count, shells, open_edges, misoriented_edges, euler }
}

/// Every vertex of a binary STL, three per triangle, in file order.
pub fn stl_vertices(path: &Path) -> Vec<[f64; 3]> {
    let data = std::fs::read(path).unwrap();
    let count = u32::from_le_bytes(data[80..84].try_into().unwrap()) as usize;
    let f = |at: usize| f64::from(f32::from_le_bytes(data[at..at + 4].try_into().unwrap()));
    (0..count)
        .flat_map(|t| (0..3).map(move |k| 84 + 50 * t + 12 + 12 * k))
        .map(|at| [f(at), f(at + 4), f(at + 8)])
        .collect()
}
