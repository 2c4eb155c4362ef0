//! A planar pattern made along a band laid onto a curve on a surface and
//! made solid there.
//!
//! The pattern comes as a *sheet*: for an open curve, made along a straight
//! line from the origin along `+x` (so `x` is the arc length `u` and `y` the
//! offset `v` across, to the left); for a closed one, made along a
//! counter-clockwise circle as long as the curve (`u` is the angle times
//! the radius, `v` the distance in from the circle), so that its loop
//! closes on the sheet as on the surface. The sheet is extruded there
//! (watertight by construction), its edges split until they follow the
//! surface within [`super::CHORD_TOLERANCE_MM`], and each vertex mapped:
//! `p(u) + v·b(u)` from the curve's smooth frames, moved onto the surface
//! along the frame's normal (the paper stops at `p + v·b`, a flat ribbon
//! tangent to the surface along the curve only), then raised by its height
//! along the smooth normal there.

use std::cell::RefCell;
use std::collections::HashMap;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use super::{CHORD_TOLERANCE_MM, Frames, SurfaceCurve, SurfaceMesh};
use crate::geom::Region;
use crate::mesh::{Mesh, MeshError, extrude_fine, split_edges};

/// About the longest edge of the sheet's triangulation, mm: on a radius of
/// 10 mm an edge this long stands 0.01 mm off the surface at its middle.
const FINE_EDGE_MM: f64 = 1.0;

/// Edges shorter than this on the sheet are never split, mm: where the map
/// jumps (a band reaching past a thin part of the model) no split would
/// ever satisfy the chord test.
const SHORTEST_SPLIT_MM: f64 = 0.02;

/// How a sheet's points stand for points of the band.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sheet {
    /// Made along `+x` from the origin: `u = x`, `v = y`.
    Line,
    /// Made along a counter-clockwise circle of this radius about the
    /// origin, mm.
    Circle {
        /// The circle's radius, mm.
        radius_mm: f64,
    },
}

impl Sheet {
    /// The band coordinates `(u, v)` of a sheet point, mm.
    pub fn band_from_sheet(&self, p: DVec2) -> DVec2 {
        match *self {
            Sheet::Line => p,
            Sheet::Circle { radius_mm } => {
                DVec2::new(p.y.atan2(p.x).rem_euclid(TAU) * radius_mm, radius_mm - p.length())
            }
        }
    }
}

/// The band's map onto the surface.
pub struct BandOnSurface<'a> {
    /// The surface.
    pub surface: &'a SurfaceMesh,
    /// The curve the band follows.
    pub curve: &'a SurfaceCurve,
    /// Its frames.
    pub frames: &'a Frames,
    /// Whether band points are moved onto the surface (not when the band is
    /// twisted away from it).
    pub conform: bool,
}

impl BandOnSurface<'_> {
    /// The surface point for band point `(u, v)` raised by `height_mm`.
    pub fn surface_from_band(&self, band: DVec2, height_mm: f64) -> DVec3 {
        let (p, across, normal) = self.frames.at(self.curve, band.x);
        let flat = p + across * band.y;
        if !self.conform {
            return flat + normal * height_mm;
        }
        // Down the frame's normal, not to the closest point: on a faceted
        // mesh every point in a vertex's normal cone has that vertex as its
        // closest point, so distinct pattern vertices would land on one;
        // a ray along a smoothly turning direction lands each on its own.
        let reach = self.frames.length_mm.min(band.y.abs() + 1.0);
        let on = self
            .surface
            .ray_hit(flat + normal * reach, -normal)
            .filter(|hit| hit.position_mm.distance(flat) <= 2.0 * reach)
            .unwrap_or_else(|| self.surface.closest_point(flat.to_array()));
        let mut up = self.surface.normal(on.face, on.barycentric);
        // A point off the surface's side (a band wider than a thin part)
        // keeps the frame's normal rather than the far side's.
        if up.dot(normal) < 0.0 {
            up = normal;
        }
        on.position_mm + up * height_mm
    }
}

/// `sheet_mm` (see [`Sheet`]) made `thickness_mm` thick on the surface,
/// facing out.
pub fn lay_band(sheet_mm: &Region, sheet: Sheet, band: &BandOnSurface, thickness_mm: f64) -> Result<Mesh, MeshError> {
    // Well-shaped triangles first: a long sliver split until it follows
    // the surface would crumble into thousands.
    let flat = extrude_fine(sheet_mm, thickness_mm, FINE_EDGE_MM)?;
    // Each vertex is mapped once, and each edge judged once: splitting goes
    // round after round over every edge, and a ray cast is the dear part.
    let mapped: RefCell<HashMap<[u64; 3], DVec3>> = RefCell::new(HashMap::new());
    type Edge = ([u64; 3], [u64; 3]);
    let judged: RefCell<HashMap<Edge, bool>> = RefCell::new(HashMap::new());
    let key = |v: [f64; 3]| v.map(f64::to_bits);
    let map = |v: [f64; 3]| {
        if let Some(p) = mapped.borrow().get(&key(v)) {
            return *p;
        }
        let p = band.surface_from_band(sheet.band_from_sheet(DVec2::new(v[0], v[1])), v[2]);
        mapped.borrow_mut().insert(key(v), p);
        p
    };
    let fine = split_edges(&flat, |a, b| {
        if let Some(&verdict) = judged.borrow().get(&(key(a), key(b))) {
            return verdict;
        }
        let middle = map([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])]);
        let long_enough = (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>() > SHORTEST_SPLIT_MM.powi(2);
        let verdict = long_enough && middle.distance(0.5 * (map(a) + map(b))) > CHORD_TOLERANCE_MM;
        judged.borrow_mut().insert((key(a), key(b)), verdict);
        verdict
    });
    let mut mesh =
        Mesh { vertices: fine.vertices.iter().map(|&v| map(v).to_array()).collect(), triangles: fine.triangles };
    // Points an f32 step apart on the sheet can land on one point of the
    // file once bent, which would leave it open: refused rather than written.
    let mut ids: HashMap<[u32; 3], u32> = HashMap::new();
    let welded = Mesh {
        vertices: Vec::new(),
        triangles: mesh
            .triangles
            .iter()
            .map(|t| {
                t.map(|i| {
                    let next = ids.len() as u32;
                    *ids.entry(mesh.vertices[i as usize].map(|c| (c as f32).to_bits())).or_insert(next)
                })
            })
            .collect(),
    };
    let merged = mesh.vertices.len() - ids.len();
    let welded = Mesh { vertices: vec![[0.0; 3]; ids.len()], ..welded };
    if merged > 0 && welded.sanity_check().is_err() {
        return Err(MeshError::Collapsed(merged));
    }
    mesh.orient_outward();
    Ok(mesh)
}
