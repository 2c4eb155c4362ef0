//! Curves drawn on the built-in bases, checked against the base mesh by a
//! brute-force distance of the tests' own, not the surface's search tree.

#[path = "../../tests/common/distance.rs"]
mod distance;
use distance::to_triangle;
use glam::DVec3;
use tracery_core::report::Timings;
use tracery_core::surface::{Drawn, SurfaceMesh, SurfaceSettings, builtin_base, draw_on};

fn drawn(base: &str, points: &str, closed: bool, band_mm: f64) -> (SurfaceMesh, Drawn) {
    let surface = SurfaceMesh::new(builtin_base(base).unwrap()).unwrap();
    let mut settings = SurfaceSettings::default();
    settings.points_mm = SurfaceSettings::parse_points(points).unwrap();
    settings.closed = closed;
    let on = draw_on(&surface, &settings, band_mm, &mut Timings::default()).unwrap();
    (surface, on)
}

/// Distance from `p` to the nearest triangle of `surface` within `reach_mm`
/// of it (infinity when none is).
fn to_surface(surface: &SurfaceMesh, p: DVec3, reach_mm: f64) -> f64 {
    let positions = surface.positions();
    surface
        .triangles()
        .iter()
        .map(|t| t.map(|i| positions[i as usize]))
        .filter(|[a, b, c]| a.distance(p).min(b.distance(p)).min(c.distance(p)) < reach_mm)
        .map(|[a, b, c]| to_triangle(p, a, b, c))
        .fold(f64::INFINITY, f64::min)
}

fn longest_edge_mm(surface: &SurfaceMesh) -> f64 {
    let positions = surface.positions();
    surface
        .triangles()
        .iter()
        .flat_map(|t| (0..3).map(move |k| positions[t[k] as usize].distance(positions[t[(k + 1) % 3] as usize])))
        .fold(0.0, f64::max)
}

#[test]
fn curve_points_and_the_middles_of_their_segments_lie_on_the_surface() {
    for (base, points, closed) in [
        ("egg", "21,0,20;15,-15,30;0,-19,40", false),
        ("vase", "30,0,25;0,30,25;-30,0,25;0,-30,25", true),
        ("torus", "30,0,20;40,0,10;30,0,0;20,0,10", true),
    ] {
        let (surface, on) = drawn(base, points, closed, 8.0);
        let tolerance = 1e-6 * surface.size_mm();
        let reach = longest_edge_mm(&surface) + 1.0;
        let p = &on.curve.points_mm;
        assert!(p.len() > 50, "{base}: {} points", p.len());
        let pairs = if closed { p.len() } else { p.len() - 1 };
        let mut worst: f64 = 0.0;
        for k in 0..pairs {
            let (a, b) = (p[k], p[(k + 1) % p.len()]);
            // A segment cutting a chord across a mesh edge would leave the
            // surface in its middle.
            worst = worst.max(to_surface(&surface, a, reach)).max(to_surface(&surface, 0.5 * (a + b), reach));
        }
        assert!(worst <= tolerance, "{base}: a curve point {worst:e} mm off the surface (allowed {tolerance:e})");
    }
}

#[test]
fn frames_turn_gradually_along_the_curve() {
    for (base, points, closed, most_deg_per_mm) in [
        // A ring of radius 30 turns its normal by 1.9° per mm.
        ("vase", "30,0,25;0,30,25;-30,0,25;0,-30,25", true, 4.0),
        ("egg", "21,0,20;15,-15,30;0,-19,40", false, 6.0),
        ("torus", "40,0,10;0,40,10;-40,0,10;0,-40,10", true, 4.0),
    ] {
        let (_, on) = drawn(base, points, closed, 8.0);
        let step_mm = 0.25;
        let steps = (on.frames.length_mm / step_mm) as usize;
        let mut worst: f64 = 0.0;
        let mut last = on.frames.at(&on.curve, 0.0);
        for k in 1..=steps {
            let here = on.frames.at(&on.curve, k as f64 * step_mm);
            let turn = here.1.angle_between(last.1).max(here.2.angle_between(last.2));
            worst = worst.max(turn.to_degrees() / step_mm);
            // Frames stay orthonormal.
            assert!(here.1.dot(here.2).abs() < 1e-6, "{base}: across and normal not square");
            last = here;
        }
        assert!(worst <= most_deg_per_mm, "{base}: frames turn {worst:.2}°/mm (at most {most_deg_per_mm})");
    }
}

#[test]
fn a_ring_through_four_points_at_one_height_stays_at_that_height() {
    let (_, on) = drawn("cylinder", "25,0,30;0,25,30;-25,0,30;0,-25,30", true, 8.0);
    let heights = on.curve.points_mm.iter().map(|p| p.z);
    let (low, high) = heights.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| (lo.min(z), hi.max(z)));
    assert!(low > 29.98 && high < 30.02, "the ring wanders from z = {low:.3} to {high:.3} mm");
    // Once round, as long as the circle (the base's facets make it a hair shorter).
    let length = on.curve.length_mm();
    let circle = std::f64::consts::TAU * 25.0;
    assert!((length - circle).abs() < 0.005 * circle, "ring {length:.2} mm against the circle's {circle:.2}");
}

#[test]
fn hollowed_models_with_creases_keep_the_whole_wall() {
    // The vase's lip and foot, and the cylinder's and cone's rims, are
    // creases: moved along smooth normals, vertices beside them came within
    // half a wall of the other side.
    let wall_mm = 2.0;
    for base in ["vase", "cylinder", "cone", "egg"] {
        let model = builtin_base(base).unwrap();
        let surface = SurfaceMesh::new(model.clone()).unwrap();
        let shell = tracery_core::surface::hollow(&surface, wall_mm).unwrap();
        assert!(shell.sanity_check().is_ok(), "{base}");
        assert_eq!(shell.shell_count(), 2, "{base}");
        let inner = &shell.vertices[model.vertices.len()..];
        // Every inner vertex near a crease, and a sample of the rest, by brute force.
        let near_crease =
            |p: &[f64; 3]| p[2] < 3.0 || p[2] > model.vertices.iter().map(|v| v[2]).fold(0.0, f64::max) - 3.0;
        let step = (inner.len() / 200).max(1);
        let checked: Vec<&[f64; 3]> =
            inner.iter().enumerate().filter(|(i, p)| near_crease(p) || i % step == 0).map(|(_, p)| p).collect();
        let thinnest =
            checked.iter().map(|p| distance::to_mesh(&model.vertices, &model.triangles, **p)).fold(f64::MAX, f64::min);
        assert!(thinnest > 0.95 * wall_mm, "{base}: an inner vertex is {thinnest:.3} mm from the outside");
        // The inner surface faces in: the shell holds a positive volume.
        assert!(shell.signed_volume() > 0.0, "{base}");
    }
}
