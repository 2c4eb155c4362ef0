//! [`Mesh::sanity_check`]: a closed, consistently oriented 2-manifold.

use std::collections::HashMap;

use super::Mesh;

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
        let mut directed: HashMap<(u32, u32), usize> = HashMap::with_capacity(3 * self.triangles.len());
        for (t, tri) in self.triangles.iter().enumerate() {
            if let Some(&vertex) = tri.iter().find(|&&i| i as usize >= self.vertices.len()) {
                return Err(MeshDefect::BadIndex { triangle: t, vertex, vertices: self.vertices.len() });
            }
            if tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] {
                return Err(MeshDefect::Degenerate { triangle: t });
            }
            for k in 0..3 {
                *directed.entry((tri[k], tri[(k + 1) % 3])).or_default() += 1;
            }
        }
        for (&(a, b), &forward) in &directed {
            let backward = directed.get(&(b, a)).copied().unwrap_or(0);
            if forward != 1 || backward != 1 {
                return Err(MeshDefect::Edge { a, b, forward, backward });
            }
        }
        Ok(())
    }
}
