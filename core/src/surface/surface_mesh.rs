//! A base model ready to draw on: checked (manifold, finite, not too large),
//! with its edges, smooth vertex normals, and a bounding-volume hierarchy
//! (parry3d's) for closest points and ray picks.

use std::collections::HashMap;

use glam::DVec3;
use parry3d_f64::math::Vector as PVector;
use parry3d_f64::query::{PointQueryWithLocation, Ray, RayCast};
use parry3d_f64::shape::{TriMesh, TrianglePointLocation};

use crate::mesh::Mesh;

/// Most triangles a base may have: parameterizing a chart of it and laying
/// a band on it stay interactive up to here.
pub const MAX_BASE_TRIANGLES: usize = 1_000_000;

/// Why a mesh cannot be drawn on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SurfaceError {
    /// No triangles.
    #[error("the base mesh has no triangles")]
    Empty,
    /// Too many triangles.
    #[error("the base mesh has {triangles} triangles; at most {MAX_BASE_TRIANGLES} are taken (simplify it first)")]
    TooLarge {
        /// How many it has.
        triangles: usize,
    },
    /// A triangle names a missing vertex, or a coordinate is not finite.
    #[error("the base mesh is broken: {0}")]
    Broken(String),
    /// An edge is shared by more than two triangles.
    #[error(
        "the base mesh is not a surface: {edges} edge(s) are shared by more than two triangles (the first at {at_mm:?} mm); repair it in a mesh editor"
    )]
    NonManifold {
        /// How many edges.
        edges: usize,
        /// Where the first is.
        at_mm: [f64; 3],
    },
    /// Neighbouring triangles face opposite ways.
    #[error(
        "the base mesh's triangles do not face one way: {edges} edge(s) join triangles that face opposite sides (the first at {at_mm:?} mm); repair it in a mesh editor"
    )]
    Orientation {
        /// How many edges.
        edges: usize,
        /// Where the first is.
        at_mm: [f64; 3],
    },
}

/// Where a point lies on the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// The triangle.
    pub face: u32,
    /// Barycentric coordinates in it (they sum to 1).
    pub barycentric: [f64; 3],
    /// The point, mm.
    pub position_mm: DVec3,
}

/// A base mesh that passed its checks, with what drawing on it needs.
pub struct SurfaceMesh {
    mesh: Mesh,
    positions: Vec<DVec3>,
    vertex_normals: Vec<DVec3>,
    /// Triangles on each undirected edge `(low, high)`.
    edge_faces: HashMap<(u32, u32), smallvec::SmallVec<[u32; 2]>>,
    bvh: TriMesh,
    size_mm: f64,
}

impl SurfaceMesh {
    /// Checks `mesh` and builds what drawing on it needs. Triangles that
    /// collapse to a line are dropped; a surface with boundaries (an open
    /// shell, a vase without a bottom) is taken; a closed one whose faces
    /// look inward is turned to look outward.
    ///
    /// ```
    /// use tracery_core::surface::{SurfaceMesh, builtin_base};
    /// let sphere = SurfaceMesh::new(builtin_base("sphere").unwrap()).unwrap();
    /// let on = sphere.closest_point([0.0, 0.0, 100.0]);
    /// assert!((on.position_mm.z - 60.0).abs() < 1e-6);
    /// ```
    pub fn new(mut mesh: Mesh) -> Result<SurfaceMesh, SurfaceError> {
        if mesh.triangles.is_empty() {
            return Err(SurfaceError::Empty);
        }
        if mesh.triangles.len() > MAX_BASE_TRIANGLES {
            return Err(SurfaceError::TooLarge { triangles: mesh.triangles.len() });
        }
        let n = mesh.vertices.len();
        if let Some(t) = mesh.triangles.iter().position(|t| t.iter().any(|&i| i as usize >= n)) {
            return Err(SurfaceError::Broken(format!("triangle {t} names a vertex that is not there")));
        }
        if mesh.vertices.iter().flatten().any(|c| !c.is_finite()) {
            return Err(SurfaceError::Broken("a vertex is not a finite number".into()));
        }
        let positions: Vec<DVec3> = mesh.vertices.iter().map(|&v| DVec3::from_array(v)).collect();
        mesh.triangles.retain(|t| {
            let [a, b, c] = t.map(|i| positions[i as usize]);
            (b - a).cross(c - a).length_squared() > 0.0
        });
        if mesh.triangles.is_empty() {
            return Err(SurfaceError::Empty);
        }
        let mut directed: HashMap<(u32, u32), u32> = HashMap::new();
        let mut edge_faces: HashMap<(u32, u32), smallvec::SmallVec<[u32; 2]>> = HashMap::new();
        for (f, t) in mesh.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                *directed.entry((a, b)).or_default() += 1;
                edge_faces.entry((a.min(b), a.max(b))).or_default().push(f as u32);
            }
        }
        let at = |e: &(u32, u32)| (0.5 * (positions[e.0 as usize] + positions[e.1 as usize])).to_array();
        let crowded: Vec<_> = edge_faces.iter().filter(|(_, f)| f.len() > 2).map(|(e, _)| *e).collect();
        if let Some(first) = crowded.iter().min() {
            return Err(SurfaceError::NonManifold { edges: crowded.len(), at_mm: at(first) });
        }
        let flipped: Vec<_> = directed.iter().filter(|(_, count)| **count > 1).map(|(e, _)| *e).collect();
        if let Some(first) = flipped.iter().min() {
            return Err(SurfaceError::Orientation { edges: flipped.len(), at_mm: at(first) });
        }
        // Some programs write a closed model with every face looking in. Its
        // texture was grown inside it, and united with it came out as loose
        // pieces with no model: such a model is turned outward. (Points on
        // it are kept in millimetres, not by face, so nothing moves.)
        if edge_faces.values().all(|faces| faces.len() == 2) {
            mesh.orient_outward();
        }
        // Normals weighted by angle, so that how a flat area is cut into
        // triangles does not tilt them.
        let mut vertex_normals = vec![DVec3::ZERO; n];
        for_each_corner(&positions, &mesh.triangles, |vertex, normal, angle| {
            vertex_normals[vertex as usize] += normal * angle;
        });
        for normal in &mut vertex_normals {
            *normal = normal.normalize_or_zero();
        }
        let (low, high) =
            positions.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
        let bvh = TriMesh::new(positions.iter().map(|p| PVector::new(p.x, p.y, p.z)).collect(), mesh.triangles.clone())
            .map_err(|e| SurfaceError::Broken(e.to_string()))?;
        Ok(SurfaceMesh { size_mm: low.distance(high), mesh, positions, vertex_normals, edge_faces, bvh })
    }

    /// The mesh as checked.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The diagonal of the mesh's bounding box, mm.
    pub fn size_mm(&self) -> f64 {
        self.size_mm
    }

    /// Vertex positions, mm.
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// The triangles.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.mesh.triangles
    }

    /// The triangles on the edge between vertices `a` and `b` (none, one on
    /// a boundary, two inside).
    pub fn faces_on_edge(&self, a: u32, b: u32) -> &[u32] {
        self.edge_faces.get(&(a.min(b), a.max(b))).map(|f| f.as_slice()).unwrap_or(&[])
    }

    /// The point of the surface at `barycentric` in `face`.
    pub fn point(&self, face: u32, barycentric: [f64; 3]) -> DVec3 {
        let t = self.mesh.triangles[face as usize];
        (0..3).map(|k| self.positions[t[k] as usize] * barycentric[k]).sum()
    }

    /// The smooth normal at `barycentric` in `face`: vertex normals blended.
    pub fn normal(&self, face: u32, barycentric: [f64; 3]) -> DVec3 {
        let t = self.mesh.triangles[face as usize];
        let blended: DVec3 = (0..3).map(|k| self.vertex_normals[t[k] as usize] * barycentric[k]).sum();
        blended.try_normalize().unwrap_or_else(|| self.face_normal(face))
    }

    /// The smooth (angle-weighted) normal at vertex `v`.
    pub fn vertex_normal(&self, v: u32) -> DVec3 {
        self.vertex_normals[v as usize]
    }

    /// The flat normal of `face`.
    pub fn face_normal(&self, face: u32) -> DVec3 {
        let p = self.mesh.triangles[face as usize].map(|i| self.positions[i as usize]);
        (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero()
    }

    /// The point of the surface closest to `point_mm`.
    pub fn closest_point(&self, point_mm: [f64; 3]) -> SurfacePoint {
        let query = PVector::new(point_mm[0], point_mm[1], point_mm[2]);
        let (projection, (face, location)) = self.bvh.project_local_point_and_get_location(query, false);
        let position = DVec3::new(projection.point.x, projection.point.y, projection.point.z);
        let barycentric = match location {
            TrianglePointLocation::OnFace(_, b) => b,
            _ => self.barycentric(face, position),
        };
        SurfacePoint { face, barycentric, position_mm: position }
    }

    /// Where a ray from `origin_mm` along `direction` first meets the
    /// surface, if it does.
    pub fn ray_hit(&self, origin_mm: DVec3, direction: DVec3) -> Option<SurfacePoint> {
        let ray = Ray::new(PVector::new(origin_mm.x, origin_mm.y, origin_mm.z), {
            let d = direction.normalize();
            PVector::new(d.x, d.y, d.z)
        });
        // Not solid: a ray starting inside the model meets its surface too.
        let hit = self.bvh.cast_local_ray_and_get_normal(&ray, f64::MAX, false)?;
        let position = origin_mm + direction.normalize() * hit.time_of_impact;
        // The triangle is the hit's sub-shape; its `feature` names a face,
        // edge or vertex of that one triangle.
        let face = hit.subshape;
        Some(SurfacePoint { face, barycentric: self.barycentric(face, position), position_mm: position })
    }

    /// Barycentric coordinates of `p` (on or near the plane of `face`),
    /// clamped into the triangle.
    pub fn barycentric(&self, face: u32, p: DVec3) -> [f64; 3] {
        let [a, b, c] = self.mesh.triangles[face as usize].map(|i| self.positions[i as usize]);
        let (v0, v1, v2) = (b - a, c - a, p - a);
        let (d00, d01, d11, d20, d21) = (v0.dot(v0), v0.dot(v1), v1.dot(v1), v2.dot(v0), v2.dot(v1));
        let denom = d00 * d11 - d01 * d01;
        let v = ((d11 * d20 - d01 * d21) / denom).clamp(0.0, 1.0);
        let w = ((d00 * d21 - d01 * d20) / denom).clamp(0.0, 1.0 - v);
        [1.0 - v - w, v, w]
    }
}

/// Calls `visit(vertex, face_normal, angle)` for each corner of each
/// triangle: the unit normal of its face (zero for a degenerate face) and
/// the angle between its two edges, radians. Angle-weighted sums over a
/// vertex's corners do not depend on how a flat area is cut into triangles.
pub(super) fn for_each_corner(positions: &[DVec3], triangles: &[[u32; 3]], mut visit: impl FnMut(u32, DVec3, f64)) {
    for t in triangles {
        let p = t.map(|i| positions[i as usize]);
        let normal = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
        for k in 0..3 {
            let (e1, e2) = (p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
            visit(t[k], normal, e1.angle_between(e2));
        }
    }
}
