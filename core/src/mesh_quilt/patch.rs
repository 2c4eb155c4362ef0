//! A patch of a curved base laid flat (the paper's section 3.1): base
//! faces within a geodesic radius of a seed face, flattened by least
//! squares conformal maps (LSCM, a sparse solve through faer) whose rows
//! follow the guidance field, scaled to keep their area, and turned so the
//! field at the seed points along `u`. A patch whose area is distorted by
//! more than [`MAX_AREA_DISTORTION`] somewhere, or that is not a disk, is
//! refused, and the caller grows a smaller one.
//!
//! Why the rows follow the field: the paper lays each patch flat by a
//! conformal map alone and turns it to the field at the seed, so the
//! swatch's straight rows become geodesics. Where the field's lines are
//! not geodesics (the parallels round a vase's belly or shoulder), a row
//! leaves its line by about `κ_g L² / 2` at a distance `L` from the seed:
//! some 5 mm across a 20 mm weave patch at 45° on a 40 mm sphere, more than
//! the weave's spacing. Neighbouring patches' threads then meet at a slant,
//! fail to stitch and are left out. With the field's lines held to
//! constant `v`, a surface of revolution turned about its axis unrolls as
//! Mercator's map (conformal, parallels straight), and rows run round it.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use rustc_hash::FxHashMap;

use faer::Mat;
use faer::prelude::Solve;
use faer::sparse::{SparseColMat, Triplet};
use glam::{DVec2, DVec3};

use super::GuidanceField;
use crate::geom::TriangleGrid;
use crate::surface::SurfaceMesh;

/// The most a patch's triangles may grow or shrink in area when laid flat
/// (the paper's factor of 4).
pub const MAX_AREA_DISTORTION: f64 = 4.0;

/// How much following the field weighs against keeping angles: the
/// residuals have the same units (a share of a triangle's size), so at 1 a
/// turn of the rows off the field costs about what as large a shear does.
/// Where the field can be followed conformally (round a surface of
/// revolution) both vanish together.
const FIELD_WEIGHT: f64 = 1.0;

/// Where following the field distorts area past [`FIELD_MAX_DISTORTION`]
/// (round the pole of a field turning about it, as on a vase's flat top,
/// Mercator's map grows without bound), the patch is laid flat nearly
/// conformally: the field at this weight only sets the turn.
const LIGHT_FIELD_WEIGHT: f64 = 1e-2;

/// The most a patch laid flat along the field may grow or shrink a
/// triangle's area, tighter than [`MAX_AREA_DISTORTION`]: Mercator's map
/// keeps angles but not size, and rivets or scales placed through it
/// would come out up to twice as wide as their neighbours, overlapping
/// them. Past this, angles and size come first.
const FIELD_MAX_DISTORTION: f64 = 2.0;

/// What sets the flat patch's size, lightly: `u` growing at unit rate along
/// the field. Conformal maps and the field's lines are alike at any
/// size, so without it the solve would shrink the patch to a point; the
/// size is set again afterwards from the areas.
const SIZE_WEIGHT: f64 = 1e-3;

/// The base's faces and which faces share an edge, for growing patches.
pub(super) struct FaceGraph {
    /// Each face's centroid, mm.
    pub centres: Vec<DVec3>,
    /// Faces across each face's edges.
    pub neighbours: Vec<Vec<u32>>,
}

impl FaceGraph {
    /// The face graph of `surface`.
    pub fn new(surface: &SurfaceMesh) -> FaceGraph {
        let triangles = surface.triangles();
        let centres = (0..triangles.len() as u32).map(|f| surface.point(f, [1.0 / 3.0; 3])).collect();
        let neighbours = triangles
            .iter()
            .enumerate()
            .map(|(f, t)| {
                (0..3)
                    .flat_map(|k| surface.faces_on_edge(t[k], t[(k + 1) % 3]).iter().copied())
                    .filter(|&g| g as usize != f)
                    .collect()
            })
            .collect();
        FaceGraph { centres, neighbours }
    }

    /// Faces within `radius_mm` of any of `seeds` along the face graph
    /// (centre to centre), with their distances, nearest first.
    pub fn within(&self, seeds: &[u32], radius_mm: f64) -> Vec<(u32, f64)> {
        self.within_where(seeds, radius_mm, |_, _| true)
    }

    /// As [`FaceGraph::within`], stepping from a face to its neighbour
    /// only where `crosses(from, to)` says it may.
    pub fn within_where(&self, seeds: &[u32], radius_mm: f64, crosses: impl Fn(u32, u32) -> bool) -> Vec<(u32, f64)> {
        let mut best: FxHashMap<u32, f64> = seeds.iter().map(|&s| (s, 0.0)).collect();
        let mut heap: BinaryHeap<Reverse<(u64, u32)>> = seeds.iter().map(|&s| Reverse((0, s))).collect();
        let mut out = Vec::new();
        while let Some(Reverse((d, f))) = heap.pop() {
            let d = f64::from_bits(d);
            if best.get(&f).is_some_and(|&b| d > b) {
                continue;
            }
            out.push((f, d));
            for &g in &self.neighbours[f as usize] {
                if !crosses(f, g) {
                    continue;
                }
                let e = d + self.centres[f as usize].distance(self.centres[g as usize]);
                if e <= radius_mm && best.get(&g).is_none_or(|&b| e < b) {
                    best.insert(g, e);
                    // Non-negative floats order as their bits do.
                    heap.push(Reverse((e.to_bits(), g)));
                }
            }
        }
        out
    }
}

/// Why a patch could not be laid flat.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Unflat {
    /// The faces do not make a disk (they wrap around a handle or a neck).
    NotDisk,
    /// Some triangle grows or shrinks by more than the limit, or flips.
    Distorted(f64),
    /// The solve failed.
    Solve,
}

/// Base faces laid flat, in millimetres of the flat plane.
pub(super) struct Patch {
    /// The base face of each patch triangle.
    faces: Vec<u32>,
    local_of_face: FxHashMap<u32, u32>,
    triangles: Vec<[u32; 3]>,
    uv: Vec<DVec2>,
    /// Each triangle's direction of `u` on the base (unit, tangent).
    u_axis: Vec<DVec3>,
    grid: TriangleGrid,
    /// The seed's triangle, in the patch's numbering.
    seed_local: usize,
    /// The largest growth or shrinking of a triangle's area.
    pub distortion: f64,
}

impl Patch {
    /// Lays `faces` of `surface` (nearest the seed first) flat, with
    /// `seed`'s centroid at `seed_uv`, the lines of `field` (a tangent per
    /// base face) held to constant `v` where that keeps area within
    /// [`FIELD_MAX_DISTORTION`], else nearly conformally
    /// ([`LIGHT_FIELD_WEIGHT`]), and the field at the seed along `+u`. Refused
    /// when even the nearly conformal map distorts past
    /// [`MAX_AREA_DISTORTION`]: the rows along the field would not do better.
    pub fn lay_flat(
        surface: &SurfaceMesh,
        faces: Vec<u32>,
        seed: u32,
        field: &GuidanceField,
        seed_uv: DVec2,
    ) -> Result<Patch, Unflat> {
        Self::lay_flat_within(surface, faces, seed, field, seed_uv, FIELD_MAX_DISTORTION)
    }

    /// As [`Patch::lay_flat`], with rows along the field where they grow or
    /// shrink no triangle's area by more than `rows_max_distortion` (below 1,
    /// never: the paper's way).
    fn lay_flat_within(
        surface: &SurfaceMesh,
        faces: Vec<u32>,
        seed: u32,
        field: &GuidanceField,
        seed_uv: DVec2,
        rows_max_distortion: f64,
    ) -> Result<Patch, Unflat> {
        let mut vertex_of: Vec<u32> = Vec::new();
        let mut local: FxHashMap<u32, u32> = FxHashMap::default();
        let triangles: Vec<[u32; 3]> = faces
            .iter()
            .map(|&f| {
                surface.triangles()[f as usize].map(|v| {
                    *local.entry(v).or_insert_with(|| {
                        vertex_of.push(v);
                        (vertex_of.len() - 1) as u32
                    })
                })
            })
            .collect();
        let positions: Vec<DVec3> = vertex_of.iter().map(|&v| surface.positions()[v as usize]).collect();
        let mut edges: Vec<(u32, u32)> = triangles
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
            .collect();
        edges.sort_unstable();
        edges.dedup();
        if positions.len() as i64 - edges.len() as i64 + triangles.len() as i64 != 1 {
            return Err(Unflat::NotDisk);
        }
        let seed_local = faces.iter().position(|&f| f == seed).ok_or(Unflat::NotDisk)?;
        let directions: Vec<DVec3> = faces.iter().map(|&f| field.direction(f)).collect();
        let area_3d: Vec<f64> = triangles.iter().map(|t| triangle_area_3d(t.map(|v| positions[v as usize]))).collect();
        let flat = Flat {
            positions: &positions,
            triangles: &triangles,
            directions: &directions,
            area_3d: &area_3d,
            seed_local,
        };
        let conformal = flat.solve(LIGHT_FIELD_WEIGHT)?;
        let (mut uv, distortion) = if rows_max_distortion >= 1.0 {
            flat.solve(FIELD_WEIGHT).ok().filter(|&(_, d)| d <= rows_max_distortion).unwrap_or(conformal)
        } else {
            conformal
        };
        // Turn and move: the field at the seed along +u, the seed where asked.
        let seed_t = triangles[seed_local];
        let jacobian = Jacobian::of(seed_t.map(|v| positions[v as usize]), seed_t.map(|v| uv[v as usize]));
        let along = jacobian.to_flat(directions[seed_local]);
        let angle = if along.length_squared() > 1e-18 { along.y.atan2(along.x) } else { 0.0 };
        let turn = DVec2::from_angle(-angle);
        let centre: DVec2 = seed_t.iter().map(|&v| turn.rotate(uv[v as usize])).sum::<DVec2>() / 3.0;
        for p in &mut uv {
            *p = turn.rotate(*p) - centre + seed_uv;
        }
        let u_axis = triangles
            .iter()
            .map(|t| Jacobian::of(t.map(|v| positions[v as usize]), t.map(|v| uv[v as usize])).du.normalize_or_zero())
            .collect();
        let (low, high) = uv.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
        let grid = TriangleGrid::new(&uv, &triangles, low, high);
        let local_of_face = faces.iter().enumerate().map(|(t, &f)| (f, t as u32)).collect();
        Ok(Patch { faces, local_of_face, triangles, uv, u_axis, grid, seed_local, distortion })
    }

    /// The base faces in the patch.
    pub fn faces(&self) -> &[u32] {
        &self.faces
    }

    /// Where a point of base face `face` lies on the flat patch.
    pub fn to_flat(&self, face: u32, barycentric: [f64; 3]) -> Option<DVec2> {
        let t = *self.local_of_face.get(&face)?;
        Some((0..3).map(|k| self.uv[self.triangles[t as usize][k] as usize] * barycentric[k]).sum())
    }

    /// The base face under `p` on the flat patch, with barycentric coordinates.
    pub fn locate(&self, p: DVec2) -> Option<(u32, [f64; 3])> {
        let (t, b) = self.grid.locate(&self.uv, &self.triangles, p)?;
        Some((self.faces[t as usize], b.map(|c| c.max(0.0)).map(|c| c / b.iter().map(|c| c.max(0.0)).sum::<f64>())))
    }

    /// Where the flat point `p` lies on the plane of the seed's face, the
    /// seed's flat map carried on past the patch's edge: on a patch of one
    /// plane (a flat cap), the point of that plane wherever `p` is.
    pub fn on_seed_plane(&self, surface: &SurfaceMesh, p: DVec2) -> DVec3 {
        let corners =
            surface.triangles()[self.faces[self.seed_local] as usize].map(|v| surface.positions()[v as usize]);
        let flat = self.triangles[self.seed_local].map(|v| self.uv[v as usize]);
        let jacobian = Jacobian::of(corners, flat);
        let d = p - flat[0];
        corners[0] + jacobian.du * d.x + jacobian.dv * d.y
    }

    /// Where the flat point `p`, perhaps past the patch's edge, lands on
    /// the patch's nearest triangle carried on flat past its edges, with
    /// that face's normal: for what reaches only a little past the edge.
    pub fn carried_on(&self, surface: &SurfaceMesh, p: DVec2) -> (DVec3, DVec3) {
        let centre = |t: &[u32; 3]| t.iter().map(|&v| self.uv[v as usize]).sum::<DVec2>() / 3.0;
        let nearest = (0..self.triangles.len())
            .min_by(|&a, &b| {
                centre(&self.triangles[a])
                    .distance_squared(p)
                    .total_cmp(&centre(&self.triangles[b]).distance_squared(p))
            })
            .unwrap_or(self.seed_local);
        let face = self.faces[nearest];
        let corners = surface.triangles()[face as usize].map(|v| surface.positions()[v as usize]);
        let flat = self.triangles[nearest].map(|v| self.uv[v as usize]);
        let jacobian = Jacobian::of(corners, flat);
        let d = p - flat[0];
        (corners[0] + jacobian.du * d.x + jacobian.dv * d.y, surface.face_normal(face))
    }

    /// The base's `u` direction (unit, tangent) over face `face`, if in the patch.
    pub fn u_axis(&self, face: u32) -> Option<DVec3> {
        self.local_of_face.get(&face).map(|&t| self.u_axis[t as usize])
    }
}

/// A disk of base triangles to lay flat, in the patch's own numbering.
struct Flat<'a> {
    positions: &'a [DVec3],
    triangles: &'a [[u32; 3]],
    /// The field's tangent over each triangle.
    directions: &'a [DVec3],
    /// Each triangle's area in space, mm².
    area_3d: &'a [f64],
    seed_local: usize,
}

impl Flat<'_> {
    /// The triangles laid flat with the field at `field_weight`
    /// ([`lscm_along`]), scaled so the quarter nearest the seed keeps its
    /// area, with the largest growth or shrinking of a triangle's area;
    /// refused past [`MAX_AREA_DISTORTION`] or where a triangle flips.
    fn solve(&self, field_weight: f64) -> Result<(Vec<DVec2>, f64), Unflat> {
        let (triangles, area_3d) = (self.triangles, self.area_3d);
        let pin = triangles[self.seed_local][0];
        let mut uv =
            lscm_along(self.positions, triangles, (self.directions, field_weight), pin).ok_or(Unflat::Solve)?;
        // LSCM keeps angles, not size: scale so the flat area is the base's.
        let area_uv = |uv: &[DVec2], t: &[u32; 3]| {
            let [a, b, c] = t.map(|v| uv[v as usize]);
            0.5 * (b - a).perp_dot(c - a)
        };
        // The scale is true near the seed, where the patch is matched and
        // most of what it adds lies: the faces are nearest first, and the
        // nearest quarter sets it.
        let core = (triangles.len() / 4).max(1);
        let core_flat: f64 = triangles[..core].iter().map(|t| area_uv(&uv, t)).sum();
        if core_flat.abs() <= f64::MIN_POSITIVE {
            return Err(Unflat::Solve);
        }
        // A mirror image (the solve does not know which side is up) is
        // turned over: patch triangles run counter-clockwise like the base's.
        let flip = if core_flat < 0.0 { -1.0 } else { 1.0 };
        let scale = (area_3d[..core].iter().sum::<f64>() / core_flat.abs()).sqrt();
        for p in &mut uv {
            *p = DVec2::new(p.x, flip * p.y) * scale;
        }
        let mut distortion: f64 = 1.0;
        for (t, a3) in triangles.iter().zip(area_3d) {
            let a2 = area_uv(&uv, t);
            if a2 <= 0.0 || *a3 <= 0.0 {
                return Err(Unflat::Distorted(f64::INFINITY));
            }
            distortion = distortion.max((a2 / a3).max(a3 / a2));
        }
        if distortion > MAX_AREA_DISTORTION {
            return Err(Unflat::Distorted(distortion));
        }
        Ok((uv, distortion))
    }
}

/// Area of a triangle in space.
pub(super) fn triangle_area_3d([a, b, c]: [DVec3; 3]) -> f64 {
    0.5 * (b - a).cross(c - a).length()
}

/// The linear map from a flat triangle to its base triangle.
struct Jacobian {
    du: DVec3,
    dv: DVec3,
}

impl Jacobian {
    fn of(p: [DVec3; 3], q: [DVec2; 3]) -> Jacobian {
        let (e1, e2) = (q[1] - q[0], q[2] - q[0]);
        let det = e1.perp_dot(e2);
        let (f1, f2) = (p[1] - p[0], p[2] - p[0]);
        // [f1 f2] = J [e1 e2], so J = [f1 f2] [e1 e2]^-1.
        let inv = [[e2.y / det, -e2.x / det], [-e1.y / det, e1.x / det]];
        Jacobian { du: f1 * inv[0][0] + f2 * inv[1][0], dv: f1 * inv[0][1] + f2 * inv[1][1] }
    }

    /// The flat vector whose image is nearest `d` (least squares).
    fn to_flat(&self, d: DVec3) -> DVec2 {
        let (a, b, c) = (self.du.dot(self.du), self.du.dot(self.dv), self.dv.dot(self.dv));
        let (x, y) = (self.du.dot(d), self.dv.dot(d));
        let det = a * c - b * b;
        if det.abs() <= f64::MIN_POSITIVE {
            return DVec2::ZERO;
        }
        DVec2::new((c * x - b * y) / det, (a * y - b * x) / det)
    }
}

/// Least squares conformal map (Lévy et al. 2002) of a disk-like mesh,
/// with the lines of `directions` (a tangent per triangle) held to
/// constant `v` at `field_weight` ([`FIELD_WEIGHT`]) and `u` growing about one unit per mm
/// along them ([`SIZE_WEIGHT`]); `pin` at the origin. `None` if the solve
/// fails.
///
/// Each triangle adds, in its own flat frame, with `∇φ_m` the gradient of
/// its corner `m`'s hat function: the conformal rows `Σ W_m (u_m + i v_m)`,
/// zero for a similarity; `Σ v_m ∇φ_m · f`, the change of `v` along the
/// field `f`; and `Σ u_m ∇φ_m · f − 1`. Each is scaled by the square root
/// of the triangle's area, so that the sums are integrals.
fn lscm_along(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    (directions, field_weight): (&[DVec3], f64),
    pin: u32,
) -> Option<Vec<DVec2>> {
    let n = positions.len();
    // Unknowns: u then v of each vertex but the pin.
    let mut column = vec![usize::MAX; n];
    let mut free = 0;
    for (v, c) in column.iter_mut().enumerate() {
        if v != pin as usize {
            *c = free;
            free += 1;
        }
    }
    if free == 0 {
        return None;
    }
    let unknowns = 2 * free;
    let mut normal: FxHashMap<(usize, usize), f64> =
        FxHashMap::with_capacity_and_hasher(triangles.len() * 40, Default::default());
    let mut rhs = Mat::<f64>::zeros(unknowns, 1);
    let mut add_row = |coefficients: [(f64, f64); 3], t: &[u32; 3], constant: f64| {
        let mut entries: Vec<(usize, f64)> = Vec::with_capacity(6);
        for (m, &(cu, cv)) in coefficients.iter().enumerate() {
            let v = t[m] as usize;
            // The pin sits at the origin: its terms vanish.
            if v != pin as usize {
                entries.push((column[v], cu));
                entries.push((free + column[v], cv));
            }
        }
        for &(i, wi) in &entries {
            for &(j, wj) in &entries {
                *normal.entry((i, j)).or_default() += wi * wj;
            }
            rhs[(i, 0)] -= wi * constant;
        }
    };
    for (t, &direction) in triangles.iter().zip(directions) {
        let p = t.map(|v| positions[v as usize]);
        let x_axis = (p[1] - p[0]).normalize_or_zero();
        let normal_dir = (p[1] - p[0]).cross(p[2] - p[0]);
        let area2 = normal_dir.length();
        if area2 <= f64::MIN_POSITIVE {
            continue;
        }
        let y_axis = normal_dir.cross(x_axis) / area2;
        let q = p.map(|c| DVec2::new((c - p[0]).dot(x_axis), (c - p[0]).dot(y_axis)));
        let w = 1.0 / area2.sqrt();
        // W_m: the edge opposite corner m, as a complex number; the
        // residual Σ W_m (u_m + i v_m) vanishes for a similarity.
        let edges: [DVec2; 3] = std::array::from_fn(|m| q[(m + 2) % 3] - q[(m + 1) % 3]);
        let c: [DVec2; 3] = edges.map(|e| e * w);
        // Real row: Σ a u − b v; imaginary row: Σ b u + a v.
        add_row(std::array::from_fn(|m| (c[m].x, -c[m].y)), t, 0.0);
        add_row(std::array::from_fn(|m| (c[m].y, c[m].x)), t, 0.0);
        // ∇φ_m = perp(edge_m) / area2; times √(area2) that is perp(edge_m) w.
        let f = DVec2::new(direction.dot(x_axis), direction.dot(y_axis)).normalize_or_zero();
        if f == DVec2::ZERO {
            continue;
        }
        let along: [f64; 3] = edges.map(|e| e.perp().dot(f) * w);
        let (field, size) = (field_weight.sqrt(), SIZE_WEIGHT.sqrt());
        add_row(along.map(|a| (0.0, field * a)), t, 0.0);
        add_row(along.map(|a| (size * a, 0.0)), t, -size * area2.sqrt());
    }
    let mut entries: Vec<((usize, usize), f64)> = normal.into_iter().collect();
    entries.sort_unstable_by_key(|&(key, _)| key);
    let triplets: Vec<Triplet<usize, usize, f64>> = entries.iter().map(|&((r, c), w)| Triplet::new(r, c, w)).collect();
    let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(unknowns, unknowns, &triplets).ok()?;
    // The normal equations are symmetric positive definite (the pin fixes
    // the place, the field the turn, the size term the size): Cholesky,
    // reading the lower side only, is several times cheaper than LU.
    let solved = matrix.sp_cholesky(faer::Side::Lower).ok()?.solve(&rhs);
    let uv: Vec<DVec2> = (0..n)
        .map(|v| {
            if v == pin as usize {
                DVec2::ZERO
            } else {
                DVec2::new(solved[(column[v], 0)], solved[(free + column[v], 0)])
            }
        })
        .collect();
    uv.iter().all(|p| p.is_finite()).then_some(uv)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::builtin_base;

    /// A cylinder's side unrolls without distortion: LSCM must find that.
    #[test]
    fn a_cylinder_side_lays_flat_without_stretch() {
        let surface = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
        let graph = FaceGraph::new(&surface);
        let seed = (0..surface.triangles().len() as u32)
            .find(|&f| (graph.centres[f as usize].z - 30.0).abs() < 1.0 && surface.face_normal(f).z.abs() < 0.1)
            .unwrap();
        let faces: Vec<u32> = graph.within(&[seed], 20.0).into_iter().map(|(f, _)| f).collect();
        let tangent = DVec3::Z.cross(surface.face_normal(seed)).normalize();
        let field = GuidanceField::around_axis(&surface);
        let patch = Patch::lay_flat(&surface, faces.clone(), seed, &field, DVec2::new(5.0, 5.0)).unwrap();
        assert!(patch.distortion < 1.02, "distortion {}", patch.distortion);
        // Lengths between base vertices' images match their distance
        // along the surface (around the cylinder and up it).
        let seed_uv = patch.to_flat(seed, [1.0 / 3.0; 3]).unwrap();
        assert!(seed_uv.distance(DVec2::new(5.0, 5.0)) < 1e-9);
        for &f in faces.iter().step_by(37) {
            let p = graph.centres[f as usize];
            let q = graph.centres[seed as usize];
            let around = 25.0 * (p.truncate().angle_to(q.truncate())).abs();
            let up = p.z - q.z;
            let flat = patch.to_flat(f, [1.0 / 3.0; 3]).unwrap() - seed_uv;
            assert!((flat.x.abs() - around).abs() < 0.3, "around {around} flat {flat}");
            assert!((flat.y.abs() - up.abs()).abs() < 0.3, "up {up} flat {flat}");
            // Up the cylinder is +v: u runs along the field, v to its left.
            assert!(flat.y * up >= -1e-6);
        }
        assert!(patch.u_axis(seed).unwrap().dot(tangent) > 0.999);
        let (face, b) = patch.locate(seed_uv).unwrap();
        assert_eq!(face, seed);
        assert!(b.iter().all(|&c| (c - 1.0 / 3.0).abs() < 1e-6));
    }

    /// The parallel through a seed on a sphere's upper half is no geodesic
    /// (it bends by 1/30 mm⁻¹ at 45° on a 30 mm sphere). Laid flat with
    /// the field round the axis, it is still one straight row, `v` the
    /// same all along it; a conformal map alone bends it off the row by
    /// about 1 mm, 8 mm from the seed (κ L² / 2).
    #[test]
    fn the_parallel_through_the_seed_lays_flat_as_a_straight_row() {
        let surface = SurfaceMesh::new(builtin_base("sphere").unwrap()).unwrap();
        let graph = FaceGraph::new(&surface);
        let centre = DVec3::new(0.0, 0.0, 30.0);
        let latitude = |p: DVec3| ((p - centre).z / (p - centre).length()).asin();
        let seed = (0..surface.triangles().len() as u32)
            .min_by(|&a, &b| {
                let off = |f: u32| (latitude(graph.centres[f as usize]) - 45f64.to_radians()).abs();
                off(a).total_cmp(&off(b))
            })
            .unwrap();
        let faces: Vec<u32> = graph.within(&[seed], 12.0).into_iter().map(|(f, _)| f).collect();
        let field = GuidanceField::around_axis(&surface);
        // Rows along the field up to the general limit (this patch needs
        // more than the tighter one), or never.
        let bent = |rows_max_distortion: f64| {
            let patch = Patch::lay_flat_within(&surface, faces.clone(), seed, &field, DVec2::ZERO, rows_max_distortion)
                .unwrap();
            let seed_latitude = latitude(graph.centres[seed as usize]);
            let mut worst: f64 = 0.0;
            let mut along: f64 = 0.0;
            for &f in &faces {
                let p = graph.centres[f as usize];
                // Faces on the parallel: within 0.1 mm of it, up or down.
                if (latitude(p) - seed_latitude).abs() * 30.0 < 0.1 {
                    let flat = patch.to_flat(f, [1.0 / 3.0; 3]).unwrap();
                    worst = worst.max(flat.y.abs());
                    along = along.max(flat.x.abs());
                }
            }
            assert!(along > 7.0, "the parallel runs {along} mm in the patch");
            worst
        };
        let (followed, conformal) = (bent(MAX_AREA_DISTORTION), bent(0.0));
        assert!(followed < 0.25, "the row bends {followed} mm off the parallel");
        assert!(conformal > 0.7, "the conformal map alone bends it {conformal} mm: this test tests nothing");
    }

    /// A whole sphere is no disk; half of one distorts within the limit
    /// only if small enough.
    #[test]
    fn too_much_of_a_sphere_is_refused() {
        let surface = SurfaceMesh::new(builtin_base("sphere").unwrap()).unwrap();
        let graph = FaceGraph::new(&surface);
        let all: Vec<u32> = (0..surface.triangles().len() as u32).collect();
        let field = GuidanceField::around_axis(&surface);
        assert_eq!(Patch::lay_flat(&surface, all, 0, &field, DVec2::ZERO).err(), Some(Unflat::NotDisk));
        let seed = 5000;
        let small: Vec<u32> = graph.within(&[seed], 15.0).into_iter().map(|(f, _)| f).collect();
        let patch = Patch::lay_flat(&surface, small, seed, &field, DVec2::ZERO).unwrap();
        assert!(patch.distortion < MAX_AREA_DISTORTION);
        let big: Vec<u32> = graph.within(&[seed], 80.0).into_iter().map(|(f, _)| f).collect();
        assert!(matches!(
            Patch::lay_flat(&surface, big, seed, &field, DVec2::ZERO),
            Err(Unflat::Distorted(_) | Unflat::NotDisk)
        ));
    }
}
