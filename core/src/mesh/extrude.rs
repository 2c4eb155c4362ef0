//! Extrusion of a planar region into a closed, watertight solid.

use rayon::prelude::*;
use rustc_hash::FxHashMap;

use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use super::Mesh;
use super::swept_faces::swept_faces;
use crate::geom::{Rect, Region};

/// How far apart parts that touch at a single point are moved, in mm.
const TOUCH_GAP_MM: f64 = 1e-3;

/// How close to another ring's edge, in `f32` steps at the pattern's largest
/// coordinate, a vertex counts as on it where parts came out welded: rounding to `f32` moves each
/// coordinate by half a step, and the triangulation's own predicates round
/// too. About 10⁻⁴ mm on a 200 mm pattern, far below any printer.
const F32_CONTACT_ULPS: f64 = 4.0;

/// Spikes narrower than this at their base are dropped before meshing
/// ([`crate::geom::without_needles`]): far below any feature a printer or a
/// laser makes, and above the rounding of `f32` for coordinates up to about
/// 800 mm.
const NEEDLE_MM: f64 = 1e-4;

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
    /// The solid laid on a surface would be open or non-manifold once
    /// written as `f32`.
    #[error(
        "the band laid on the surface would not be a closed solid ({0} of its points fall together in the file); try another seed or a narrower band"
    )]
    Collapsed(usize),
    /// The tessellator failed on the pattern's outline.
    #[error("the pattern's outline could not be triangulated: {0}")]
    Tessellation(String),
}

/// Extrudes `region` (millimetres, in the plane `z = 0`) to `thickness_mm`:
/// a closed, 2-manifold, consistently oriented mesh with one shell per component.
///
/// Top and bottom faces fill the rings on their own points, and the walls
/// join the same vertices, so the mesh is watertight by construction. The
/// faces come from a sweep-line triangulation ([`i_triangle`], on an exact
/// integer grid) where the rings neither cross nor touch and its triangles
/// check out, and otherwise from a constrained Delaunay triangulation
/// ([`spade`], in `f64`) whose constraint edges are exactly the rings'
/// edges, inside and outside told apart by flooding it from its outer face,
/// flipping at every ring edge; an outline that crosses itself is repaired.
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
    checked_thickness(thickness_mm)?;
    let make = |contacts: bool| {
        with_repairs(region, |region, split_junctions| {
            extrude_exactly(region, thickness_mm, split_junctions, None, contacts)
        })
    };
    let mesh = make(false)?;
    // Each polygon is one body. A vertex of one part within rounding of
    // another part's edge (parts the pattern stages moved apart by less
    // than a short edge allows) is put into that edge by the triangulation,
    // welding the two: seen on `vectorian195` along a wave, parts 10⁻⁵ mm
    // apart, one pair welded. Such vertices are then found first
    // ([`F32_CONTACT_ULPS`]) and moved off like touching points. Only
    // then: looking for them on every pattern cost the corpus sweep a
    // quarter more time (159 s to 198 s).
    if mesh.shell_count() < region.polygons.len()
        && let Ok(apart) = make(true)
        && apart.shell_count() > mesh.shell_count()
    {
        return Ok(apart);
    }
    Ok(mesh)
}

/// The inside of `region` cut into well-shaped triangles (no angle under
/// 20°, no edge much over `edge_mm`; spade's Delaunay refinement): an open
/// sheet in the plane `z = 0`, counter-clockwise seen from `+z`, whose
/// boundary edges are the rings' edges (split where refinement split them).
/// It is for a pattern that will be bent: a long sliver split until it
/// follows a curved surface would crumble into thousands. The bent sheet is
/// made solid with [`super::thicken`].
///
/// ```
/// use tracery_core::mesh::triangulate_fine;
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// let strip = vec![DVec2::new(0.0, 0.0), DVec2::new(40.0, 0.0), DVec2::new(40.0, 2.0), DVec2::new(0.0, 2.0)];
/// let sheet = triangulate_fine(&Region::new(vec![Polygon { outer: strip, holes: vec![] }]), 1.0).unwrap();
/// let area: f64 = sheet.triangles.iter().map(|t| {
///     let [a, b, c] = t.map(|i| sheet.vertices[i as usize]);
///     0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
/// }).sum();
/// assert!((area - 80.0).abs() < 1e-9);
/// ```
pub fn triangulate_fine(region: &Region, edge_mm: f64) -> Result<Mesh, MeshError> {
    with_repairs(region, |region, split_junctions| extrude_exactly(region, 0.0, split_junctions, Some(edge_mm), false))
}

/// `Ok` for a thickness a solid can have: a positive number of mm.
pub(crate) fn checked_thickness(thickness_mm: f64) -> Result<(), MeshError> {
    if thickness_mm.is_finite() && thickness_mm > 0.0 { Ok(()) } else { Err(MeshError::Thickness(thickness_mm)) }
}

/// `make` on the region as given and, where its outline cannot be
/// triangulated, on the region [`repaired`], then with its T-junctions
/// split as well.
fn with_repairs(region: &Region, make: impl Fn(&Region, bool) -> Result<Mesh, MeshError>) -> Result<Mesh, MeshError> {
    match make(region, false) {
        Err(MeshError::Tessellation(_)) => {
            let repaired = repaired(region);
            match make(&repaired, false) {
                // Still a vertex on another ring's edge: make it a shared point.
                Err(MeshError::Tessellation(_)) => make(&repaired, true),
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

fn extrude_exactly(
    region: &Region,
    thickness_mm: f64,
    split_junctions: bool,
    fine: Option<f64>,
    contacts: bool,
) -> Result<Mesh, MeshError> {
    // STL stores `f32`: vertices are rounded to it first and welded by exact
    // position, so two vertices never become one only in the file.
    // Each ring with the polygon it belongs to, for the sweep below.
    let (mut rounded, rounded_polygon): (Vec<Vec<glam::DVec2>>, Vec<usize>) = region
        .polygons
        .iter()
        .enumerate()
        .flat_map(|(p, polygon)| polygon.rings().map(move |ring| (p, ring)))
        .map(|(p, ring)| {
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
            crate::geom::without_needles(&mut r, NEEDLE_MM);
            (r, p)
        })
        .filter(|(r, _)| r.len() >= 3)
        .unzip();
    if split_junctions {
        crate::geom::insert_edge_contacts(&mut rounded, 0.0);
    } else if contacts {
        let extent = rounded.iter().flatten().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        crate::geom::insert_edge_contacts(&mut rounded, F32_CONTACT_ULPS * f64::from(f32::EPSILON) * extent);
    }
    // Where rings touch at a point (parts meeting at a corner, two holes
    // tip to tip), a shared vertex would put four walls on one edge, so all
    // copies but one move a hair apart (`geom::separate_touching_rings`).
    // The pattern stages already did so at a coarser step; this catches
    // points that rounding to `f32` made coincide.
    crate::geom::separate_touching_rings(&mut rounded, TOUCH_GAP_MM, round_to_f32);
    let key = |p: glam::DVec2| ((p.x as f32).to_bits(), (p.y as f32).to_bits());
    let mut ids: FxHashMap<(u32, u32), usize> = FxHashMap::default();
    let mut points: Vec<Point2<f64>> = Vec::new();
    let mut rings: Vec<Vec<usize>> = Vec::new();
    let mut polygon_of: Vec<usize> = Vec::new();
    for (ring, &polygon) in rounded.iter().zip(&rounded_polygon) {
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
            polygon_of.push(polygon);
        }
    }
    if rings.is_empty() {
        return Err(MeshError::Empty);
    }
    if let Some(edge_mm) = fine {
        let all: Vec<usize> = (0..rings.len()).collect();
        return Ok(refined(constrained(&points, &ring_edges(&rings, &all))?.cdt, edge_mm));
    }
    // Most outlines are simple, and a sweep fills them in a tenth of the time;
    // the constrained triangulation takes the rest, and tells why it cannot
    // where it cannot (then the outline is repaired).
    let faces = match swept_faces(&flat(&points), &rings, &polygon_of) {
        Some(faces) => faces,
        None => constrained_faces(&mut points, &mut rings)?,
    };
    Ok(solid(&points, &rings, faces, thickness_mm))
}

/// The triangles filling `rings` (indices into `points`), counter-clockwise,
/// from constrained Delaunay triangulations; an error where an outline
/// crosses itself or another. Large groups of rings are cut into slabs,
/// whose cuts add points to `points` and to the rings they cross.
fn constrained_faces(points: &mut Vec<Point2<f64>>, rings: &mut [Vec<usize>]) -> Result<Vec<[u32; 3]>, MeshError> {
    // Rings whose bounding boxes are apart cannot cross or touch, so each
    // group of overlapping ones is triangulated on its own, groups on every
    // core; each group is checked for crossings exactly as the whole was.
    // Large groups are cut into slabs, triangulated on every core as well.
    let groups = overlapping_groups(points, rings);
    let mut jobs: Vec<(usize, Vec<[usize; 2]>)> = Vec::new();
    for (g, group) in groups.iter().enumerate() {
        match super::slabs::slab_edges(points, rings, group) {
            Some(slabs) => jobs.extend(slabs.into_iter().map(|edges| (g, edges))),
            None => jobs.push((g, ring_edges(rings, group))),
        }
    }
    let points = &*points;
    let faces: Vec<Result<Vec<[u32; 3]>, MeshError>> =
        jobs.par_iter().map(|(_, edges)| inside_faces(points, edges)).collect();
    let mut by_group: Vec<Vec<Result<Vec<[u32; 3]>, MeshError>>> = groups.iter().map(|_| Vec::new()).collect();
    for ((g, _), result) in jobs.iter().zip(faces) {
        by_group[*g].push(result);
    }
    let mut faces: Vec<Vec<[u32; 3]>> = Vec::with_capacity(groups.len());
    for (group, results) in groups.iter().zip(by_group) {
        match results.into_iter().collect::<Result<Vec<_>, _>>() {
            Ok(slabs) => faces.extend(slabs),
            // A slab that could not be triangulated: the group whole, with
            // the crossings its rings now have, which is checked as before.
            // The first error, whichever thread met it first.
            Err(_) => faces.push(inside_faces(points, &ring_edges(rings, group))?),
        }
    }
    Ok(faces.concat())
}

/// The points as `DVec2`.
fn flat(points: &[Point2<f64>]) -> Vec<glam::DVec2> {
    points.iter().map(|p| glam::DVec2::new(p.x, p.y)).collect()
}

/// The solid between `faces` (counter-clockwise triangles of `points`
/// filling `rings`) at `z = 0` and at `thickness_mm`, with walls along
/// the rings' edges.
fn solid(points: &[Point2<f64>], rings: &[Vec<usize>], faces: Vec<[u32; 3]>, thickness_mm: f64) -> Mesh {
    let count = points.len() as u32;
    let mut mesh = Mesh { vertices: Vec::with_capacity(2 * points.len()), triangles: Vec::new() };
    mesh.vertices.extend(points.iter().map(|p| [p.x, p.y, 0.0]));
    mesh.vertices.extend(points.iter().map(|p| [p.x, p.y, thickness_mm]));
    for [a, b, c] in faces {
        // The faces run counter-clockwise: the top faces up.
        mesh.triangles.push([a + count, b + count, c + count]);
        mesh.triangles.push([a, c, b]);
    }
    for ring in rings {
        let n = ring.len();
        for k in 0..n {
            let (a, b) = (ring[k] as u32, ring[(k + 1) % n] as u32);
            // Outer rings run counter-clockwise and holes clockwise, so the
            // material is on the left of every edge and the wall faces right.
            mesh.triangles.push([a, b, b + count]);
            mesh.triangles.push([a, b + count, a + count]);
        }
    }
    mesh
}

/// The rings (indices into `rings`) in groups whose bounding boxes overlap,
/// directly or through others; boxes that only touch overlap. Two rings in
/// different groups are apart.
fn overlapping_groups(points: &[Point2<f64>], rings: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let boxes: Vec<Rect> = rings
        .iter()
        .map(|ring| {
            Rect::from_points(ring.iter().map(|&i| glam::DVec2::new(points[i].x, points[i].y)))
                .expect("a ring has at least three points")
        })
        .collect();
    let mut by_left: Vec<usize> = (0..rings.len()).collect();
    by_left.sort_unstable_by(|&a, &b| boxes[a].min.x.total_cmp(&boxes[b].min.x));
    let mut sets = crate::disjoint_sets::DisjointSets::new(rings.len());
    // A sweep along x: only boxes still open at a box's left edge can overlap it.
    let mut open: Vec<usize> = Vec::new();
    for &r in &by_left {
        open.retain(|&o| boxes[o].max.x >= boxes[r].min.x);
        for &o in &open {
            if boxes[o].overlaps(&boxes[r]) {
                sets.join(o, r);
            }
        }
        open.push(r);
    }
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut group_of: FxHashMap<usize, usize> = FxHashMap::default();
    for r in 0..rings.len() {
        let root = sets.find(r);
        let g = *group_of.entry(root).or_insert_with(|| {
            groups.push(Vec::new());
            groups.len() - 1
        });
        groups[g].push(r);
    }
    groups
}

/// The edges of the rings in `group`, as indices into the points.
fn ring_edges(rings: &[Vec<usize>], group: &[usize]) -> Vec<[usize; 2]> {
    group
        .iter()
        .map(|&r| &rings[r])
        .flat_map(|ring| (0..ring.len()).map(|k| [ring[k], ring[(k + 1) % ring.len()]]))
        .collect()
}

/// A constrained Delaunay triangulation of some of the points, with for
/// each of its vertices its index in the points, and its constraint edges
/// as indices of its vertices.
struct Constrained {
    cdt: ConstrainedDelaunayTriangulation<Point2<f64>>,
    global: Vec<usize>,
    edges: Vec<[usize; 2]>,
}

/// The constrained Delaunay triangulation whose constraints are `edges`
/// (indices into `points`). An error where an outline crosses itself or
/// another, or a vertex lies on another edge.
fn constrained(points: &[Point2<f64>], global_edges: &[[usize; 2]]) -> Result<Constrained, MeshError> {
    let mut local: FxHashMap<usize, usize> = FxHashMap::default();
    let mut global: Vec<usize> = Vec::new();
    let mut local_of = |g: usize| {
        *local.entry(g).or_insert_with(|| {
            global.push(g);
            global.len() - 1
        })
    };
    let edges: Vec<[usize; 2]> = global_edges.iter().map(|&[a, b]| [local_of(a), local_of(b)]).collect();
    let group_points: Vec<Point2<f64>> = global.iter().map(|&g| points[g]).collect();
    let mut conflicts = 0;
    let cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::try_bulk_load_cdt(group_points, edges.clone(), |_| {
        conflicts += 1
    })
    .map_err(|e| MeshError::Tessellation(format!("{e:?}")))?;
    if conflicts > 0 || cdt.num_vertices() != global.len() {
        return Err(MeshError::Tessellation("the outline crosses itself".into()));
    }
    for &[a, b] in &edges {
        let (va, vb) = (FixedVertexHandle::from_index(a), FixedVertexHandle::from_index(b));
        if cdt.get_edge_from_neighbors(va, vb).is_none() {
            return Err(MeshError::Tessellation("a vertex lies on another ring's edge".into()));
        }
    }
    Ok(Constrained { cdt, global, edges })
}

/// The triangles inside the closed outlines made by `edges` (indices into
/// `points`, each with the inside on its left), counter-clockwise, as
/// indices into `points`.
fn inside_faces(points: &[Point2<f64>], edges: &[[usize; 2]]) -> Result<Vec<[u32; 3]>, MeshError> {
    let Constrained { cdt, global, edges: local_edges } = constrained(points, edges)?;
    // Crossing a ring edge toggles inside and outside.
    let inside = crate::geom::faces_inside(&cdt);
    // Rings keep their material on their left. An outline that doubles
    // back within `f32` rounding of itself can come out of the rounding
    // with material on the wrong side of it and no edge crossing: the
    // triangulation holds, but the flood fills the wrong side, and the
    // walls would not meet the faces (an open solid). Such an outline is
    // repaired as one that crosses itself would be, or refused.
    let filled = |face: spade::handles::FaceHandle<'_, spade::handles::PossiblyOuterTag, _, _, _, _>| {
        face.as_inner().is_some_and(|f| inside[f.fix().index()] == Some(true))
    };
    for &[a, b] in &local_edges {
        let (va, vb) = (FixedVertexHandle::from_index(a), FixedVertexHandle::from_index(b));
        let edge = cdt.get_edge_from_neighbors(va, vb).expect("every ring edge is in the triangulation");
        if !filled(edge.face()) || filled(edge.rev().face()) {
            return Err(MeshError::Tessellation("an outline has material on its wrong side".into()));
        }
    }
    Ok(cdt
        .inner_faces()
        .filter(|face| inside[face.fix().index()] == Some(true))
        .map(|face| face.vertices().map(|v| global[v.fix().index()] as u32))
        .collect())
}

/// Triangles smaller than this are never refined, mm².
const MIN_REFINED_AREA_MM2: f64 = 1e-3;

/// Most vertices refinement may add: a bound on time and memory whatever
/// the outline.
const MAX_REFINEMENT_VERTICES: usize = 400_000;

/// The inside faces of a refined triangulation (refinement's own flood
/// from the outside) as a sheet at `z = 0`.
fn refined(mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>>, edge_mm: f64) -> Mesh {
    use spade::{AngleLimit, RefinementParameters};
    let result = cdt.refine(
        RefinementParameters::<f64>::new()
            .exclude_outer_faces(true)
            .with_angle_limit(AngleLimit::from_deg(20.0))
            .with_max_allowed_area(0.5 * edge_mm * edge_mm)
            // Parts a micrometre apart (touching parts moved apart) are left
            // alone: splitting around them would make points closer than a
            // printer, or an STL's f32, can tell apart.
            .with_min_required_area(MIN_REFINED_AREA_MM2)
            .with_max_additional_vertices(MAX_REFINEMENT_VERTICES),
    );
    let excluded: std::collections::HashSet<_> = result.excluded_faces.into_iter().collect();
    let sheet = Mesh {
        vertices: cdt.vertices().map(|v| [v.position().x, v.position().y, 0.0]).collect(),
        // Spade's faces run counter-clockwise.
        triangles: cdt
            .inner_faces()
            .filter(|face| !excluded.contains(&face.fix()))
            .map(|face| face.vertices().map(|v| v.fix().index() as u32))
            .collect(),
    };
    // Vertices refinement placed outside the material are left out.
    compact(sheet).0
}

/// Drops vertices no triangle uses; with, for each vertex kept, its index
/// in `mesh` (so that values kept beside the vertices can follow them).
///
/// ```
/// use tracery_core::mesh::{Mesh, compact};
/// let mesh = Mesh { vertices: vec![[9.0; 3], [0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], triangles: vec![[1, 2, 3]] };
/// let (out, kept) = compact(mesh);
/// assert_eq!(out.triangles, vec![[0, 1, 2]]);
/// assert_eq!(kept, vec![1, 2, 3]);
/// ```
pub fn compact(mesh: Mesh) -> (Mesh, Vec<u32>) {
    let mut index = vec![u32::MAX; mesh.vertices.len()];
    let mut kept = Vec::new();
    let mut out = Mesh { vertices: Vec::new(), triangles: Vec::with_capacity(mesh.triangles.len()) };
    for t in &mesh.triangles {
        out.triangles.push(t.map(|v| {
            if index[v as usize] == u32::MAX {
                index[v as usize] = out.vertices.len() as u32;
                out.vertices.push(mesh.vertices[v as usize]);
                kept.push(v);
            }
            index[v as usize]
        }));
    }
    (out, kept)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points and index rings of a loop's outline with a wavy rim that
    /// crosses any vertical line many times: `n` points on each rim.
    fn wavy_loop(n: usize) -> (Vec<Point2<f64>>, Vec<Vec<usize>>) {
        let rim = |radius: f64| -> Vec<Point2<f64>> {
            (0..n)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / n as f64;
                    let r = radius + 1.5 * (60.0 * t).sin();
                    // On the f32 grid, as the meshing rounds them.
                    Point2::new(f64::from((r * t.cos()) as f32), f64::from((r * t.sin()) as f32))
                })
                .collect()
        };
        let mut points = rim(44.0);
        let mut inner = rim(30.0);
        inner.reverse();
        points.extend(inner);
        (points, vec![(0..n).collect(), (n..2 * n).collect()])
    }

    /// Signed area of the polygon through `points` at `indices`.
    fn ring_area(points: &[Point2<f64>], indices: impl IntoIterator<Item = usize>) -> f64 {
        let ring: Vec<glam::DVec2> = indices.into_iter().map(|i| glam::DVec2::new(points[i].x, points[i].y)).collect();
        crate::geom::signed_area(&ring)
    }

    fn area(points: &[Point2<f64>], faces: &[[u32; 3]]) -> f64 {
        faces.iter().map(|t| ring_area(points, t.map(|i| i as usize))).sum()
    }

    #[test]
    fn a_large_group_is_cut_into_slabs_that_fill_the_outline() {
        // The sweep takes such outlines; the constrained triangulation is
        // what it falls back on, so it is checked on its own.
        let (mut points, mut rings) = wavy_loop(12_000);
        let expected: f64 = rings.iter().map(|r| ring_area(&points, r.iter().copied())).sum();
        let before = points.len();
        let faces = constrained_faces(&mut points, &mut rings).expect("a simple outline");
        // The slabs' cut lines add points where they cross the rims.
        assert!(points.len() > before, "no slabs: {} points", points.len());
        let filled = area(&points, &faces);
        assert!((filled - expected).abs() < 1e-9 * expected, "{filled} against {expected}");
        assert!(faces.iter().all(|t| area(&points, &[*t]) > 0.0));
    }

    #[test]
    fn the_sweep_fills_a_large_loop_with_its_own_points() {
        let (points, rings) = wavy_loop(12_000);
        let expected: f64 = rings.iter().map(|r| ring_area(&points, r.iter().copied())).sum();
        let faces = swept_faces(&flat(&points), &rings, &[0, 0]).expect("a simple outline");
        // n + 2h − 2 triangles on the outline's own points.
        assert_eq!(faces.len(), points.len());
        let filled = area(&points, &faces);
        assert!((filled - expected).abs() < 1e-9 * expected, "{filled} against {expected}");
    }

    #[test]
    fn parts_that_rounding_lays_edge_on_edge_stay_two_bodies() {
        // A trapezoid's short base a hair above a square's top edge, far
        // less than an `f32` step at 150 mm: rounded for the file, the base
        // lies on the edge, and the triangulation would weld the two parts
        // along it.
        use glam::DVec2;
        let (x, y) = (150.0, 150.0);
        let square = vec![
            DVec2::new(x - 2.0, y - 4.0),
            DVec2::new(x + 2.0, y - 4.0),
            DVec2::new(x + 2.0, y),
            DVec2::new(x - 2.0, y),
        ];
        let tip = vec![
            DVec2::new(x - 0.3, y + 1e-9),
            DVec2::new(x + 0.3, y + 1e-9),
            DVec2::new(x + 2.0, y + 3.0),
            DVec2::new(x - 2.0, y + 3.0),
        ];
        let region = Region::new(vec![
            crate::geom::Polygon { outer: square, holes: vec![] },
            crate::geom::Polygon { outer: tip, holes: vec![] },
        ]);
        let mesh = extrude(&region, 2.0).unwrap();
        assert_eq!(mesh.shell_count(), 2);
        assert!(mesh.sanity_check().is_ok(), "{:?}", mesh.sanity_check());
    }
}
