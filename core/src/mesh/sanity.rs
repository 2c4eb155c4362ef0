//! [`Mesh::sanity_check`]: a closed, consistently oriented 2-manifold.

use super::Mesh;
use super::by_vertex::ByVertex;

/// What is wrong with a mesh.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshDefect {
    /// A triangle refers to a vertex that does not exist.
    #[error("triangle {triangle} refers to vertex {vertex}, but there are {vertices} vertices")]
    BadIndex {
        /// Triangle index.
        triangle: usize,
        /// The index.
        vertex: u32,
        /// Vertices in the mesh.
        vertices: usize,
    },
    /// A triangle uses a vertex twice.
    #[error("triangle {triangle} uses a vertex twice")]
    Degenerate {
        /// Triangle index.
        triangle: usize,
    },
    /// A vertex coordinate is not a finite number.
    #[error("vertex {vertex} has a coordinate that is not a finite number")]
    NotFinite {
        /// Vertex index.
        vertex: usize,
    },
    /// An edge is used other than once in each direction: a hole in the
    /// surface, a flipped triangle, or more than two triangles on one edge.
    #[error(
        "edge {a}-{b} is used {forward} time(s) from {a} to {b} and {backward} time(s) back; a closed surface uses it once each way"
    )]
    Edge {
        /// One end.
        a: u32,
        /// The other end.
        b: u32,
        /// Uses from `a` to `b`.
        forward: usize,
        /// Uses from `b` to `a`.
        backward: usize,
    },
}

impl Mesh {
    /// Checks that every edge is used exactly twice, once in each direction
    /// (closed, 2-manifold at edges, consistently oriented), that every index
    /// is valid and no triangle is degenerate by index.
    ///
    /// ```
    /// use tracery_core::mesh::Mesh;
    /// // A tetrahedron, faces counter-clockwise seen from outside.
    /// let mesh = Mesh {
    ///     vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    ///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    /// };
    /// assert!(mesh.sanity_check().is_ok());
    /// let open = Mesh { triangles: mesh.triangles[..3].to_vec(), ..mesh };
    /// assert!(open.sanity_check().is_err());
    /// ```
    pub fn sanity_check(&self) -> Result<(), MeshDefect> {
        if let Some(vertex) = self.vertices.iter().position(|v| v.iter().any(|x| !x.is_finite())) {
            return Err(MeshDefect::NotFinite { vertex });
        }
        for (t, tri) in self.triangles.iter().enumerate() {
            if let Some(&vertex) = tri.iter().find(|&&i| i as usize >= self.vertices.len()) {
                return Err(MeshDefect::BadIndex { triangle: t, vertex, vertices: self.vertices.len() });
            }
            if tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] {
                return Err(MeshDefect::Degenerate { triangle: t });
            }
        }
        // Each vertex's outgoing edges in one flat array, so that both
        // directions of an edge are found in two short lists. A hash map of
        // directed edges did the same and took 40 % of a corpus sweep on
        // dense loops.
        let edges = || self.triangles.iter().flat_map(|tri| (0..3).map(move |k| (tri[k], tri[(k + 1) % 3])));
        let leaving = ByVertex::new(self.vertices.len(), edges);
        let uses = |a: u32, b: u32| {
            let out = leaving.of(a);
            out.partition_point(|&t| t <= b) - out.partition_point(|&t| t < b)
        };
        for tri in &self.triangles {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let (forward, backward) = (uses(a, b), uses(b, a));
                if forward != 1 || backward != 1 {
                    return Err(MeshDefect::Edge { a, b, forward, backward });
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetrahedron() -> Mesh {
        Mesh {
            vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
        }
    }

    /// Uses of the directed edge `a → b`, counted the plain way.
    fn uses(mesh: &Mesh, a: u32, b: u32) -> usize {
        mesh.triangles.iter().flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3]))).filter(|&e| e == (a, b)).count()
    }

    #[test]
    fn each_defect_names_an_edge_with_its_true_counts() {
        let mut flipped = tetrahedron();
        flipped.triangles[2] = [1, 3, 2];
        let mut doubled = tetrahedron();
        doubled.triangles.push([0, 2, 1]);
        let mut open = tetrahedron();
        open.triangles.pop();
        let mut two_bodies = tetrahedron();
        two_bodies.vertices.extend([[5.0, 0.0, 0.0], [6.0, 0.0, 0.0], [5.0, 1.0, 0.0], [5.0, 0.0, 1.0]]);
        two_bodies.triangles.extend(tetrahedron().triangles.iter().map(|t| t.map(|i| i + 4)));
        assert_eq!(two_bodies.sanity_check(), Ok(()));
        let mut bad_index = tetrahedron();
        bad_index.triangles[1] = [0, 1, 7];
        assert_eq!(bad_index.sanity_check(), Err(MeshDefect::BadIndex { triangle: 1, vertex: 7, vertices: 4 }));
        let mut degenerate = tetrahedron();
        degenerate.triangles[3] = [0, 3, 0];
        assert_eq!(degenerate.sanity_check(), Err(MeshDefect::Degenerate { triangle: 3 }));
        for (name, mesh) in [("flipped", flipped), ("doubled", doubled), ("open", open)] {
            match mesh.sanity_check() {
                Err(MeshDefect::Edge { a, b, forward, backward }) => {
                    assert_eq!((forward, backward), (uses(&mesh, a, b), uses(&mesh, b, a)), "{name}");
                    assert!(forward != 1 || backward != 1, "{name}: {a}-{b} is sound");
                }
                other => panic!("{name}: {other:?}"),
            }
        }
    }
}
