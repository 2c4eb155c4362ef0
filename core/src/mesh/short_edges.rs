//! Edges far shorter than anything printed, collapsed: a boolean can leave
//! corners a fraction of a micrometre apart where two surfaces nearly meet,
//! and once an STL rounds them to `f32` they fall together and the file
//! reads as edges shared by four faces.

use glam::DVec3;

use super::{Mesh, compact};

/// Edges shorter than this are collapsed after a boolean, mm: a tenth of a
/// micrometre, far below what a printer makes, and far above the `f32`
/// rounding of an STL's coordinates at a model's size (about 4e-6 mm at
/// 50 mm).
pub const MIN_EDGE_MM: f64 = 1e-4;

/// Collapses every edge of the closed, manifold `mesh` shorter than
/// `min_edge_mm` into its midpoint, where that keeps the mesh closed and
/// manifold (the edge's two ends share no neighbour but the corners
/// opposite it) and turns no other triangle over; returns how many were
/// collapsed. The two triangles on each collapsed edge are removed.
///
/// ```
/// use tracery_core::mesh::{Mesh, collapse_short_edges};
/// // A tetrahedron whose edge from corner 1 to corner 3 is split 1 nm
/// // from corner 1, as a boolean can leave it.
/// let mut mesh = Mesh {
///     vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0 - 1e-6, 0.0, 1e-6]],
///     triangles: vec![[0, 2, 1], [0, 1, 4], [0, 4, 3], [1, 2, 4], [4, 2, 3], [0, 3, 2]],
/// };
/// assert_eq!(collapse_short_edges(&mut mesh, 1e-4), 1);
/// assert_eq!((mesh.vertices.len(), mesh.triangles.len()), (4, 4));
/// assert!(mesh.sanity_check().is_ok());
/// assert!((mesh.signed_volume() - 1.0 / 6.0).abs() < 1e-6);
/// ```
pub fn collapse_short_edges(mesh: &mut Mesh, min_edge_mm: f64) -> usize {
    let position = |mesh: &Mesh, v: u32| DVec3::from_array(mesh.vertices[v as usize]);
    let mut short: Vec<(f64, u32, u32)> = Vec::new();
    for t in &mesh.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let length = position(mesh, a).distance(position(mesh, b));
            // Each edge once: from its lower corner.
            if a < b && length < min_edge_mm {
                short.push((length, a, b));
            }
        }
    }
    if short.is_empty() {
        return 0;
    }
    short.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut around: Vec<Vec<u32>> = vec![Vec::new(); mesh.vertices.len()];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for &v in tri {
            around[v as usize].push(t as u32);
        }
    }
    let mut alive = vec![true; mesh.triangles.len()];
    let mut collapsed = 0;
    for (_, a, b) in short {
        let live = |around: &[u32], alive: &[bool]| around.iter().copied().filter(|&t| alive[t as usize]).collect();
        let (at_a, at_b): (Vec<u32>, Vec<u32>) = (live(&around[a as usize], &alive), live(&around[b as usize], &alive));
        let on_edge: Vec<u32> = at_a.iter().copied().filter(|t| at_b.contains(t)).collect();
        // Gone with an earlier collapse, or longer now that an end moved.
        if on_edge.len() != 2 || position(mesh, a).distance(position(mesh, b)) >= min_edge_mm {
            continue;
        }
        let neighbours = |faces: &[u32], v: u32| -> Vec<u32> {
            let mut n: Vec<u32> = faces.iter().flat_map(|&t| mesh.triangles[t as usize]).filter(|&u| u != v).collect();
            n.sort_unstable();
            n.dedup();
            n
        };
        let (near_a, near_b) = (neighbours(&at_a, a), neighbours(&at_b, b));
        let shared = near_a.iter().filter(|u| near_b.contains(u)).count();
        // The link condition: only the two corners opposite the edge are
        // next to both ends; otherwise the collapse would pinch the mesh.
        if shared != 2 {
            continue;
        }
        let middle = 0.5 * (position(mesh, a) + position(mesh, b));
        let turns_over = at_a.iter().chain(&at_b).filter(|t| !on_edge.contains(t)).any(|&t| {
            let tri = mesh.triangles[t as usize];
            let [p, q, r] = tri.map(|v| position(mesh, v));
            let moved = tri.map(|v| if v == a || v == b { middle } else { position(mesh, v) });
            (q - p).cross(r - p).dot((moved[1] - moved[0]).cross(moved[2] - moved[0])) < 0.0
        });
        if turns_over {
            continue;
        }
        mesh.vertices[a as usize] = middle.to_array();
        for &t in &on_edge {
            alive[t as usize] = false;
        }
        for &t in &at_b {
            if alive[t as usize] {
                for v in &mut mesh.triangles[t as usize] {
                    if *v == b {
                        *v = a;
                    }
                }
                around[a as usize].push(t);
            }
        }
        collapsed += 1;
    }
    let triangles = mesh.triangles.iter().zip(&alive).filter(|&(_, &keep)| keep).map(|(t, _)| *t).collect();
    *mesh = compact(Mesh { vertices: std::mem::take(&mut mesh.vertices), triangles }).0;
    collapsed
}
