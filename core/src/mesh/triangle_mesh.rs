//! The triangle mesh type shared by every mode, and its shells.

/// A triangle mesh in millimetres.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub vertices: Vec<[f64; 3]>,
    /// Triangles as vertex indices, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// Number of shells: groups of triangles connected through shared edges.
    pub fn shell_count(&self) -> usize {
        let n = self.triangles.len();
        let mut parent: Vec<usize> = (0..n).collect();
        fn find(parent: &mut [usize], mut x: usize) -> usize {
            while parent[x] != x {
                parent[x] = parent[parent[x]];
                x = parent[x];
            }
            x
        }
        let mut by_edge: std::collections::HashMap<(u32, u32), usize> = std::collections::HashMap::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let key = (a.min(b), a.max(b));
                if let Some(&other) = by_edge.get(&key) {
                    let (ra, rb) = (find(&mut parent, t), find(&mut parent, other));
                    parent[ra] = rb;
                } else {
                    by_edge.insert(key, t);
                }
            }
        }
        (0..n).filter(|&t| find(&mut parent, t) == t).count()
    }
}

impl Mesh {
    /// The triangles facing up at the top (`z` = the highest `z`), projected
    /// onto the plane: the region's fill, for drawing it.
    pub fn top_faces(&self) -> Vec<[glam::DVec2; 3]> {
        let top = self.top_z();
        self.triangles
            .iter()
            .filter(|t| t.iter().all(|&i| self.vertices[i as usize][2] == top))
            .map(|t| t.map(|i| glam::DVec2::new(self.vertices[i as usize][0], self.vertices[i as usize][1])))
            .collect()
    }

    /// The highest `z` of any vertex (negative infinity when there is none):
    /// an extruded pattern's thickness.
    pub fn top_z(&self) -> f64 {
        self.vertices.iter().map(|v| v[2]).fold(f64::NEG_INFINITY, f64::max)
    }

    /// Appends `other`'s vertices and triangles (the meshes stay separate shells).
    pub fn append(&mut self, other: &Mesh) {
        let base = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.triangles.extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }
}
