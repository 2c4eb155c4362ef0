//! [`Faces`]: the triangles of several elements behind one bounding volume
//! hierarchy (parry3d's), for closest-face queries.

use glam::DVec3;
use parry3d_f64::math::Pose;
use parry3d_f64::math::Vector as PVector;
use parry3d_f64::query::{PointQueryWithLocation, Ray, RayCast, intersection_test};
use parry3d_f64::shape::TriMesh;

use super::Element;

/// The closest point of a set of faces to a query.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Closest {
    /// Distance from the query, mm.
    pub distance_mm: f64,
    /// The closest point, mm.
    pub point_mm: DVec3,
    /// Which element (its place in the list the faces were built from).
    pub element: u32,
    /// Which triangle of that element.
    pub face: u32,
    /// The triangle's unit normal.
    pub normal: DVec3,
}

/// Triangles of several elements, indexed for closest-point queries.
pub struct Faces {
    bvh: Option<TriMesh>,
    owner: Vec<(u32, u32)>,
    normals: Vec<DVec3>,
}

impl Faces {
    /// The faces of `elements`, named by their place in the slice.
    pub fn new<'a>(elements: impl IntoIterator<Item = &'a Element>) -> Faces {
        let mut points = Vec::new();
        let mut triangles = Vec::new();
        let mut owner = Vec::new();
        let mut normals = Vec::new();
        for (e, element) in elements.into_iter().enumerate() {
            let base = points.len() as u32;
            points.extend(element.vertices.iter().map(|v| PVector::new(v.x, v.y, v.z)));
            for (f, t) in element.triangles.iter().enumerate() {
                triangles.push(t.map(|i| i + base));
                owner.push((e as u32, f as u32));
                normals.push(element.face_normal(f));
            }
        }
        let bvh = if triangles.is_empty() { None } else { TriMesh::new(points, triangles).ok() };
        Faces { bvh, owner, normals }
    }

    /// Whether there is no face.
    pub fn is_empty(&self) -> bool {
        self.bvh.is_none()
    }

    /// The closest point to `query_mm`, if there is any face.
    pub fn closest(&self, query_mm: DVec3) -> Option<Closest> {
        let bvh = self.bvh.as_ref()?;
        let (projection, (face, _)) =
            bvh.project_local_point_and_get_location(PVector::new(query_mm.x, query_mm.y, query_mm.z), false);
        Some(self.closest_at(query_mm, projection.point, face))
    }

    /// The closest point to `query_mm` no farther than `max_mm`: the search
    /// leaves out every branch of the hierarchy farther away, so it is
    /// cheap where nothing is near.
    pub fn closest_within(&self, query_mm: DVec3, max_mm: f64) -> Option<Closest> {
        let bvh = self.bvh.as_ref()?;
        let (projection, (face, _)) = bvh.project_local_point_and_get_location_with_max_dist(
            PVector::new(query_mm.x, query_mm.y, query_mm.z),
            false,
            max_mm,
        )?;
        Some(self.closest_at(query_mm, projection.point, face)).filter(|h| h.distance_mm <= max_mm)
    }

    fn closest_at(&self, query_mm: DVec3, point: PVector, face: u32) -> Closest {
        let point_mm = DVec3::new(point.x, point.y, point.z);
        let (element, local) = self.owner[face as usize];
        Closest {
            distance_mm: point_mm.distance(query_mm),
            point_mm,
            element,
            face: local,
            normal: self.normals[face as usize],
        }
    }

    /// How far along the unit vector `direction_mm` from `origin_mm` the
    /// last face within `max_mm` lies, 0 when none does: where a ray
    /// starting inside or below closed elements leaves them for good.
    ///
    /// ```
    /// use glam::DVec3;
    /// use tracery_core::mesh_quilt::{Faces, tube};
    /// // A rod of radius 1 along x; a ray up from 3 mm below it passes in
    /// // and out, and leaves it for good about 4 mm on.
    /// let rod = tube(&[DVec3::ZERO, DVec3::X * 10.0], 1.0, 16, false);
    /// let faces = Faces::new([&rod]);
    /// let out = faces.last_hit_along(DVec3::new(5.0, 0.0, -3.0), DVec3::Z, 10.0);
    /// assert!((out - 4.0).abs() < 0.05, "{out}");
    /// // From inside it, straight to the top; beside it, nothing.
    /// assert!((faces.last_hit_along(DVec3::new(5.0, 0.0, 0.0), DVec3::Z, 10.0) - 1.0).abs() < 0.05);
    /// assert_eq!(faces.last_hit_along(DVec3::new(5.0, 3.0, -3.0), DVec3::Z, 10.0), 0.0);
    /// ```
    pub fn last_hit_along(&self, origin_mm: DVec3, direction_mm: DVec3, max_mm: f64) -> f64 {
        let Some(bvh) = &self.bvh else { return 0.0 };
        // A step past each hit, so the next cast does not find it again;
        // and a cap on the hits, so a ray grazing along a face, hitting it
        // again at each step, ends.
        const STEP_MM: f64 = 1e-5;
        const MAX_HITS: usize = 64;
        let (mut travelled, mut last) = (0.0, 0.0);
        for _ in 0..MAX_HITS {
            if travelled >= max_mm {
                break;
            }
            let start = origin_mm + direction_mm * travelled;
            let ray = Ray::new(
                PVector::new(start.x, start.y, start.z),
                PVector::new(direction_mm.x, direction_mm.y, direction_mm.z),
            );
            let Some(t) = bvh.cast_local_ray(&ray, max_mm - travelled, false) else { break };
            last = travelled + t;
            travelled = last + STEP_MM;
        }
        last
    }

    /// Whether any face of these crosses or touches any face of `other`.
    pub fn intersects(&self, other: &Faces) -> bool {
        match (&self.bvh, &other.bvh) {
            (Some(a), Some(b)) => {
                intersection_test(&Pose::IDENTITY, a, &Pose::IDENTITY, b).is_ok_and(|hit| hit.intersecting)
            }
            _ => false,
        }
    }
}

/// Each output element's own faces, built when first asked for and kept
/// until the element changes: the check that nothing new crosses what is
/// there asks for the same long threads patch after patch.
#[derive(Default)]
pub(super) struct ElementFaces {
    built: Vec<Option<Faces>>,
}

impl ElementFaces {
    /// The faces of `element`, output element `k`.
    pub fn get(&mut self, k: usize, element: &Element) -> &Faces {
        let slot = self.slot(k);
        // A guard, cheap next to a build: faces of another element (one
        // changed without `set`) would not match its triangle count.
        if slot.as_ref().is_some_and(|f| f.owner.len() != element.triangles.len()) {
            *slot = None;
        }
        slot.get_or_insert_with(|| Faces::new([element]))
    }

    /// Output element `k`'s faces, when built.
    pub fn built(&self, k: usize) -> Option<&Faces> {
        self.built.get(k)?.as_ref()
    }

    /// Output element `k` is now the one `faces` were built from.
    pub fn set(&mut self, k: usize, faces: Faces) {
        *self.slot(k) = Some(faces);
    }

    fn slot(&mut self, k: usize) -> &mut Option<Faces> {
        if self.built.len() <= k {
            self.built.resize_with(k + 1, || None);
        }
        &mut self.built[k]
    }
}
