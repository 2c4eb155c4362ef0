//! A planar pattern made along a band laid onto a curve on a surface and
//! made solid there.
//!
//! The pattern comes as a *sheet*: for an open curve, made along a straight
//! line from the origin along `+x` (so `x` is the arc length `u` and `y` the
//! offset `v` across, to the left); for a closed one, made along a
//! counter-clockwise circle as long as the curve (`u` is the angle times
//! the radius, `v` the distance in from the circle), so that its loop
//! closes on the sheet as on the surface. The sheet is triangulated there,
//! its edges split until they follow the surface within
//! [`super::CHORD_TOLERANCE_MM`], and each vertex mapped: `p(u) + v·b(u)`
//! from the curve's smooth frames, moved onto the surface along the frame's
//! normal (the paper stops at `p + v·b`, a flat ribbon tangent to the
//! surface along the curve only); the solid stands on those points, raised
//! along the smooth normal there (watertight by construction).

use std::cell::RefCell;
use std::collections::HashMap;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use super::{CHORD_TOLERANCE_MM, Frames, SurfaceCurve, SurfaceMesh};
use crate::disjoint_sets::DisjointSets;
use crate::geom::Region;
use crate::mesh::{Mesh, MeshError, checked_thickness, compact, split_edges, thicken, triangulate_fine};

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
        let (on, up) = self.foot_and_up(band);
        on + up * height_mm
    }

    /// Where band point `(u, v)` meets the surface, and the direction its
    /// height is raised along there (unit).
    fn foot_and_up(&self, band: DVec2) -> (DVec3, DVec3) {
        let (p, across, normal) = self.frames.at(self.curve, band.x);
        let flat = p + across * band.y;
        if !self.conform {
            return (flat, normal);
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
        (on.position_mm, up)
    }
}

/// `sheet_mm` (see [`Sheet`]) made `thickness_mm` thick on the surface,
/// facing out, its underside `sink_mm` below the surface (0 for a band
/// lying on it).
///
/// The sheet is cut into well-shaped triangles, its edges split until both
/// the bottom (on the surface) and the top follow it within
/// [`CHORD_TOLERANCE_MM`], and only then made solid ([`thicken`]): each
/// vertex's bottom and top are joined straight along the normal, so the
/// walls need no splitting of their own.
pub fn lay_band(
    sheet_mm: &Region,
    sheet: Sheet,
    band: &BandOnSurface,
    thickness_mm: f64,
    sink_mm: f64,
) -> Result<Mesh, MeshError> {
    checked_thickness(thickness_mm)?;
    // Well-shaped triangles first: a long sliver split until it follows
    // the surface would crumble into thousands.
    let flat = triangulate_fine(sheet_mm, FINE_EDGE_MM)?;
    // Each sheet point is placed once (a ray cast is the dear part): an
    // edge's middle, judged in one round, is a vertex in the next.
    let placed: RefCell<HashMap<[u64; 2], (DVec3, DVec3)>> = RefCell::new(HashMap::new());
    let place = |v: [f64; 3]| {
        let key = [v[0].to_bits(), v[1].to_bits()];
        if let Some(&found) = placed.borrow().get(&key) {
            return found;
        }
        let found = band.foot_and_up(sheet.band_from_sheet(DVec2::new(v[0], v[1])));
        placed.borrow_mut().insert(key, found);
        found
    };
    let fine = split_edges(&flat, |a, b| {
        if (a[0] - b[0]).hypot(a[1] - b[1]) <= SHORTEST_SPLIT_MM {
            return false;
        }
        let ((pa, ua), (pb, ub)) = (place(a), place(b));
        let (pm, um) = place([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.0]);
        let strays = |h: f64| (pm + um * h).distance(0.5 * (pa + ua * h + pb + ub * h)) > CHORD_TOLERANCE_MM;
        strays(-sink_mm) || strays(thickness_mm)
    });
    let (bottom, top): (Vec<[f64; 3]>, Vec<[f64; 3]>) = fine
        .vertices
        .iter()
        .map(|&v| {
            let (on, up) = place(v);
            ((on - up * sink_mm).to_array(), (on + up * thickness_mm).to_array())
        })
        .unzip();
    let (fine, bottom, top) = weld_tiny_edges(fine, bottom, top);
    let mut mesh = thicken(&fine, &bottom, &top);
    if let Some(merged) = falls_together_in_f32(&mesh) {
        return Err(MeshError::Collapsed(merged));
    }
    mesh.orient_outward();
    Ok(mesh)
}

/// Placed points closer than this are one, mm: far below a printer's
/// resolution, and above the `f32` step of an STL at half a metre.
const WELD_MM: f64 = 1e-4;

/// The sheet with every edge whose ends are placed less than [`WELD_MM`]
/// apart (at the bottom or at the top) collapsed, and the triangles that
/// collapse with it dropped. Refinement and splitting can leave vertices a
/// fraction of a micrometre apart, which an STL's `f32` would merge
/// anyway, leaving the solid open there.
fn weld_tiny_edges(sheet: Mesh, bottom: Vec<[f64; 3]>, top: Vec<[f64; 3]>) -> (Mesh, Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let apart = |a: usize, b: usize| {
        let d = |p: &[[f64; 3]]| DVec3::from_array(p[a]).distance(DVec3::from_array(p[b]));
        d(&bottom).min(d(&top))
    };
    let mut sets = DisjointSets::new(sheet.vertices.len());
    let mut welded = false;
    for t in &sheet.triangles {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            if apart(a, b) < WELD_MM {
                welded |= sets.join(a, b);
            }
        }
    }
    if !welded {
        return (sheet, bottom, top);
    }
    let collapsed = Mesh {
        vertices: sheet.vertices,
        triangles: sheet
            .triangles
            .iter()
            .map(|t| t.map(|v| sets.find(v as usize) as u32))
            .filter(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
            .collect(),
    };
    let (out, kept) = compact(collapsed);
    let out_bottom = kept.iter().map(|&v| bottom[v as usize]).collect();
    let out_top = kept.iter().map(|&v| top[v as usize]).collect();
    (out, out_bottom, out_top)
}

/// Whether the mesh, once its vertices are written as `f32` (and those
/// that fall together merged, as a reader does), is no longer closed and
/// manifold; with how many vertices merged. A guard: a file that is
/// watertight in `f64` and open in `f32` must never be written.
fn falls_together_in_f32(mesh: &Mesh) -> Option<usize> {
    let mut ids: HashMap<[u32; 3], u32> = HashMap::new();
    let index: Vec<u32> = mesh
        .vertices
        .iter()
        .map(|v| {
            let next = ids.len() as u32;
            *ids.entry(v.map(|c| (c as f32).to_bits())).or_insert(next)
        })
        .collect();
    let merged = mesh.vertices.len() - ids.len();
    let welded = Mesh {
        vertices: vec![[0.0; 3]; ids.len()],
        triangles: mesh.triangles.iter().map(|t| t.map(|i| index[i as usize])).collect(),
    };
    welded.sanity_check().is_err().then_some(merged)
}
