//! Closed solids the built-in swatches are modelled from: tubes swept along
//! paths, tori, and solids of revolution. Each comes out closed and
//! consistently oriented outward.

use std::f64::consts::TAU;

use glam::{DMat3, DVec2, DVec3};

use super::Element;

/// A tube of `radius_mm` swept along `path` with `sides` sides. A closed
/// path makes a ring; an open one is capped flat at both ends.
///
/// ```
/// use tracery_core::mesh_quilt::tube;
/// use glam::DVec3;
/// let rod = tube(&[DVec3::ZERO, DVec3::X * 5.0, DVec3::X * 10.0], 1.0, 8, false);
/// assert!(rod.is_closed());
/// ```
pub fn tube(path: &[DVec3], radius_mm: f64, sides: usize, closed: bool) -> Element {
    let n = path.len();
    let tangent = |i: usize| -> DVec3 {
        let (a, b) = if closed {
            (path[(i + n - 1) % n], path[(i + 1) % n])
        } else {
            (path[i.saturating_sub(1)], path[(i + 1).min(n - 1)])
        };
        (b - a).normalize()
    };
    // Frames carried along the path by parallel transport, so the tube does
    // not twist.
    let mut normal = tangent(0).any_orthonormal_vector();
    let mut out = Element::default();
    for (i, &centre) in path.iter().enumerate() {
        let t = tangent(i);
        normal = (normal - t * normal.dot(t)).normalize();
        let binormal = t.cross(normal);
        for s in 0..sides {
            let angle = TAU * s as f64 / sides as f64;
            out.vertices.push(centre + radius_mm * (normal * angle.cos() + binormal * angle.sin()));
        }
    }
    let ring = |i: usize, s: usize| (i * sides + s % sides) as u32;
    let segments = if closed { n } else { n - 1 };
    for i in 0..segments {
        let j = (i + 1) % n;
        for s in 0..sides {
            out.triangles.push([ring(i, s), ring(j, s + 1), ring(j, s)]);
            out.triangles.push([ring(i, s), ring(i, s + 1), ring(j, s + 1)]);
        }
    }
    if !closed {
        for (i, outward) in [(0, -tangent(0)), (n - 1, tangent(n - 1))] {
            let centre = out.vertices.len() as u32;
            out.vertices.push(path[i]);
            for s in 0..sides {
                let tri = [centre, ring(i, s), ring(i, s + 1)];
                let [a, b, c] = tri.map(|k| out.vertices[k as usize]);
                let facing = (b - a).cross(c - a).dot(outward) > 0.0;
                out.triangles.push(if facing { tri } else { [tri[0], tri[2], tri[1]] });
            }
        }
    }
    orient_outward(&mut out);
    out
}

/// A ring of `major_mm` radius and `minor_mm` tube radius around `centre`,
/// in the plane spanned by the rotation's `x` and `y` axes.
pub fn torus(centre: DVec3, rotation: DMat3, major_mm: f64, minor_mm: f64, segments: usize, sides: usize) -> Element {
    let path: Vec<DVec3> = (0..segments)
        .map(|k| {
            let a = TAU * k as f64 / segments as f64;
            centre + rotation * DVec3::new(major_mm * a.cos(), major_mm * a.sin(), 0.0)
        })
        .collect();
    tube(&path, minor_mm, sides, true)
}

/// A solid of revolution about the `z` axis through `centre`: `profile`
/// gives (radius, height) from a point on the axis to another point on the
/// axis, and is turned through `sides` steps (6 makes a hexagon).
pub fn lathe(centre: DVec3, profile: &[DVec2], sides: usize, rotation: DMat3) -> Element {
    let inner = &profile[1..profile.len() - 1];
    let mut out = Element::default();
    let at = |r: f64, z: f64, s: usize| {
        let a = TAU * s as f64 / sides as f64;
        centre + rotation * DVec3::new(r * a.cos(), r * a.sin(), z)
    };
    out.vertices.push(centre + rotation * DVec3::new(0.0, 0.0, profile[0].y));
    for p in inner {
        for s in 0..sides {
            out.vertices.push(at(p.x, p.y, s));
        }
    }
    let top = out.vertices.len() as u32;
    out.vertices.push(centre + rotation * DVec3::new(0.0, 0.0, profile[profile.len() - 1].y));
    let ring = |i: usize, s: usize| (1 + i * sides + s % sides) as u32;
    for s in 0..sides {
        out.triangles.push([0, ring(0, s + 1), ring(0, s)]);
        out.triangles.push([top, ring(inner.len() - 1, s), ring(inner.len() - 1, s + 1)]);
    }
    for i in 0..inner.len() - 1 {
        for s in 0..sides {
            out.triangles.push([ring(i, s), ring(i, s + 1), ring(i + 1, s + 1)]);
            out.triangles.push([ring(i, s), ring(i + 1, s + 1), ring(i + 1, s)]);
        }
    }
    orient_outward(&mut out);
    out
}

/// A closed profile (radius, height), away from the axis, turned about the
/// `z` axis through `centre` in `sides` steps: a ring, or a nut with 6.
pub fn lathe_ring(centre: DVec3, profile: &[DVec2], sides: usize) -> Element {
    let m = profile.len();
    let mut out = Element::default();
    for s in 0..sides {
        let a = TAU * s as f64 / sides as f64;
        for p in profile {
            out.vertices.push(centre + DVec3::new(p.x * a.cos(), p.x * a.sin(), p.y));
        }
    }
    let at = |s: usize, k: usize| ((s % sides) * m + k % m) as u32;
    for s in 0..sides {
        for k in 0..m {
            out.triangles.push([at(s, k), at(s + 1, k), at(s + 1, k + 1)]);
            out.triangles.push([at(s, k), at(s + 1, k + 1), at(s, k + 1)]);
        }
    }
    orient_outward(&mut out);
    out
}

/// Turns every triangle over if the element encloses a negative volume.
pub(super) fn orient_outward(element: &mut Element) {
    if element.to_mesh().signed_volume() < 0.0 {
        for t in &mut element.triangles {
            t.swap(1, 2);
        }
    }
}
