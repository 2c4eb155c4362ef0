//! [`FlatCaps`]: a model's flat tops, where the quilt ends at the rim.
//!
//! A patch on a straight cap keeps to the cap (see
//! [`GuidanceField::with_straight_caps`]), and an element is laid only where
//! every vertex lands on the patch, so every element reaching past the rim
//! used to be left out: a bare margin of 3 to 8 mm stayed inside a vase's
//! rim. On a cap that is a plane, the patch's flat frame carries on past its
//! edge exactly, so such an element is laid whole in the cap's plane. Then
//! a thread is cut off flat at the rim, as the plane's edge cuts it
//! ([`trim_to_area`](super::trim_to_area)), and an element that is not a
//! thread (a link, a rivet) is left out, as before: half of one is a crumb.

use glam::{DVec2, DVec3};

use super::Element;
use super::edge::{EDGE_TOLERANCE_MM, solid_pieces};
use super::field::GuidanceField;
use super::patch::FaceGraph;
use super::zones::boxes_overlap;
use crate::geom::{Polygon, Rect, Region, offset, signed_area};
use crate::mesh::{Mesh, boundary_loops, difference_solids, extrude, intersect_solids};
use crate::surface::SurfaceMesh;

/// A cap is flat when every face's normal lies within this many degrees of
/// the cap's mean normal...
pub const FLAT_CAP_DEG: f64 = 0.5;

/// ...and every vertex within this distance of its plane, mm.
pub const FLAT_CAP_TOLERANCE_MM: f64 = 0.01;

/// Threads are cut this far inside the rim, mm. Cut at the rim itself, the
/// cut faces of their sunk parts lay in the plane of a straight wall below
/// it, and united with the model the two made seams that an STL's `f32`
/// corners turn into edges shared four ways (`admesh` counted 3 parts and
/// turned 14 facets on the vase).
pub const RIM_INSET_MM: f64 = 0.1;

/// One flat cap: its plane, a frame in it, and its outline as a prism.
pub(super) struct FlatCap {
    frame: Frame,
    /// The cap seen along its normal, in the frame.
    outline: Region,
    /// The outline, [`RIM_INSET_MM`] inside the rim, from well below the
    /// cap's plane to well above it: what a cut thread keeps.
    prism: Mesh,
    /// The prism's bounding box, mm.
    bounds: (DVec3, DVec3),
}

/// What [`FlatCap::fit`] made of one element.
pub(super) struct Fitted {
    /// The element whole, the pieces of a thread inside the rim, or nothing.
    pub pieces: Vec<Element>,
    /// Whether a thread was cut at the rim.
    pub cut: bool,
}

impl FlatCap {
    /// The cap made of `faces`, if they lie in one plane; its prism reaches
    /// `below_mm` under the plane and `above_mm` over it.
    fn of(surface: &SurfaceMesh, faces: &[u32], below_mm: f64, above_mm: f64) -> Option<FlatCap> {
        let triangles: Vec<[u32; 3]> = faces.iter().map(|&f| surface.triangles()[f as usize]).collect();
        let corners = |t: &[u32; 3]| t.map(|v| surface.positions()[v as usize]);
        let normal = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = corners(t);
                (b - a).cross(c - a)
            })
            .sum::<DVec3>()
            .normalize_or_zero();
        let flat = FLAT_CAP_DEG.to_radians().cos();
        if normal == DVec3::ZERO || faces.iter().any(|&f| surface.face_normal(f).dot(normal) < flat) {
            return None;
        }
        let mut vertices: Vec<u32> = triangles.iter().flatten().copied().collect();
        vertices.sort_unstable();
        vertices.dedup();
        let points: Vec<DVec3> = vertices.iter().map(|&v| surface.positions()[v as usize]).collect();
        let origin = points.iter().copied().sum::<DVec3>() / points.len() as f64;
        if points.iter().any(|&p| (p - origin).dot(normal).abs() > FLAT_CAP_TOLERANCE_MM) {
            return None;
        }
        let x_axis = normal.any_orthonormal_vector();
        let y_axis = normal.cross(x_axis);
        let frame = Frame { origin, normal, x_axis, y_axis };
        // The cap's triangles run counter-clockwise seen from outside, so
        // in a frame whose x × y is the normal its outer rims run
        // counter-clockwise and the rims of holes in it clockwise.
        let rings: Vec<Vec<DVec2>> = boundary_loops(&triangles)
            .iter()
            .map(|ring| ring.iter().map(|&v| frame.flat(surface.positions()[v as usize])).collect())
            .collect();
        let (outers, holes): (Vec<Vec<DVec2>>, Vec<Vec<DVec2>>) =
            rings.into_iter().partition(|ring| signed_area(ring) > 0.0);
        let mut polygons: Vec<Polygon> = outers.into_iter().map(|outer| Polygon { outer, holes: Vec::new() }).collect();
        for hole in holes {
            let home = polygons.iter_mut().find(|p| crate::geom::ring_contains(&p.outer, hole[0]))?;
            home.holes.push(hole);
        }
        let outline = Region::new(polygons);
        let prism = frame.prism(&offset(&outline, -RIM_INSET_MM), -below_mm, above_mm)?;
        let bounds = prism.vertices.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(DVec3::from_array(v)), hi.max(DVec3::from_array(v)))
        });
        Some(FlatCap { frame, outline, prism, bounds })
    }

    /// Whether `p` lies within `margin_mm` of the cap's outline, seen along
    /// its normal.
    fn covers_within(&self, p: DVec3, margin_mm: f64) -> bool {
        let flat = self.frame.flat(p);
        self.outline.contains(flat)
            || self.outline.polygons.iter().any(|polygon| polygon.outline_distance(flat) <= margin_mm)
    }

    /// Whether `p` lies within the cap's outline, seen along its normal.
    fn covers(&self, p: DVec3) -> bool {
        self.covers_within(p, EDGE_TOLERANCE_MM)
    }

    /// The outward normal of the cap's plane.
    pub fn normal(&self) -> DVec3 {
        self.frame.normal
    }

    /// How far `p` lies above the cap's plane (along its outward normal), mm.
    pub fn height(&self, p: DVec3) -> f64 {
        (p - self.frame.origin).dot(self.frame.normal)
    }

    /// `element`, a thread laid on the side below the cap and on past its
    /// rim, cut off flat `depth_mm` under the cap's plane: its pieces of at
    /// least `min_volume_mm3` that are solids. Empty if the cut fails.
    pub fn cut_under(&self, element: &Element, depth_mm: f64, min_volume_mm3: f64) -> Vec<Element> {
        let (mut lo, mut hi) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        let mut top: f64 = 0.0;
        for &p in &element.vertices {
            let flat = self.frame.flat(p);
            (lo, hi) = (lo.min(flat), hi.max(flat));
            top = top.max(self.height(p));
        }
        // A box wider than the element, from the cut up past its top.
        let square = Region::rectangle(&Rect::new(lo - DVec2::ONE, hi + DVec2::ONE));
        let Some(above) = self.frame.prism(&square, -depth_mm, top + 1.0) else { return Vec::new() };
        difference_solids(&element.to_mesh(), &above)
            .map(|mesh| solid_pieces(&mesh, min_volume_mm3).0)
            .unwrap_or_default()
    }

    /// `element`, laid in the cap's plane, fitted to the cap: whole if it
    /// lies within the rim; a thread cut off there, keeping its pieces of
    /// at least `min_volume_mm3` that are solids; anything else reaching
    /// past the rim left out. A cut the booleans cannot make leaves the
    /// thread out too.
    pub fn fit(&self, element: Element, min_volume_mm3: f64) -> Fitted {
        if element.vertices.iter().all(|&p| self.covers(p)) {
            return Fitted { pieces: vec![element], cut: false };
        }
        if !element.is_thread() {
            return Fitted { pieces: Vec::new(), cut: false };
        }
        let pieces = intersect_solids(&element.to_mesh(), &self.prism)
            .map(|mesh| solid_pieces(&mesh, min_volume_mm3).0)
            .unwrap_or_default();
        Fitted { pieces, cut: true }
    }
}

/// The flat caps of a model, and which face lies on which.
pub(super) struct FlatCaps {
    cap_of_face: Vec<Option<u32>>,
    caps: Vec<FlatCap>,
}

impl FlatCaps {
    /// The straight caps of `field` that are planes, each with a prism
    /// reaching `below_mm` under its plane and `above_mm` over it.
    pub fn new(surface: &SurfaceMesh, field: &GuidanceField, graph: &FaceGraph, below_mm: f64, above_mm: f64) -> Self {
        let n = surface.triangles().len();
        let mut cap_of_face = vec![None; n];
        let mut caps = Vec::new();
        let mut seen = vec![false; n];
        for start in 0..n as u32 {
            if seen[start as usize] || !field.on_cap(start) {
                continue;
            }
            seen[start as usize] = true;
            let (mut faces, mut todo) = (vec![start], vec![start]);
            while let Some(f) = todo.pop() {
                for &g in &graph.neighbours[f as usize] {
                    if !seen[g as usize] && field.on_cap(g) {
                        seen[g as usize] = true;
                        faces.push(g);
                        todo.push(g);
                    }
                }
            }
            if let Some(cap) = FlatCap::of(surface, &faces, below_mm, above_mm) {
                for &f in &faces {
                    cap_of_face[f as usize] = Some(caps.len() as u32);
                }
                caps.push(cap);
            }
        }
        FlatCaps { cap_of_face, caps }
    }

    /// Cuts off again at the rim every thread lying over a flat cap (most
    /// of its vertices over the cap, none deeper than `below_mm` under its
    /// plane) that reaches past it: merging moves elements to meet their
    /// neighbours, and it carried some cut ends up to 0.7 mm past the rim
    /// (on a post's top, 23 of 174 cut threads, each keeping 99 % or more
    /// of itself).
    /// Returns how many threads it cut.
    pub fn trim_overhangs(&self, elements: &mut Vec<Element>, below_mm: f64, min_volume_mm3: f64) -> usize {
        let mut cut = 0;
        let mut kept = Vec::with_capacity(elements.len());
        for e in elements.drain(..) {
            let bounds = e.bounds();
            let home = self.caps.iter().find(|cap| {
                boxes_overlap(bounds, cap.bounds)
                    && e.vertices.iter().all(|&p| cap.height(p) >= -below_mm)
                    && 2 * e.vertices.iter().filter(|&&p| cap.covers(p)).count() > e.vertices.len()
            });
            match home {
                Some(cap) if e.is_thread() && !e.vertices.iter().all(|&p| cap.covers(p)) => {
                    cut += 1;
                    kept.extend(cap.fit(e, min_volume_mm3).pieces);
                }
                _ => kept.push(e),
            }
        }
        *elements = kept;
        cut
    }

    /// The flat cap whose plane `p` lies above, within `margin_mm` of its
    /// rim seen along its normal: where a point of the side carried on
    /// past the rim has gone.
    pub fn above(&self, p: DVec3, margin_mm: f64) -> Option<&FlatCap> {
        self.caps.iter().find(|cap| cap.height(p) > 0.0 && cap.covers_within(p, margin_mm))
    }

    /// The flat cap face `f` lies on, if any.
    pub fn of_face(&self, f: u32) -> Option<&FlatCap> {
        self.cap_of_face.get(f as usize).copied().flatten().map(|c| &self.caps[c as usize])
    }
}

/// A cap's plane and a frame in it, `x_axis × y_axis = normal`.
struct Frame {
    origin: DVec3,
    normal: DVec3,
    x_axis: DVec3,
    y_axis: DVec3,
}

impl Frame {
    /// `p` seen along the normal, in the frame.
    fn flat(&self, p: DVec3) -> DVec2 {
        DVec2::new((p - self.origin).dot(self.x_axis), (p - self.origin).dot(self.y_axis))
    }

    /// `region` (in the frame) from `from_mm` to `to_mm` above the plane,
    /// as a closed mesh in space.
    fn prism(&self, region: &Region, from_mm: f64, to_mm: f64) -> Option<Mesh> {
        let mut prism = extrude(region, to_mm - from_mm).ok()?;
        for v in &mut prism.vertices {
            let p = self.origin + self.x_axis * v[0] + self.y_axis * v[1] + self.normal * (v[2] + from_mm);
            *v = p.to_array();
        }
        Some(prism)
    }
}
