//! Brute-force distances from points to triangles, for checking that
//! geometry lies on a surface without the code under test.
#![allow(dead_code)]

use glam::DVec3;

/// Distance from `p` to triangle `abc` (Ericson, Real-Time Collision
/// Detection, 5.1.5).
pub fn to_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return p.distance(a);
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return p.distance(b);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return p.distance(a + ab * (d1 / (d1 - d3)));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return p.distance(c);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return p.distance(a + ac * (d2 / (d2 - d6)));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return p.distance(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    let denom = 1.0 / (va + vb + vc);
    p.distance(a + ab * (vb * denom) + ac * (vc * denom))
}

/// Distance from `p` to the nearest of `triangles` (every one is tried).
pub fn to_mesh(vertices: &[[f64; 3]], triangles: &[[u32; 3]], p: [f64; 3]) -> f64 {
    let p = DVec3::from(p);
    triangles
        .iter()
        .map(|t| t.map(|i| DVec3::from(vertices[i as usize])))
        .map(|[a, b, c]| to_triangle(p, a, b, c))
        .fold(f64::INFINITY, f64::min)
}
