//! Helpers shared by the quilting tests, each written here apart from the
//! code under test: closedness by counting directed edges, crossings by a
//! segment–triangle test, bases turned about `z`, bare area, and a mesh
//! split into its bodies.

// Each test file uses some of these.
#![allow(dead_code)]

use std::collections::HashMap;

use glam::DVec3;
use tracery_core::control::Control;
use tracery_core::mesh::Mesh;
use tracery_core::mesh_quilt::{Element, GuidanceField, Quilt, Settings, Swatch, builtin_swatch, quilt_surface};
use tracery_core::surface::SurfaceMesh;

/// Every directed edge used once, and its reverse once.
pub fn closed(e: &Element) -> bool {
    let mut count: HashMap<(u32, u32), i32> = HashMap::new();
    for t in &e.triangles {
        for k in 0..3 {
            *count.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    count.iter().all(|(&(a, b), &n)| n == 1 && count.get(&(b, a)) == Some(&1))
}

/// Whether segment `p`–`q` passes through triangle `t` (Möller–Trumbore).
pub fn segment_hits(p: DVec3, q: DVec3, t: [DVec3; 3]) -> bool {
    let d = q - p;
    let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
    let h = d.cross(e2);
    let a = e1.dot(h);
    if a.abs() < 1e-12 {
        return false;
    }
    let s = p - t[0];
    let u = s.dot(h) / a;
    let qv = s.cross(e1);
    let v = d.dot(qv) / a;
    let along = e2.dot(qv) / a;
    (0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && (0.0..=1.0).contains(&along)
}

pub fn boxes_meet(a: (DVec3, DVec3), b: (DVec3, DVec3)) -> bool {
    a.0.cmple(b.1).all() && b.0.cmple(a.1).all()
}

/// Whether two elements' surfaces cross: an edge of one through a triangle of the other.
pub fn cross(a: &Element, b: &Element) -> bool {
    if !boxes_meet(a.bounds(), b.bounds()) {
        return false;
    }
    let tris =
        |e: &Element| -> Vec<[DVec3; 3]> { e.triangles.iter().map(|t| t.map(|i| e.vertices[i as usize])).collect() };
    let tri_box = |t: &[DVec3; 3]| (t[0].min(t[1]).min(t[2]), t[0].max(t[1]).max(t[2]));
    let (ta, tb) = (tris(a), tris(b));
    for x in &ta {
        for y in &tb {
            if !boxes_meet(tri_box(x), tri_box(y)) {
                continue;
            }
            for k in 0..3 {
                if segment_hits(x[k], x[(k + 1) % 3], *y) || segment_hits(y[k], y[(k + 1) % 3], *x) {
                    return true;
                }
            }
        }
    }
    false
}

pub fn crossing_pairs(elements: &[Element]) -> usize {
    let mut n = 0;
    for i in 0..elements.len() {
        for j in i + 1..elements.len() {
            n += cross(&elements[i], &elements[j]) as usize;
        }
    }
    n
}

/// Whether an element's surface passes through itself: an edge through a
/// triangle sharing no corner with it. Candidate pairs come from a sweep
/// along x over the triangles' boxes, not from the library's grid.
pub fn crosses_itself(e: &Element) -> bool {
    let tris: Vec<[DVec3; 3]> = e.triangles.iter().map(|t| t.map(|v| e.vertices[v as usize])).collect();
    let tri_box = |t: &[DVec3; 3]| (t[0].min(t[1]).min(t[2]), t[0].max(t[1]).max(t[2]));
    let boxes: Vec<(DVec3, DVec3)> = tris.iter().map(tri_box).collect();
    let mut order: Vec<usize> = (0..tris.len()).collect();
    order.sort_by(|&i, &j| boxes[i].0.x.total_cmp(&boxes[j].0.x));
    for (k, &i) in order.iter().enumerate() {
        for &j in order[k + 1..].iter().take_while(|&&j| boxes[j].0.x <= boxes[i].1.x) {
            let (t, u) = (e.triangles[i], e.triangles[j]);
            if u.iter().any(|v| t.contains(v)) || !boxes_meet(boxes[i], boxes[j]) {
                continue;
            }
            let (x, y) = (tris[i], tris[j]);
            if (0..3).any(|k| segment_hits(y[k], y[(k + 1) % 3], x) || segment_hits(x[k], x[(k + 1) % 3], y)) {
                return true;
            }
        }
    }
    false
}

/// A closed solid turned about `z`: its profile runs from the axis at
/// `z = 0` through `corners` (radius, height), the last on the axis, in
/// steps of at most 0.75 mm, with 64 segments round.
pub fn turned(corners: &[(f64, f64)]) -> SurfaceMesh {
    let profile: Vec<(f64, f64)> = {
        let mut p = vec![(0.0, 0.0)];
        for w in corners.windows(2).fold(vec![corners[0]], |mut acc, w| {
            let steps = (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1).div_euclid(0.75).max(1.0) as usize;
            acc.extend((1..=steps).map(|k| {
                let t = k as f64 / steps as f64;
                (w[0].0 + (w[1].0 - w[0].0) * t, w[0].1 + (w[1].1 - w[0].1) * t)
            }));
            acc
        }) {
            p.push(w);
        }
        p
    };
    let segments = 64u32;
    let mut mesh = Mesh::default();
    let inner = &profile[1..profile.len() - 1];
    mesh.vertices.push([0.0, 0.0, 0.0]);
    for &(r, z) in inner {
        for k in 0..segments {
            let a = std::f64::consts::TAU * k as f64 / segments as f64;
            mesh.vertices.push([r * a.cos(), r * a.sin(), z]);
        }
    }
    let top = mesh.vertices.len() as u32;
    mesh.vertices.push([0.0, 0.0, profile[profile.len() - 1].1]);
    let ring = |i: usize, k: u32| 1 + i as u32 * segments + k % segments;
    for k in 0..segments {
        mesh.triangles.push([0, ring(0, k + 1), ring(0, k)]);
        let last = inner.len() - 1;
        mesh.triangles.push([top, ring(last, k), ring(last, k + 1)]);
        for i in 0..last {
            mesh.triangles.push([ring(i, k), ring(i, k + 1), ring(i + 1, k + 1)]);
            mesh.triangles.push([ring(i, k), ring(i + 1, k + 1), ring(i + 1, k)]);
        }
    }
    assert!(mesh.sanity_check().is_ok());
    SurfaceMesh::new(mesh).unwrap()
}

/// The weave at half size laid round `base` along its parallels, each
/// element checked closed and none crossing another; with the swatch.
pub fn woven_round(base: &SurfaceMesh) -> (Swatch, Quilt) {
    woven_round_seeded(base, Settings::default().seed)
}

/// [`woven_round`] with the random choices of `seed`.
pub fn woven_round_seeded(base: &SurfaceMesh, seed: u64) -> (Swatch, Quilt) {
    let swatch = builtin_swatch("weave").unwrap().scaled(0.5);
    let mut settings = Settings::default();
    settings.seed = seed;
    let quilt =
        quilt_surface(&swatch, base, &GuidanceField::around_axis(base), &settings, &Control::default()).unwrap();
    assert!(quilt.elements.iter().all(closed));
    assert_eq!(crossing_pairs(&quilt.elements), 0);
    (swatch, quilt)
}

/// The share of `base`'s area, all but the faces it stands on, farther
/// than `within_mm` from every vertex of `elements`: where the texture has
/// a hole. Measured at face centres, weighted by area.
pub fn bare_share_of_faces(base: &SurfaceMesh, elements: &[Element], within_mm: f64) -> f64 {
    bare_share_where(base, elements, within_mm, |normal, _| normal.z >= -0.9)
}

/// As [`bare_share_of_faces`], over the faces for which `counts(unit
/// normal, centre)` holds.
pub fn bare_share_where(
    base: &SurfaceMesh,
    elements: &[Element],
    within_mm: f64,
    counts: impl Fn(DVec3, DVec3) -> bool,
) -> f64 {
    let cell = |p: DVec3| (p / within_mm).floor().as_ivec3();
    let mut grid: HashMap<glam::IVec3, Vec<DVec3>> = HashMap::new();
    for v in elements.iter().flat_map(|e| e.vertices.iter()) {
        grid.entry(cell(*v)).or_default().push(*v);
    }
    let (mut bare, mut all) = (0.0, 0.0);
    for t in base.triangles() {
        let [a, b, c] = t.map(|v| base.positions()[v as usize]);
        let normal = (b - a).cross(c - a);
        let (area, centre) = (0.5 * normal.length(), (a + b + c) / 3.0);
        if !counts(normal.normalize(), centre) {
            continue;
        }
        let home = cell(centre);
        let near = (-1..=1).any(|i| {
            (-1..=1).any(|j| {
                (-1..=1).any(|k| {
                    grid.get(&(home + glam::IVec3::new(i, j, k)))
                        .is_some_and(|vs| vs.iter().any(|v| v.distance(centre) <= within_mm))
                })
            })
        });
        all += area;
        if !near {
            bare += area;
        }
    }
    bare / all
}

/// The mesh's bodies (triangles joined through shared corners), each as
/// its vertices.
pub fn bodies(mesh: &Mesh) -> Vec<Vec<DVec3>> {
    let mut parent: Vec<usize> = (0..mesh.vertices.len()).collect();
    fn root(parent: &mut [usize], mut v: usize) -> usize {
        while parent[v] != v {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        v
    }
    for t in &mesh.triangles {
        for k in 1..3 {
            let (a, b) = (root(&mut parent, t[0] as usize), root(&mut parent, t[k] as usize));
            parent[a] = b;
        }
    }
    let used: std::collections::BTreeSet<usize> = mesh.triangles.iter().flatten().map(|&v| v as usize).collect();
    let mut by_root: std::collections::BTreeMap<usize, Vec<DVec3>> = Default::default();
    for v in used {
        let r = root(&mut parent, v);
        by_root.entry(r).or_default().push(DVec3::from_array(mesh.vertices[v]));
    }
    by_root.into_values().collect()
}
