//! A model hollowed into a shell of even wall, for carving a pattern out of
//! it: the surface as it is, and a copy moved in by the wall, facing in.
//!
//! Each vertex moves to the point a wall away from the planes of all its
//! faces (least squares), not along its smooth normal: at a crease such as
//! a vase's rim the smooth normal leans toward the larger side, and a
//! vertex moved a wall along it ends up nearer the other side than the
//! wall, so the shell is thin there (or folds).

use glam::{DMat3, DVec3};

use super::SurfaceMesh;
use super::surface_mesh::for_each_corner;
use crate::mesh::Mesh;

/// Why a model could not be hollowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum HollowError {
    /// The wall is not a positive number.
    #[error("the wall {0} mm must be a positive number")]
    Wall(f64),
    /// Moving the surface in by the wall folds it somewhere.
    #[error(
        "the model is too thin or too sharply curved near ({:.1}, {:.1}, {:.1}) mm for a {wall_mm} mm wall; try a thinner wall",
        at_mm[0], at_mm[1], at_mm[2]
    )]
    TooThin {
        /// The wall asked for, mm.
        wall_mm: f64,
        /// Where the inner surface comes too close to the outer one.
        at_mm: [f64; 3],
    },
}

/// Share of the wall an inner vertex must keep from the outer surface:
/// below it the inner surface has folded over (a sharp crease, a part
/// thinner than twice the wall).
const KEPT_SHARE: f64 = 0.5;

/// `surface` as a shell `wall_mm` thick: two shells, the model facing out
/// and the inner surface facing in.
///
/// ```
/// use tracery_core::surface::{SurfaceMesh, builtin_base, hollow};
/// let egg = SurfaceMesh::new(builtin_base("egg").unwrap()).unwrap();
/// let shell = hollow(&egg, 2.0).unwrap();
/// assert!(shell.sanity_check().is_ok());
/// assert_eq!(shell.shell_count(), 2);
/// assert!(shell.signed_volume() < 0.25 * egg.mesh().signed_volume());
/// ```
pub fn hollow(surface: &SurfaceMesh, wall_mm: f64) -> Result<Mesh, HollowError> {
    if !(wall_mm.is_finite() && wall_mm > 0.0) {
        return Err(HollowError::Wall(wall_mm));
    }
    let outer = surface.mesh();
    let count = outer.vertices.len() as u32;
    let mut shell = outer.clone();
    let offsets = inward_offsets(surface);
    let positions = surface.positions();
    let mut inner: Vec<DVec3> =
        positions.iter().zip(&offsets).map(|(&p, d)| push_clear(surface, p - *d * wall_mm, wall_mm)).collect();
    untangle(surface, &mut inner, wall_mm);
    for (v, &p) in inner.iter().enumerate() {
        let kept = surface.closest_point(p.to_array()).position_mm.distance(p);
        if kept < KEPT_SHARE * wall_mm {
            return Err(HollowError::TooThin { wall_mm, at_mm: positions[v].to_array() });
        }
    }
    // Where the model is too thin for the wall, the inner surface stays
    // turned over after untangling: refused, not folded.
    if let Some(face) = turned_faces(surface, &inner).first() {
        let corner = outer.triangles[*face][0];
        return Err(HollowError::TooThin { wall_mm, at_mm: positions[corner as usize].to_array() });
    }
    shell.vertices.extend(inner.iter().map(|p| p.to_array()));
    shell.triangles.extend(outer.triangles.iter().map(|&[a, b, c]| [a + count, c + count, b + count]));
    Ok(shell)
}

/// Faces of the inner surface `inner` (one point per vertex of `surface`)
/// that face the other way from their face on the model.
fn turned_faces(surface: &SurfaceMesh, inner: &[DVec3]) -> Vec<usize> {
    surface
        .triangles()
        .iter()
        .enumerate()
        .filter(|(face, [a, b, c])| {
            let (a, b, c) = (inner[*a as usize], inner[*b as usize], inner[*c as usize]);
            (b - a).cross(c - a).dot(surface.face_normal(*face as u32)) <= 0.0
        })
        .map(|(face, _)| face)
        .collect()
}

/// Rounds of untangling the inner surface.
const UNTANGLE_ROUNDS: usize = 30;

/// Beside a crease, vertices pushed clear of the other side's faces crowd
/// onto the crease's offset and can pass one another, turning faces over.
/// Each round moves the vertices of turned faces, and their neighbours, to
/// the middle of their neighbours and clear of the surface again, which
/// spreads the crowd along the offset crease.
fn untangle(surface: &SurfaceMesh, inner: &mut [DVec3], wall_mm: f64) {
    let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); inner.len()];
    for &[a, b, c] in surface.triangles() {
        for (from, to) in [(a, b), (b, c), (c, a), (b, a), (c, b), (a, c)] {
            if !neighbours[from as usize].contains(&to) {
                neighbours[from as usize].push(to);
            }
        }
    }
    for _ in 0..UNTANGLE_ROUNDS {
        let turned = turned_faces(surface, inner);
        if turned.is_empty() {
            return;
        }
        let mut moving: Vec<u32> = Vec::new();
        for face in turned {
            for &v in &surface.triangles()[face] {
                moving.push(v);
                moving.extend(&neighbours[v as usize]);
            }
        }
        moving.sort_unstable();
        moving.dedup();
        for v in moving {
            let around = &neighbours[v as usize];
            if around.is_empty() {
                continue;
            }
            let middle = around.iter().map(|&n| inner[n as usize]).sum::<DVec3>() / around.len() as f64;
            inner[v as usize] = push_clear(surface, middle, wall_mm);
        }
    }
}

/// Rounds of pushing an inner vertex clear of the surface.
const PUSH_ROUNDS: usize = 8;

/// `inner` moved, if it is nearer the surface than `wall_mm` (beside a
/// crease, within a wall of another face), straight away from its nearest
/// surface point to a wall from it; repeated, since clearing one part of
/// the surface can come nearer another (the two sides of a rim).
fn push_clear(surface: &SurfaceMesh, mut inner: DVec3, wall_mm: f64) -> DVec3 {
    for _ in 0..PUSH_ROUNDS {
        let nearest = surface.closest_point(inner.to_array()).position_mm;
        let away = inner - nearest;
        let distance = away.length();
        if distance >= wall_mm * (1.0 - 1e-3) || distance <= 1e-9 * wall_mm {
            break;
        }
        inner = nearest + away * (wall_mm / distance);
    }
    inner
}

/// Pulls a vertex's offset toward its smooth normal where its faces leave
/// a direction undetermined (flat or smooth surroundings): a share of the
/// mean of the faces' `n nᵀ`, whose eigenvalues sum to 1.
const REGULARIZATION: f64 = 1e-2;

/// Longest offset per mm of wall: beyond it (a needle's tip) the vertex
/// moves along its smooth normal instead, and the thin-wall check decides.
const MAX_OFFSET: f64 = 3.0;

/// For each vertex, the displacement per mm of wall that puts it a wall
/// away from the plane of each of its faces, in the least-squares sense:
/// `d` minimizing `Σ wᵢ (nᵢ·d − 1)²` over its faces' unit normals `nᵢ`
/// weighted by their corner angles.
fn inward_offsets(surface: &SurfaceMesh) -> Vec<DVec3> {
    let positions = surface.positions();
    let mut normal_matrix = vec![DMat3::ZERO; positions.len()];
    let mut normal_sum = vec![DVec3::ZERO; positions.len()];
    let mut weight = vec![0.0; positions.len()];
    for_each_corner(positions, surface.triangles(), |v, n, angle| {
        if !angle.is_finite() {
            return;
        }
        let v = v as usize;
        normal_matrix[v] += DMat3::from_cols(n * n.x, n * n.y, n * n.z) * angle;
        normal_sum[v] += n * angle;
        weight[v] += angle;
    });
    (0..positions.len())
        .map(|v| {
            let smooth = surface.vertex_normal(v as u32);
            if weight[v] <= 0.0 {
                return smooth;
            }
            let a = normal_matrix[v] * (1.0 / weight[v]) + DMat3::IDENTITY * REGULARIZATION;
            let b = normal_sum[v] / weight[v] + smooth * REGULARIZATION;
            let d = a.inverse() * b;
            if d.is_finite() && d.length() <= MAX_OFFSET && d.dot(smooth) > 0.0 { d } else { smooth }
        })
        .collect()
}
