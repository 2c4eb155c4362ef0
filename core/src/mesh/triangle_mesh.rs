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
    /// Each triangle's shell (groups of triangles connected through shared
    /// edges), as the index of one triangle of that shell.
    fn shell_of_triangles(&self) -> Vec<usize> {
        let n = self.triangles.len();
        let mut sets = crate::disjoint_sets::DisjointSets::new(n);
        // Each edge listed under its lower vertex with its triangle, so that
        // the triangles of an edge are neighbours in that vertex's sorted
        // list. A hash map keyed by edge did the same, and was a tenth of a
        // corpus sweep.
        let edges = || {
            self.triangles.iter().enumerate().flat_map(|(t, tri)| {
                (0..3).map(move |k| {
                    let (a, b) = (tri[k], tri[(k + 1) % 3]);
                    (a.min(b), (a.max(b), t as u32))
                })
            })
        };
        for list in super::by_vertex::ByVertex::new(self.vertices.len(), edges).lists() {
            for w in list.windows(2) {
                if w[0].0 == w[1].0 {
                    sets.join(w[0].1 as usize, w[1].1 as usize);
                }
            }
        }
        (0..n).map(|t| sets.find(t)).collect()
    }

    /// Number of shells: groups of triangles connected through shared edges.
    pub fn shell_count(&self) -> usize {
        self.shell_of_triangles().iter().enumerate().filter(|&(t, &s)| s == t).count()
    }

    /// Removes the shells enclosing less than `min_volume_mm3` (crumbs no
    /// printer can make, such as the slivers a boolean leaves where two
    /// surfaces nearly touch), with the vertices only they used; returns
    /// how many were removed.
    ///
    /// ```
    /// use tracery_core::mesh::Mesh;
    /// let tetra = |s: f64, x: f64| Mesh {
    ///     vertices: vec![[x, 0.0, 0.0], [x + s, 0.0, 0.0], [x, s, 0.0], [x, 0.0, s]],
    ///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    /// };
    /// let mut both = tetra(3.0, 0.0);
    /// both.append(&tetra(0.01, 10.0));
    /// assert_eq!(both.remove_crumbs(1e-3), 1);
    /// assert_eq!((both.shell_count(), both.vertices.len()), (1, 4));
    /// ```
    pub fn remove_crumbs(&mut self, min_volume_mm3: f64) -> usize {
        self.remove_shells(|volume_mm3| volume_mm3.abs() < min_volume_mm3)
    }

    /// Fills the cavities: removes the shells facing inward (a negative
    /// volume), each the wall of a pocket sealed inside the solid, as the
    /// union of solids that together enclose some air leaves; returns how
    /// many were removed. The solid is the same seen from outside, and
    /// prints as one body with no air trapped in it. Only for a mesh whose
    /// shells all face out but for such walls.
    ///
    /// ```
    /// use tracery_core::mesh::Mesh;
    /// let tetra = |s: f64| Mesh {
    ///     vertices: vec![[0.0, 0.0, 0.0], [s, 0.0, 0.0], [0.0, s, 0.0], [0.0, 0.0, s]],
    ///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    /// };
    /// // A small tetrahedron facing in, inside a large one: a hollow.
    /// let mut hollow = tetra(6.0);
    /// let mut pocket = tetra(1.0);
    /// pocket.vertices.iter_mut().flatten().for_each(|c| *c += 1.0);
    /// pocket.triangles.iter_mut().for_each(|t| t.swap(1, 2));
    /// hollow.append(&pocket);
    /// assert_eq!(hollow.fill_cavities(), 1);
    /// assert_eq!((hollow.shell_count(), hollow.vertices.len()), (1, 4));
    /// assert!((hollow.signed_volume() - 36.0).abs() < 1e-9);
    /// ```
    pub fn fill_cavities(&mut self) -> usize {
        self.remove_shells(|volume_mm3| volume_mm3 < 0.0)
    }

    /// Removes the shells whose signed volume (mm³) `remove` picks, with
    /// the vertices only they used; returns how many were removed.
    fn remove_shells(&mut self, remove: impl Fn(f64) -> bool) -> usize {
        let shells = self.shell_of_triangles();
        // Each shell's volume, at the index of the triangle naming it.
        let mut volume = vec![0.0; self.triangles.len()];
        for (t, &shell) in self.triangles.iter().zip(&shells) {
            let [a, b, c] = t.map(|v| glam::DVec3::from(self.vertices[v as usize]));
            volume[shell] += a.dot(b.cross(c)) / 6.0;
        }
        let removed = shells.iter().enumerate().filter(|&(t, &s)| s == t && remove(volume[s])).count();
        if removed == 0 {
            return 0;
        }
        let triangles =
            self.triangles.iter().zip(&shells).filter(|&(_, &s)| !remove(volume[s])).map(|(t, _)| *t).collect();
        let kept = Mesh { vertices: std::mem::take(&mut self.vertices), triangles };
        *self = super::compact(kept).0;
        removed
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

    /// The volume the mesh encloses, mm³: positive when its triangles face
    /// out, negative when they face in.
    ///
    /// ```
    /// use tracery_core::mesh::Mesh;
    /// let tetra = Mesh {
    ///     vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    ///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    /// };
    /// assert!((tetra.signed_volume() - 1.0 / 6.0).abs() < 1e-12);
    /// ```
    pub fn signed_volume(&self) -> f64 {
        let at = |i: u32| glam::DVec3::from_array(self.vertices[i as usize]);
        self.triangles.iter().map(|t| at(t[0]).dot(at(t[1]).cross(at(t[2]))) / 6.0).sum()
    }

    /// Turns every triangle over if the mesh faces in: a map that mirrors
    /// (a sheet bent onto a surface the other way round) leaves it so.
    pub fn orient_outward(&mut self) {
        if self.signed_volume() < 0.0 {
            for t in &mut self.triangles {
                t.swap(1, 2);
            }
        }
    }

    /// Appends `other`'s vertices and triangles (the meshes stay separate shells).
    pub fn append(&mut self, other: &Mesh) {
        let base = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.triangles.extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetrahedron(x: f64) -> Mesh {
        Mesh {
            vertices: vec![[x, 0.0, 0.0], [x + 1.0, 0.0, 0.0], [x, 1.0, 0.0], [x, 0.0, 1.0]],
            triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
        }
    }

    /// Shells meet through edges only: two bodies that share a vertex
    /// print as two, and a cone of many triangles round one apex is one.
    #[test]
    fn shells_are_joined_through_edges_not_through_a_shared_vertex() {
        let mut touching = tetrahedron(0.0);
        touching.append(&tetrahedron(-1.0));
        // The second one's vertex at x = 0 becomes the first one's vertex 0.
        touching.triangles.iter_mut().flatten().for_each(|i| *i = if *i == 5 { 0 } else { *i });
        assert_eq!(touching.shell_count(), 2);

        let sides = 5000u32;
        let mut cone = Mesh { vertices: vec![[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]], triangles: Vec::new() };
        for k in 0..sides {
            let angle = std::f64::consts::TAU * f64::from(k) / f64::from(sides);
            cone.vertices.push([angle.cos(), angle.sin(), 0.0]);
            let (a, b) = (2 + k, 2 + (k + 1) % sides);
            cone.triangles.push([0, a, b]);
            cone.triangles.push([1, b, a]);
        }
        assert_eq!(cone.shell_count(), 1);
        assert_eq!(cone.sanity_check(), Ok(()));
    }
}
