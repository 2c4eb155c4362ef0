//! Built-in base models to draw on, modelled here as surfaces of revolution
//! (a profile turned about the `z` axis): closed, watertight, outward
//! facing, standing on `z = 0`, in millimetres.

use std::f64::consts::{PI, TAU};

use glam::DVec2;

use crate::mesh::Mesh;

/// Names of the built-in bases, as the command line takes them.
pub const BASE_NAMES: [&str; 6] = ["vase", "egg", "cylinder", "cone", "sphere", "torus"];

/// Steps around the axis: with the profile steps below, each base has
/// about 20,000 triangles, as a model someone would bring.
const SEGMENTS: usize = 128;

/// Longest step along a profile, mm.
const PROFILE_STEP_MM: f64 = 1.5;

/// A built-in base by name (see [`BASE_NAMES`]), or `None`.
///
/// ```
/// use tracery_core::surface::builtin_base;
/// let vase = builtin_base("vase").unwrap();
/// assert!(vase.sanity_check().is_ok());
/// assert_eq!(vase.shell_count(), 1);
/// assert!(builtin_base("teapot").is_none());
/// ```
pub fn builtin_base(name: &str) -> Option<Mesh> {
    let profile = match name {
        "vase" => vase_profile(),
        "egg" => egg_profile(),
        "cylinder" => polyline_profile(&[(0.0, 0.0), (25.0, 0.0), (25.0, 60.0), (0.0, 60.0)]),
        "cone" => polyline_profile(&[(0.0, 0.0), (30.0, 0.0), (12.0, 60.0), (0.0, 60.0)]),
        "sphere" => arc_profile(DVec2::new(0.0, 30.0), 30.0, -0.5 * PI, 0.5 * PI),
        "torus" => return Some(revolve_loop(&arc_profile(DVec2::new(30.0, 10.0), 10.0, 0.0, TAU))),
        _ => return None,
    };
    Some(revolve(&profile))
}

/// Points `(radius, z)` along straight pieces, each cut into steps no longer
/// than [`PROFILE_STEP_MM`].
fn polyline_profile(corners: &[(f64, f64)]) -> Vec<DVec2> {
    let mut out = vec![DVec2::from(corners[0])];
    for pair in corners.windows(2) {
        let (a, b) = (DVec2::from(pair[0]), DVec2::from(pair[1]));
        let n = (a.distance(b) / PROFILE_STEP_MM).ceil().max(1.0) as usize;
        out.extend((1..=n).map(|k| a.lerp(b, k as f64 / n as f64)));
    }
    out
}

/// An arc of a circle from angle `from` to `to` (radians, counter-clockwise
/// in the `(radius, z)` plane); a full turn leaves out the repeated end.
fn arc_profile(centre: DVec2, radius: f64, from: f64, to: f64) -> Vec<DVec2> {
    let n = ((to - from).abs() * radius / PROFILE_STEP_MM).ceil().max(8.0) as usize;
    let full = (to - from).abs() >= TAU - 1e-12;
    let points = if full { n } else { n + 1 };
    (0..points)
        .map(|k| {
            let p = centre + DVec2::from_angle(from + (to - from) * k as f64 / n as f64) * radius;
            // The poles lie on the axis exactly.
            if !full && (k == 0 || k == n) { DVec2::new(0.0, p.y) } else { p }
        })
        .collect()
}

/// An egg 60 mm tall, blunt end down.
fn egg_profile() -> Vec<DVec2> {
    let (half_height, half_width, blunt) = (30.0, 21.0, 0.15);
    let n = 80;
    (0..=n)
        .map(|k| {
            let t = PI * k as f64 / n as f64;
            let radius = if k == 0 || k == n { 0.0 } else { half_width * t.sin() * (1.0 + blunt * t.cos()) };
            DVec2::new(radius, half_height * (1.0 - t.cos()))
        })
        .collect()
}

/// A vase 80 mm tall: foot, belly, neck and lip on a smooth curve, closed
/// flat at the bottom and the top.
fn vase_profile() -> Vec<DVec2> {
    let wall = [(22.0, 0.0), (30.0, 25.0), (20.0, 48.0), (12.0, 62.0), (17.0, 80.0)].map(DVec2::from);
    // Centripetal enough for these few gentle points: a uniform Catmull-Rom
    // through the wall, ends repeated.
    let at = |i: isize| wall[i.clamp(0, wall.len() as isize - 1) as usize];
    let mut out = polyline_profile(&[(0.0, 0.0), (wall[0].x, wall[0].y)]);
    for i in 0..wall.len() as isize - 1 {
        let (p0, p1, p2, p3) = (at(i - 1), at(i), at(i + 1), at(i + 2));
        let n = (p1.distance(p2) / PROFILE_STEP_MM).ceil() as usize;
        for k in 1..=n {
            let t = k as f64 / n as f64;
            let (t2, t3) = (t * t, t * t * t);
            out.push(
                0.5 * (2.0 * p1
                    + (p2 - p0) * t
                    + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2
                    + (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3),
            );
        }
    }
    let lip = wall[wall.len() - 1];
    out.extend(polyline_profile(&[(lip.x, lip.y), (0.0, lip.y)]).into_iter().skip(1));
    out
}

/// Turns a profile from the axis back to the axis (`radius` 0 at both ends,
/// going out, up and back in) about `z`: a closed surface with a pole at
/// each end, facing out.
fn revolve(profile: &[DVec2]) -> Mesh {
    let inner = &profile[1..profile.len() - 1];
    let mut mesh = Mesh::default();
    let ring = |i: usize, j: usize| (1 + i * SEGMENTS + j % SEGMENTS) as u32;
    mesh.vertices.push([0.0, 0.0, profile[0].y]);
    for p in inner {
        for j in 0..SEGMENTS {
            let angle = DVec2::from_angle(TAU * j as f64 / SEGMENTS as f64) * p.x;
            mesh.vertices.push([angle.x, angle.y, p.y]);
        }
    }
    let top = mesh.vertices.len() as u32;
    mesh.vertices.push([0.0, 0.0, profile[profile.len() - 1].y]);
    for j in 0..SEGMENTS {
        // Around the axis, then along the profile: the cross product of the
        // two points out.
        mesh.triangles.push([0, ring(0, j + 1), ring(0, j)]);
        for i in 0..inner.len() - 1 {
            let (a, b, c, d) = (ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j));
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([a, c, d]);
        }
        mesh.triangles.push([ring(inner.len() - 1, j), ring(inner.len() - 1, j + 1), top]);
    }
    mesh
}

/// Turns a closed profile (counter-clockwise in the `(radius, z)` plane,
/// away from the axis) about `z`: a torus-like closed surface, facing out.
fn revolve_loop(profile: &[DVec2]) -> Mesh {
    let m = profile.len();
    let mut mesh = Mesh::default();
    for p in profile {
        for j in 0..SEGMENTS {
            let angle = DVec2::from_angle(TAU * j as f64 / SEGMENTS as f64) * p.x;
            mesh.vertices.push([angle.x, angle.y, p.y]);
        }
    }
    let ring = |i: usize, j: usize| ((i % m) * SEGMENTS + j % SEGMENTS) as u32;
    for i in 0..m {
        for j in 0..SEGMENTS {
            let (a, b, c, d) = (ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j));
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([a, c, d]);
        }
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_base_is_closed_faces_out_and_has_the_volume_of_its_shape() {
        for name in BASE_NAMES {
            let mesh = builtin_base(name).unwrap();
            assert!(mesh.sanity_check().is_ok(), "{name}: {:?}", mesh.sanity_check());
            assert_eq!(mesh.shell_count(), 1, "{name}");
            assert!((10_000..40_000).contains(&mesh.triangles.len()), "{name}: {}", mesh.triangles.len());
            assert!(mesh.signed_volume() > 0.0, "{name} faces in");
        }
        // Inscribed polygons lose a little volume: 128 segments lose 0.04%,
        // the torus's 42-gon section 0.4%.
        let within = |got: f64, want: f64| (got - want).abs() / want < 5e-3;
        assert!(within(builtin_base("cylinder").unwrap().signed_volume(), PI * 25.0 * 25.0 * 60.0));
        assert!(within(builtin_base("sphere").unwrap().signed_volume(), 4.0 / 3.0 * PI * 30.0f64.powi(3)));
        assert!(within(builtin_base("torus").unwrap().signed_volume(), 2.0 * PI * PI * 30.0 * 100.0));
    }
}
