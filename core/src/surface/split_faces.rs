//! Splitting a model's faces finer, where what walks over it face by face
//! needs it: everywhere, on a model with few long faces (a box from CAD
//! has 12), and in a strip along its creases, where a shell offset along
//! one normal per vertex fans out over the faces beside the crease.

use std::collections::HashSet;

use glam::DVec3;

use super::{MAX_BASE_TRIANGLES, SurfaceMesh};
use crate::mesh::{Mesh, split_edges_tracked};

/// Most rounds of [`SurfaceMesh::split_along_creases`]: each halves the
/// edges at a crease, so 12 take a 1 m face down to a quarter millimetre.
const CREASE_ROUNDS: usize = 12;

impl SurfaceMesh {
    /// This surface with its edges longer than `max_edge_mm` split at their
    /// midpoints, round after round, and each new triangle's triangle here;
    /// `None` when no edge is that long. The shape is the same: only the
    /// triangles are smaller. Where the limit would give more than half
    /// [`MAX_BASE_TRIANGLES`], it is raised to keep under that.
    ///
    /// Why: a model drawn in CAD has few, long triangles (a box has 12),
    /// and what walks over a surface face by face (a quilt's patches) is
    /// then as coarse as its faces.
    ///
    /// ```
    /// use tracery_core::mesh::Mesh;
    /// use tracery_core::surface::SurfaceMesh;
    /// let sheet = Mesh {
    ///     vertices: vec![[0.0, 0.0, 0.0], [40.0, 0.0, 0.0], [40.0, 40.0, 0.0], [0.0, 40.0, 0.0]],
    ///     triangles: vec![[0, 1, 2], [0, 2, 3]],
    /// };
    /// let sheet = SurfaceMesh::new(sheet).unwrap();
    /// let (fine, parents) = sheet.split_to(5.0).unwrap();
    /// assert_eq!(parents.len(), fine.triangles().len());
    /// assert!(fine.longest_edge_mm() <= 5.0);
    /// assert!(fine.split_to(5.0).is_none());
    /// ```
    pub fn split_to(&self, max_edge_mm: f64) -> Option<(SurfaceMesh, Vec<u32>)> {
        let max_edge_mm = max_edge_mm.max(self.least_split_edge_mm());
        if self.longest_edge_mm() <= max_edge_mm {
            return None;
        }
        let too_long = |a: [f64; 3], b: [f64; 3]| DVec3::from_array(a).distance(DVec3::from_array(b)) > max_edge_mm;
        self.split_where(too_long)
    }

    /// This surface with the edges that touch a crease (where faces meet at
    /// more than `crease_deg`) split until they are at most `edge_mm` long,
    /// and each new triangle's triangle here; `None` when none is longer.
    /// The faces beside each crease then make a strip `edge_mm` wide.
    ///
    /// Why: a shell offset along one direction per vertex must fan out
    /// where faces meet at a crease, and it fans over the faces that touch
    /// the crease. On a box from CAD, split only to a few millimetres,
    /// chain mail's rings by an edge were bent into hearts.
    ///
    /// ```
    /// use tracery_core::surface::{SurfaceMesh, builtin_base};
    /// let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
    /// let (fine, parents) = cylinder.split_along_creases(35.0, 0.5).unwrap();
    /// assert_eq!(parents.len(), fine.triangles().len());
    /// // Only the strips by the two rims are split: far fewer new faces
    /// // than splitting every face to half a millimetre would make.
    /// assert!(fine.triangles().len() < 4 * cylinder.triangles().len());
    /// assert!(fine.split_along_creases(35.0, 0.5).is_none());
    /// ```
    pub fn split_along_creases(&self, crease_deg: f64, edge_mm: f64) -> Option<(SurfaceMesh, Vec<u32>)> {
        let edge_mm = edge_mm.max(self.least_split_edge_mm());
        let crease_cos = crease_deg.to_radians().cos();
        let mut current: Option<(SurfaceMesh, Vec<u32>)> = None;
        for _ in 0..CREASE_ROUNDS {
            let surface = current.as_ref().map_or(self, |(s, _)| s);
            // Creases are found again each round: a crease's new midpoints
            // are on it, and the edges from them are split next.
            let at_crease = surface.crease_vertices(crease_cos);
            let bits = |p: [f64; 3]| p.map(f64::to_bits);
            let touching = |a: [f64; 3], b: [f64; 3]| {
                (at_crease.contains(&bits(a)) || at_crease.contains(&bits(b)))
                    && DVec3::from_array(a).distance(DVec3::from_array(b)) > edge_mm
            };
            let Some((finer, parents)) = surface.split_where(touching) else { break };
            let parents = match &current {
                Some((_, before)) => parents.iter().map(|&p| before[p as usize]).collect(),
                None => parents,
            };
            current = Some((finer, parents));
        }
        current
    }

    /// The longest edge, mm.
    pub fn longest_edge_mm(&self) -> f64 {
        let p = self.positions();
        self.triangles()
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
            .map(|(a, b)| p[a as usize].distance(p[b as usize]))
            .fold(0.0, f64::max)
    }

    /// The shortest edge splitting may aim for, mm: split at midpoints,
    /// triangles end with edges between half the limit and the limit, about
    /// 8 / limit² of them per mm², and this keeps them under half
    /// [`MAX_BASE_TRIANGLES`].
    fn least_split_edge_mm(&self) -> f64 {
        (16.0 * self.area_mm2() / MAX_BASE_TRIANGLES as f64).sqrt()
    }

    /// The surface's area, mm².
    pub fn area_mm2(&self) -> f64 {
        let p = self.positions();
        self.triangles()
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|v| p[v as usize]);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum()
    }

    /// The positions (as bits) of vertices on an edge whose two faces'
    /// normals meet with a cosine under `crease_cos`.
    fn crease_vertices(&self, crease_cos: f64) -> HashSet<[u64; 3]> {
        let mut out = HashSet::new();
        for t in self.triangles() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                if let [f, g] = self.faces_on_edge(a, b)
                    && self.face_normal(*f).dot(self.face_normal(*g)) < crease_cos
                {
                    for v in [a, b] {
                        out.insert(self.positions()[v as usize].to_array().map(f64::to_bits));
                    }
                }
            }
        }
        out
    }

    /// This surface with the edges `split` holds for split, as
    /// [`split_edges_tracked`] does; `None` when none is.
    fn split_where(&self, split: impl Fn([f64; 3], [f64; 3]) -> bool) -> Option<(SurfaceMesh, Vec<u32>)> {
        let (mesh, parents): (Mesh, Vec<u32>) = split_edges_tracked(self.mesh(), split);
        if parents.len() == self.triangles().len() {
            return None;
        }
        // Split at midpoints, nothing the checks refuse can appear.
        SurfaceMesh::new(mesh).ok().filter(|fine| fine.triangles().len() == parents.len()).map(|fine| (fine, parents))
    }
}
