//! Extrusion of a planar region into a closed, watertight solid.

use std::collections::HashMap;

use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use super::Mesh;
use crate::geom::Region;

/// How far apart parts that touch at a single point are moved, in mm.
const TOUCH_GAP_MM: f64 = 1e-3;

/// Why a mesh could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    /// The pattern is empty.
    #[error("there is no pattern to turn into a mesh")]
    Empty,
    /// Thickness is not a positive number.
    #[error("the thickness {0} mm must be a positive number")]
    Thickness(f64),
    /// The tessellator failed on the pattern's outline.
    #[error("the pattern's outline could not be triangulated: {0}")]
    Tessellation(String),
}

/// Extrudes `region` (millimetres, in the plane `z = 0`) to `thickness_mm`:
/// a closed, 2-manifold, consistently oriented mesh with one shell per component.
///
/// Top and bottom faces come from a constrained Delaunay triangulation
/// ([`spade`], in `f64`) whose constraint edges are exactly the rings' edges,
/// and the walls join the same vertices, so the mesh is watertight by
/// construction. Inside and outside are told apart by flooding the
/// triangulation from its outer face, flipping at every ring edge.
///
/// ```
/// use tracery_core::mesh::extrude;
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let mut hole = square(1.0);
/// hole.reverse();
/// let frame = Region::new(vec![Polygon { outer: square(2.0), holes: vec![hole] }]);
/// let mesh = extrude(&frame, 2.0).unwrap();
/// assert_eq!(mesh.shell_count(), 1);
/// assert!(mesh.sanity_check().is_ok());
/// ```
pub fn extrude(region: &Region, thickness_mm: f64) -> Result<Mesh, MeshError> {
    if !(thickness_mm.is_finite() && thickness_mm > 0.0) {
        return Err(MeshError::Thickness(thickness_mm));
    }
    match extrude_exactly(region, thickness_mm, false) {
        Err(MeshError::Tessellation(_)) => {
            let repaired = repaired(region);
            match extrude_exactly(&repaired, thickness_mm, false) {
                // Still a vertex on another ring's edge: make it a shared point.
                Err(MeshError::Tessellation(_)) => extrude_exactly(&repaired, thickness_mm, true),
                result => result,
            }
        }
        result => result,
    }
}

/// The point with its coordinates rounded to `f32`, as STL stores them.
fn round_to_f32(p: glam::DVec2) -> glam::DVec2 {
    glam::DVec2::new(f64::from(p.x as f32), f64::from(p.y as f32))
}

/// Smallest distance kept between successive vertices by the repair, mm:
/// far below what a printer or a laser resolves, far above `f32` rounding.
pub const REPAIR_SPACING_MM: f64 = 1e-4;

/// The region with its rings cleaned for the `f32` output: vertices closer
/// than [`REPAIR_SPACING_MM`] to the previous one dropped, then resolved
/// again by a union, so that rounding cannot make an outline cross itself
/// or touch another ring. Used when the region as given cannot be meshed.
fn repaired(region: &Region) -> Region {
    let thin = |ring: &Vec<glam::DVec2>| {
        let mut out: Vec<glam::DVec2> = Vec::with_capacity(ring.len());
        for &p in ring {
            let p = round_to_f32(p);
            if out.last().is_none_or(|q| q.distance(p) >= REPAIR_SPACING_MM) {
                out.push(p);
            }
        }
        out
    };
    let polygons = region
        .polygons
        .iter()
        .map(|p| crate::geom::Polygon { outer: thin(&p.outer), holes: p.holes.iter().map(thin).collect() })
        .collect();
    crate::geom::union(&[&Region::new(polygons)])
}

fn extrude_exactly(region: &Region, thickness_mm: f64, split_junctions: bool) -> Result<Mesh, MeshError> {
    // STL stores `f32`: vertices are rounded to it first and welded by exact
    // position, so two vertices never become one only in the file.
    let mut rounded: Vec<Vec<glam::DVec2>> = region
        .rings()
        .map(|ring| {
            let mut r: Vec<glam::DVec2> = Vec::with_capacity(ring.len());
            for &p in ring {
                let q = round_to_f32(p);
                if r.last() != Some(&q) {
                    r.push(q);
                }
            }
            while r.len() > 1 && r.first() == r.last() {
                r.pop();
            }
            r
        })
        .filter(|r| r.len() >= 3)
        .collect();
    if split_junctions {
        rounded = super::split_t_junctions(&rounded);
    }
    // Where rings touch at a point (parts meeting at a corner, two holes
    // tip to tip), a shared vertex would put four walls on one edge, so all
    // copies but one move a hair apart (`geom::separate_touching_rings`).
    // The pattern stages already did so at a coarser step; this catches
    // points that rounding to `f32` made coincide.
    crate::geom::separate_touching_rings(&mut rounded, TOUCH_GAP_MM, round_to_f32);
    let key = |p: glam::DVec2| ((p.x as f32).to_bits(), (p.y as f32).to_bits());
    let mut ids: HashMap<(u32, u32), usize> = HashMap::new();
    let mut points: Vec<Point2<f64>> = Vec::new();
    let mut rings: Vec<Vec<usize>> = Vec::new();
    for ring in &rounded {
        let mut ids_of_ring: Vec<usize> = Vec::with_capacity(ring.len());
        for p in ring {
            let next = points.len();
            let id = *ids.entry(key(*p)).or_insert(next);
            if id == next {
                points.push(Point2::new(p.x, p.y));
            }
            if ids_of_ring.last() != Some(&id) {
                ids_of_ring.push(id);
            }
        }
        while ids_of_ring.len() > 1 && ids_of_ring.first() == ids_of_ring.last() {
            ids_of_ring.pop();
        }
        if ids_of_ring.len() >= 3 {
            rings.push(ids_of_ring);
        }
    }
    if rings.is_empty() {
        return Err(MeshError::Empty);
    }
    let edges: Vec<[usize; 2]> =
        rings.iter().flat_map(|r| (0..r.len()).map(move |k| [r[k], r[(k + 1) % r.len()]])).collect();
    let mut conflicts = 0;
    let cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::try_bulk_load_cdt(points.clone(), edges.clone(), |_| {
        conflicts += 1
    })
    .map_err(|e| MeshError::Tessellation(format!("{e:?}")))?;
    if conflicts > 0 || cdt.num_vertices() != points.len() {
        return Err(MeshError::Tessellation("the outline crosses itself".into()));
    }
    for &[a, b] in &edges {
        let (va, vb) = (FixedVertexHandle::from_index(a), FixedVertexHandle::from_index(b));
        if cdt.get_edge_from_neighbors(va, vb).is_none() {
            return Err(MeshError::Tessellation("a vertex lies on another ring's edge".into()));
        }
    }
    // Flood from the outer face: crossing a ring edge toggles inside/outside.
    let mut inside: Vec<Option<bool>> = vec![None; cdt.all_faces().len()];
    let mut queue = std::collections::VecDeque::new();
    for hull_edge in cdt.convex_hull() {
        for e in [hull_edge, hull_edge.rev()] {
            if let Some(face) = e.face().as_inner()
                && inside[face.fix().index()].is_none()
            {
                inside[face.fix().index()] = Some(e.as_undirected().is_constraint_edge());
                queue.push_back(face.fix());
            }
        }
    }
    while let Some(fixed) = queue.pop_front() {
        let face = cdt.face(fixed);
        let here = inside[fixed.index()].unwrap_or(false);
        for edge in face.adjacent_edges() {
            let Some(neighbour) = edge.rev().face().as_inner() else { continue };
            let slot = &mut inside[neighbour.fix().index()];
            if slot.is_none() {
                *slot = Some(here != edge.as_undirected().is_constraint_edge());
                queue.push_back(neighbour.fix());
            }
        }
    }
    let count = points.len() as u32;
    let mut mesh = Mesh { vertices: Vec::with_capacity(2 * points.len()), triangles: Vec::new() };
    mesh.vertices.extend(points.iter().map(|p| [p.x, p.y, 0.0]));
    mesh.vertices.extend(points.iter().map(|p| [p.x, p.y, thickness_mm]));
    for face in cdt.inner_faces() {
        if inside[face.fix().index()] != Some(true) {
            continue;
        }
        // Spade's faces run counter-clockwise: the top faces up.
        let [a, b, c] = face.vertices().map(|v| v.fix().index() as u32);
        mesh.triangles.push([a + count, b + count, c + count]);
        mesh.triangles.push([a, c, b]);
    }
    for ring in &rings {
        let n = ring.len();
        for k in 0..n {
            let (a, b) = (ring[k] as u32, ring[(k + 1) % n] as u32);
            // Outer rings run counter-clockwise and holes clockwise, so the
            // material is on the left of every edge and the wall faces right.
            mesh.triangles.push([a, b, b + count]);
            mesh.triangles.push([a, b + count, a + count]);
        }
    }
    Ok(mesh)
}
