//! Splitting a mesh's coarse edges, so that a mapping applied to its vertices
//! (a flat sheet wrapped onto a curved surface) bends it smoothly instead of
//! cutting chords through the surface.

use std::collections::{HashMap, HashSet};

use super::Mesh;

/// Most rounds of splitting: each round halves every edge still too long,
/// so 24 rounds take an edge down by a factor of 16 million.
const MAX_ROUNDS: usize = 24;

/// Splits every edge for which `too_coarse` holds at its midpoint, round
/// after round, until it holds for none. `too_coarse` sees an edge's two
/// vertex positions, so the caller can judge it where the mesh will end up
/// (how far a wrapped edge strays from its chord) while the midpoints are
/// taken where it is now.
///
/// Each edge is judged once: one found fine is not asked about again in
/// later rounds (the caller's test may be dear, such as a ray cast).
///
/// An edge is split in every triangle that holds it at the same new vertex,
/// so a closed, manifold mesh stays closed and manifold, with the same
/// orientation and the same shells.
///
/// ```
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::mesh::{extrude, split_edges};
/// use tracery_core::DVec2;
/// let square = vec![DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0), DVec2::new(10.0, 10.0), DVec2::new(0.0, 10.0)];
/// let mesh = extrude(&Region::new(vec![Polygon { outer: square, holes: vec![] }]), 1.0).unwrap();
/// let distance = |a: [f64; 3], b: [f64; 3]| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
/// let fine = split_edges(&mesh, |a, b| distance(a, b) > 2.0);
/// assert!(fine.sanity_check().is_ok());
/// assert_eq!(fine.shell_count(), 1);
/// assert!(fine.triangles.iter().all(|t| (0..3).all(|k| distance(fine.vertices[t[k] as usize], fine.vertices[t[(k + 1) % 3] as usize]) <= 2.0)));
/// ```
pub fn split_edges(mesh: &Mesh, too_coarse: impl Fn([f64; 3], [f64; 3]) -> bool) -> Mesh {
    split_edges_tracked(mesh, too_coarse).0
}

/// [`split_edges`], with each new triangle's triangle in `mesh` (its
/// index), so that what the caller keeps per triangle carries over.
///
/// ```
/// use tracery_core::mesh::{Mesh, split_edges_tracked};
/// let two = Mesh {
///     vertices: vec![[0.0, 0.0, 0.0], [8.0, 0.0, 0.0], [8.0, 8.0, 0.0], [0.0, 8.0, 0.0]],
///     triangles: vec![[0, 1, 2], [0, 2, 3]],
/// };
/// let (fine, parents) = split_edges_tracked(&two, |a, b| (a[0] - b[0]).hypot(a[1] - b[1]) > 5.0);
/// assert_eq!(parents.len(), fine.triangles.len());
/// // Each new triangle lies inside the one it came from: the first
/// // triangle is under the diagonal (x ≥ y), the second above it.
/// for (t, &parent) in fine.triangles.iter().zip(&parents) {
///     let centre = t.map(|v| fine.vertices[v as usize]).iter().fold([0.0; 2], |c, p| [c[0] + p[0] / 3.0, c[1] + p[1] / 3.0]);
///     assert_eq!(parent == 0, centre[0] > centre[1]);
/// }
/// ```
pub fn split_edges_tracked(mesh: &Mesh, too_coarse: impl Fn([f64; 3], [f64; 3]) -> bool) -> (Mesh, Vec<u32>) {
    let mut out = mesh.clone();
    let mut parents: Vec<u32> = (0..mesh.triangles.len() as u32).collect();
    let mut fine_enough: HashSet<(u32, u32)> = HashSet::new();
    for _ in 0..MAX_ROUNDS {
        // The new vertex of every edge that is too long, by its ends in order.
        let mut midpoints: HashMap<(u32, u32), u32> = HashMap::new();
        for t in &out.triangles {
            for k in 0..3 {
                let (a, b) = (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]));
                if midpoints.contains_key(&(a, b)) || fine_enough.contains(&(a, b)) {
                    continue;
                }
                let (pa, pb) = (out.vertices[a as usize], out.vertices[b as usize]);
                if !too_coarse(pa, pb) {
                    fine_enough.insert((a, b));
                } else {
                    let middle = [0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])];
                    out.vertices.push(middle);
                    midpoints.insert((a, b), out.vertices.len() as u32 - 1);
                }
            }
        }
        if midpoints.is_empty() {
            break;
        }
        let middle = |a: u32, b: u32| midpoints.get(&(a.min(b), a.max(b))).copied();
        let mut triangles = Vec::with_capacity(out.triangles.len() * 2);
        let mut new_parents = Vec::with_capacity(out.triangles.len() * 2);
        for (&[a, b, c], &parent) in out.triangles.iter().zip(&parents) {
            split_triangle([a, b, c], [middle(a, b), middle(b, c), middle(c, a)], &mut triangles);
            new_parents.resize(triangles.len(), parent);
        }
        out.triangles = triangles;
        parents = new_parents;
    }
    (out, parents)
}

/// Splits triangle `[a, b, c]` at the midpoints it has (`m[0]` on `ab`,
/// `m[1]` on `bc`, `m[2]` on `ca`), keeping its orientation: four triangles
/// for three midpoints, three for two, two for one.
fn split_triangle(t: [u32; 3], m: [Option<u32>; 3], out: &mut Vec<[u32; 3]>) {
    match m {
        [None, None, None] => out.push(t),
        [Some(ab), Some(bc), Some(ca)] => {
            let [a, b, c] = t;
            out.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        _ => {
            // Turn the triangle so that its first split edge is `ab`.
            let first = (0..3).find(|&k| m[k].is_some() && m[(k + 2) % 3].is_none()).unwrap_or(0);
            let [a, b, c] = [t[first], t[(first + 1) % 3], t[(first + 2) % 3]];
            let [mab, mbc, _] = [m[first], m[(first + 1) % 3], m[(first + 2) % 3]];
            let Some(ab) = mab else { return out.push(t) };
            match mbc {
                // Two midpoints, on ab and bc.
                Some(bc) => out.extend([[a, ab, c], [ab, bc, c], [ab, b, bc]]),
                // One midpoint, on ab.
                None => out.extend([[a, ab, c], [ab, b, c]]),
            }
        }
    }
}
