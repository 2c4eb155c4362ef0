//! Whether the shell would spoil an element as a patch lays it. The shell
//! carries a swatch element round a sharp crease of the model (a top's rim,
//! where the swatch is too wide for the top to be quilted on its own) by
//! folding it there, and stretches its upper part unevenly beside one: the
//! element comes out crumpled, torn into long triangles, or through itself.
//! Such an element is not laid; a thread running across the swatch is (it
//! bends with the model, is cut at a flat top's rim, and is cut and
//! stitched where it meets its neighbours). Applied to such threads too,
//! the test left a tenth of the bellied post of
//! `woven_threads_leave_few_holes_round_a_bellied_base` bare: its weave
//! wraps creases of 30° to 36° and the rim of a top too narrow to be
//! quilted on its own. A short thread (a leaf) is tested as a compact
//! element is: leaves were folded jagged over the vase's rim.

use glam::DVec3;

use super::Element;

/// Elements are not laid where the base's normal turns by more than this
/// many degrees along one of their edges: a crease, not a curve.
///
/// Scales laid on the vase, the cylinder and the cone turn by 45° or more
/// round the rims and by 17° at most elsewhere (the egg's tip, the torus's
/// hole), and by 7° on the sphere.
pub const MAX_FOLD_DEG: f64 = 35.0;

/// Elements whose edges stretch more unevenly than this are not laid: the
/// largest or smallest edge stretch against the element's median one.
///
/// Beside the cylinder's rim, chain-mail links on its top spread 3 to 3.9;
/// links at the vase's concave neck are squashed unevenly up to 2.7 and
/// still read as links.
pub const MAX_STRETCH_SPREAD: f64 = 3.0;

/// The spread of edge stretches of `element` laid at `placed_mm` (the same
/// vertices moved): the largest of the highest stretch over the median
/// and the median over the lowest, 1 for an element moved rigidly or
/// scaled evenly. Only edges both of whose ends (vertex indices) `counts`
/// take part: what a later cut removes (below the floor) does not.
///
/// ```
/// use tracery_core::mesh_quilt::{Element, stretch_spread};
/// use glam::DVec3;
/// let tetra = Element {
///     vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
/// };
/// let doubled: Vec<DVec3> = tetra.vertices.iter().map(|&v| 2.0 * v + DVec3::X).collect();
/// assert!((stretch_spread(&tetra, &doubled, |_| true) - 1.0).abs() < 1e-12);
/// let pulled: Vec<DVec3> = tetra.vertices.iter().map(|&v| v * DVec3::new(1.0, 1.0, 5.0)).collect();
/// assert!(stretch_spread(&tetra, &pulled, |_| true) > 3.0);
/// ```
pub fn stretch_spread(element: &Element, placed_mm: &[DVec3], counts: impl Fn(usize) -> bool) -> f64 {
    let mut stretches: Vec<f64> = Vec::with_capacity(3 * element.triangles.len());
    for (a, b) in counted_edges(element, &counts) {
        let before = element.vertices[a].distance(element.vertices[b]);
        if before > 0.0 {
            stretches.push(placed_mm[a].distance(placed_mm[b]) / before);
        }
    }
    if stretches.is_empty() {
        return 1.0;
    }
    stretches.sort_unstable_by(f64::total_cmp);
    let median = stretches[stretches.len() / 2];
    let (low, high) = (stretches[0], stretches[stretches.len() - 1]);
    if low <= 0.0 {
        return f64::INFINITY;
    }
    (high / median).max(median / low)
}

/// The largest turn, degrees, between the base's normals under the two
/// ends of one edge of `element`, laid with its vertex `k` over the base
/// face whose unit normal is `normals[k]`: near 0 on a smooth base, the
/// crease's angle where an edge straddles a sharp crease (a rim), which
/// the shell folds the element round. Edges either of whose ends `counts`
/// refuses are left out, as in [`stretch_spread`].
///
/// ```
/// use tracery_core::mesh_quilt::{Element, largest_fold_deg};
/// use glam::DVec3;
/// let strip = Element { vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y], triangles: vec![[0, 1, 2]] };
/// let flat = [DVec3::Z; 3];
/// assert!(largest_fold_deg(&strip, &flat, |_| true) < 1e-6);
/// let over_a_rim = [DVec3::Z, DVec3::X, DVec3::Z];
/// assert!((largest_fold_deg(&strip, &over_a_rim, |_| true) - 90.0).abs() < 1e-6);
/// ```
pub fn largest_fold_deg(element: &Element, normals: &[DVec3], counts: impl Fn(usize) -> bool) -> f64 {
    counted_edges(element, &counts)
        .map(|(a, b)| normals[a].dot(normals[b]).clamp(-1.0, 1.0).acos().to_degrees())
        .fold(0.0, f64::max)
}

/// The edges of `element` both of whose ends `counts` takes, each once:
/// every edge is shared by two triangles, and is taken from the one where
/// it runs from the lower corner.
fn counted_edges<'a>(
    element: &'a Element,
    counts: &'a impl Fn(usize) -> bool,
) -> impl Iterator<Item = (usize, usize)> + 'a {
    element
        .triangles
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k] as usize, t[(k + 1) % 3] as usize)))
        .filter(move |&(a, b)| a < b && counts(a) && counts(b))
}
