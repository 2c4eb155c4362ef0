//! [`Element`]: one geometric element of a swatch or of the output, a
//! connected triangle mesh (a chain link, a thread, a rivet).

use rustc_hash::FxHashMap;

use glam::{DVec2, DVec3};

use crate::mesh::Mesh;

/// A connected triangle mesh in millimetres, `z` up (the shell's height).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Element {
    /// Vertex positions, mm.
    pub vertices: Vec<DVec3>,
    /// Triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

impl Element {
    /// The element moved by `offset_mm`.
    pub fn translated(&self, offset_mm: DVec3) -> Element {
        Element { vertices: self.vertices.iter().map(|&v| v + offset_mm).collect(), triangles: self.triangles.clone() }
    }

    /// The lowest and highest corner of the bounding box, mm.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.vertices.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)))
    }

    /// The bounding box seen from above, mm.
    pub fn footprint(&self) -> (DVec2, DVec2) {
        let (lo, hi) = self.bounds();
        (lo.truncate(), hi.truncate())
    }

    /// Whether every edge is used once in each direction: a closed,
    /// consistently oriented surface that can be printed.
    ///
    /// ```
    /// use tracery_core::mesh_quilt::Element;
    /// use glam::DVec3;
    /// let tetra = Element {
    ///     vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
    ///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    /// };
    /// assert!(tetra.is_closed());
    /// let open = Element { triangles: tetra.triangles[..3].to_vec(), ..tetra };
    /// assert!(!open.is_closed());
    /// ```
    pub fn is_closed(&self) -> bool {
        self.to_mesh().sanity_check().is_ok()
    }

    /// Whether the element is a thread: its vertices spread along one
    /// direction [`THREAD_ASPECT`](super::THREAD_ASPECT) times as far as
    /// along any other, whichever way it lies. A ring, a scale or a rivet
    /// spreads as far two ways. Meant for swatch-sized elements: a thread
    /// stitched round a whole model spreads every way.
    ///
    /// ```
    /// use tracery_core::mesh_quilt::{torus, tube};
    /// use glam::{DMat3, DVec3};
    /// let thread = tube(&[DVec3::ZERO, DVec3::new(5.0, 5.0, 0.0), DVec3::new(10.0, 10.0, 1.0)], 0.5, 8, false);
    /// assert!(thread.is_thread());
    /// assert!(!torus(DVec3::ZERO, DMat3::IDENTITY, 4.0, 0.8, 32, 10).is_thread());
    /// ```
    pub fn is_thread(&self) -> bool {
        let Some((_, covariance)) = self.spread() else { return false };
        // Eigenvalues come in increasing order; they are variances, so
        // their square roots are spreads.
        let Ok(variances) = covariance.self_adjoint_eigenvalues(faer::Side::Lower) else { return false };
        let (long, across) = (variances[2].max(0.0).sqrt(), variances[1].max(0.0).sqrt());
        long >= super::THREAD_ASPECT * across
    }

    /// The centre of the element's vertices and their covariance (3 × 3),
    /// whose eigenvectors are the directions it spreads along. None with
    /// fewer than four vertices.
    pub(super) fn spread(&self) -> Option<(DVec3, faer::Mat<f64>)> {
        let n = self.vertices.len() as f64;
        if n < 4.0 {
            return None;
        }
        let centre = self.vertices.iter().copied().sum::<DVec3>() / n;
        let covariance = faer::Mat::<f64>::from_fn(3, 3, |i, j| {
            self.vertices.iter().map(|&v| (v - centre)[i] * (v - centre)[j]).sum::<f64>() / n
        });
        Some((centre, covariance))
    }

    /// A shared [`Mesh`] as an element (whole, however many parts it has).
    pub fn from_mesh(mesh: &Mesh) -> Element {
        Element {
            vertices: mesh.vertices.iter().map(|&v| DVec3::from_array(v)).collect(),
            triangles: mesh.triangles.clone(),
        }
    }

    /// The element as a shared [`Mesh`].
    pub fn to_mesh(&self) -> Mesh {
        Mesh { vertices: self.vertices.iter().map(|v| v.to_array()).collect(), triangles: self.triangles.clone() }
    }

    /// Angle-weighted unit normals at the vertices.
    pub fn vertex_normals(&self) -> Vec<DVec3> {
        let mut normals = vec![DVec3::ZERO; self.vertices.len()];
        for t in &self.triangles {
            let p = t.map(|i| self.vertices[i as usize]);
            let n = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
            for k in 0..3 {
                let angle = (p[(k + 1) % 3] - p[k]).angle_between(p[(k + 2) % 3] - p[k]);
                if angle.is_finite() {
                    normals[t[k] as usize] += n * angle;
                }
            }
        }
        normals.iter().map(|n| n.normalize_or_zero()).collect()
    }

    /// The unit normal of triangle `t` (zero when it is degenerate).
    pub fn face_normal(&self, t: usize) -> DVec3 {
        let p = self.triangles[t].map(|i| self.vertices[i as usize]);
        (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero()
    }

    /// The centroid of triangle `t`.
    pub fn face_centre(&self, t: usize) -> DVec3 {
        self.triangles[t].iter().map(|&i| self.vertices[i as usize]).sum::<DVec3>() / 3.0
    }

    /// The mean edge length, mm.
    pub fn mean_edge_mm(&self) -> f64 {
        let (sum, count) = self.triangles.iter().fold((0.0, 0usize), |(s, c), t| {
            let p = t.map(|i| self.vertices[i as usize]);
            (s + p[0].distance(p[1]) + p[1].distance(p[2]) + p[2].distance(p[0]), c + 3)
        });
        if count == 0 { 0.0 } else { sum / count as f64 }
    }

    /// The longest edge, mm (0 with no triangles).
    ///
    /// ```
    /// use tracery_core::mesh_quilt::Element;
    /// use glam::DVec3;
    /// let t = Element { vertices: vec![DVec3::ZERO, DVec3::X * 3.0, DVec3::Y * 4.0], triangles: vec![[0, 1, 2]] };
    /// assert_eq!(t.longest_edge_mm(), 5.0);
    /// ```
    pub fn longest_edge_mm(&self) -> f64 {
        self.triangles
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
            .map(|(a, b)| self.vertices[a as usize].distance(self.vertices[b as usize]))
            .fold(0.0, f64::max)
    }

    /// The vertices next to each vertex (the 1-ring), sorted.
    pub fn neighbours(&self) -> Vec<Vec<u32>> {
        crate::mesh::vertex_rings(self.vertices.len(), &self.triangles)
    }

    /// For each triangle, the triangles sharing an edge with it.
    pub fn face_neighbours(&self) -> Vec<Vec<u32>> {
        let mut by_edge: FxHashMap<(u32, u32), Vec<u32>> = FxHashMap::default();
        for (f, t) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                by_edge.entry((a.min(b), a.max(b))).or_default().push(f as u32);
            }
        }
        let mut adjacent = vec![Vec::new(); self.triangles.len()];
        for faces in by_edge.values() {
            for &f in faces {
                adjacent[f as usize].extend(faces.iter().copied().filter(|&g| g != f));
            }
        }
        adjacent
    }

    /// The triangles in `keep` as an element of their own, with only the
    /// vertices they use.
    pub fn subset(&self, keep: impl Fn(usize) -> bool) -> Element {
        let mut new_index = vec![u32::MAX; self.vertices.len()];
        let mut out = Element::default();
        for (f, t) in self.triangles.iter().enumerate() {
            if !keep(f) {
                continue;
            }
            out.triangles.push(t.map(|i| {
                if new_index[i as usize] == u32::MAX {
                    new_index[i as usize] = out.vertices.len() as u32;
                    out.vertices.push(self.vertices[i as usize]);
                }
                new_index[i as usize]
            }));
        }
        out
    }

    /// The element's connected parts (through shared edges), each an
    /// element of its own.
    pub fn parts(&self) -> Vec<Element> {
        let adjacent = self.face_neighbours();
        let mut part = vec![usize::MAX; self.triangles.len()];
        let mut count = 0;
        for start in 0..self.triangles.len() {
            if part[start] != usize::MAX {
                continue;
            }
            let mut stack = vec![start];
            part[start] = count;
            while let Some(f) = stack.pop() {
                for &g in &adjacent[f] {
                    if part[g as usize] == usize::MAX {
                        part[g as usize] = count;
                        stack.push(g as usize);
                    }
                }
            }
            count += 1;
        }
        (0..count).map(|p| self.subset(|f| part[f] == p)).collect()
    }

    /// Appends `other` (as a separate part until stitched).
    pub fn append(&mut self, other: &Element) {
        let base = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.triangles.extend(other.triangles.iter().map(|t| t.map(|i| i + base)));
    }

    /// The boundary loops, each in the direction its triangles run along it.
    pub fn boundary_loops(&self) -> Vec<Vec<u32>> {
        crate::mesh::boundary_loops(&self.triangles)
    }
}
