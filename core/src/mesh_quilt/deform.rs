//! Laplacian deformation (the paper's equation 5): an element bent to meet
//! position constraints while its Laplacian coordinates, its local shape,
//! stay as they were. A sparse least-squares solve through faer.

use rustc_hash::FxHashMap;

use faer::Mat;
use faer::prelude::Solve;
use faer::sparse::{SparseColMat, Triplet};
use glam::DVec3;

use super::Element;

/// A vertex pulled towards a point, with a weight (the paper's μ).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constraint {
    /// The element's vertex.
    pub vertex: u32,
    /// Where it should go, mm.
    pub target_mm: DVec3,
    /// How strongly, against keeping the shape.
    pub weight: f64,
}

/// Moves `element`'s free vertices to minimize
/// `Σ |L(w) − L(v)|² + Σ weight·|w − target|²` with the uniform Laplacian
/// `L`; the vertices `fixed` says stay where they are, so only the part
/// being worked on is solved for. Returns false, leaving the element as it
/// was, when the solve fails or there is no constraint.
///
/// ```
/// use tracery_core::mesh_quilt::{Constraint, deform, tube};
/// use glam::DVec3;
/// let mut rod = tube(&[DVec3::ZERO, DVec3::X * 5.0, DVec3::X * 10.0], 1.0, 8, false);
/// let pulled: Vec<Constraint> = (0..rod.vertices.len() as u32)
///     .map(|v| Constraint { vertex: v, target_mm: rod.vertices[v as usize] + DVec3::Z, weight: 1.0 })
///     .collect();
/// assert!(deform(&mut rod, &pulled, |_| false));
/// assert!(rod.vertices.iter().all(|v| v.z > -1.0 + 0.999));
/// ```
pub fn deform(element: &mut Element, constraints: &[Constraint], fixed: impl Fn(u32) -> bool) -> bool {
    let n = element.vertices.len();
    let mut unknown = vec![usize::MAX; n];
    let mut count = 0;
    for (v, slot) in unknown.iter_mut().enumerate() {
        if !fixed(v as u32) {
            *slot = count;
            count += 1;
        }
    }
    let constraints: Vec<&Constraint> =
        constraints.iter().filter(|c| unknown[c.vertex as usize] != usize::MAX).collect();
    if constraints.is_empty() || count == 0 {
        return false;
    }
    let ring = element.neighbours();
    let mut normal: FxHashMap<(usize, usize), f64> = FxHashMap::default();
    let mut rhs = Mat::<f64>::zeros(count, 3);
    // Rows of L (the vertex minus the mean of its neighbours) that touch a
    // free vertex; fixed vertices in them move to the right-hand side.
    for i in 0..n {
        if unknown[i] == usize::MAX && ring[i].iter().all(|&j| unknown[j as usize] == usize::MAX) {
            continue;
        }
        let mut entries = vec![(i, 1.0)];
        if !ring[i].is_empty() {
            let w = 1.0 / ring[i].len() as f64;
            entries.extend(ring[i].iter().map(|&j| (j as usize, -w)));
        }
        let mut target: DVec3 = entries.iter().map(|&(j, w)| element.vertices[j] * w).sum();
        for &(j, w) in &entries {
            if unknown[j] == usize::MAX {
                target -= element.vertices[j] * w;
            }
        }
        for &(a, wa) in entries.iter().filter(|(a, _)| unknown[*a] != usize::MAX) {
            let ra = unknown[a];
            for &(b, wb) in entries.iter().filter(|(b, _)| unknown[*b] != usize::MAX) {
                *normal.entry((ra, unknown[b])).or_default() += wa * wb;
            }
            for k in 0..3 {
                rhs[(ra, k)] += wa * target[k];
            }
        }
    }
    for c in constraints {
        let v = unknown[c.vertex as usize];
        *normal.entry((v, v)).or_default() += c.weight;
        for k in 0..3 {
            rhs[(v, k)] += c.weight * c.target_mm[k];
        }
    }
    let mut entries: Vec<((usize, usize), f64)> = normal.into_iter().collect();
    // In a fixed order, so the factorization is the same on every run.
    entries.sort_unstable_by_key(|&(key, _)| key);
    let triplets: Vec<Triplet<usize, usize, f64>> = entries.iter().map(|&((r, c), w)| Triplet::new(r, c, w)).collect();
    let Ok(matrix) = SparseColMat::<usize, f64>::try_new_from_triplets(count, count, &triplets) else {
        return false;
    };
    // Normal equations: symmetric, and positive definite once anything is
    // held (a fixed neighbour or a constraint); Cholesky on the lower side
    // is several times cheaper than LU, and refuses what LU would get wrong.
    let Ok(llt) = matrix.sp_cholesky(faer::Side::Lower) else {
        return false;
    };
    let solved = llt.solve(&rhs);
    let mut moved = element.vertices.clone();
    for v in 0..n {
        if unknown[v] != usize::MAX {
            let r = unknown[v];
            moved[v] = DVec3::new(solved[(r, 0)], solved[(r, 1)], solved[(r, 2)]);
        }
    }
    if moved.iter().any(|v| !v.is_finite()) {
        return false;
    }
    element.vertices = moved;
    true
}
