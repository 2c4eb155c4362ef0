//! Which faces of a constrained Delaunay triangulation of rings lie inside
//! them.

use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

/// For each face of `cdt` (by fixed index), whether it is filled, when its
/// constraint edges are the edges of rings filled even-odd: a flood from
/// the outer face that toggles at every constraint edge. `None` for the
/// outer face and any face the flood cannot reach.
pub(crate) fn faces_inside(cdt: &ConstrainedDelaunayTriangulation<Point2<f64>>) -> Vec<Option<bool>> {
    let mut inside: Vec<Option<bool>> = vec![None; cdt.all_faces().len()];
    let mut queue = std::collections::VecDeque::new();
    for hull_edge in cdt.convex_hull() {
        for e in [hull_edge, hull_edge.rev()] {
            if let Some(face) = e.face().as_inner()
                && inside[face.fix().index()].is_none()
            {
                inside[face.fix().index()] = Some(e.as_undirected().is_constraint_edge());
                queue.push_back(face.fix());
            }
        }
    }
    while let Some(fixed) = queue.pop_front() {
        let face = cdt.face(fixed);
        let here = inside[fixed.index()].unwrap_or(false);
        for edge in face.adjacent_edges() {
            let Some(neighbour) = edge.rev().face().as_inner() else { continue };
            let slot = &mut inside[neighbour.fix().index()];
            if slot.is_none() {
                *slot = Some(here != edge.as_undirected().is_constraint_edge());
                queue.push_back(neighbour.fix());
            }
        }
    }
    inside
}
