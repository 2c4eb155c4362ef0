//! Extrusion of regions whose parts lie apart, side by side with
//! overlapping bounds, and nested in each other's holes: one sound body per
//! part and exactly the region's volume, whichever parts are meshed
//! together.

use tracery_core::DVec2;
use tracery_core::geom::{Polygon, Region};
use tracery_core::mesh::extrude;

fn square(x: f64, y: f64, side: f64) -> Vec<DVec2> {
    vec![DVec2::new(x, y), DVec2::new(x + side, y), DVec2::new(x + side, y + side), DVec2::new(x, y + side)]
}

fn frame(x: f64, y: f64, side: f64, wall: f64) -> Polygon {
    let mut hole = square(x + wall, y + wall, side - 2.0 * wall);
    hole.reverse();
    Polygon { outer: square(x, y, side), holes: vec![hole] }
}

/// An L whose bounding box holds a square that does not touch it.
fn ell(x: f64, y: f64) -> Polygon {
    let outer = [(0.0, 0.0), (10.0, 0.0), (10.0, 2.0), (2.0, 2.0), (2.0, 10.0), (0.0, 10.0)];
    Polygon { outer: outer.iter().map(|&(a, b)| DVec2::new(x + a, y + b)).collect(), holes: vec![] }
}

#[test]
fn parts_apart_overlapping_in_bounds_and_nested_each_make_one_sound_body() {
    let region = Region::new(vec![
        // Apart from everything.
        Polygon { outer: square(100.0, 0.0, 5.0), holes: vec![] },
        // An L and a square within its bounds, not touching it.
        ell(0.0, 0.0),
        Polygon { outer: square(5.0, 5.0, 3.0), holes: vec![] },
        // A frame with an island in its opening.
        frame(40.0, 0.0, 20.0, 2.0),
        Polygon { outer: square(45.0, 5.0, 10.0), holes: vec![] },
        // Two Ls hooked into each other's bounds, not touching.
        ell(70.0, 0.0),
        Polygon { outer: ell(0.0, 0.0).outer.iter().map(|p| DVec2::new(83.0, 10.0) - *p).collect(), holes: vec![] },
    ]);
    assert_eq!(region.component_count(), 7);
    assert_eq!(tracery_core::geom::count_topology(&region).components, 7, "the parts do not touch");
    let thickness_mm = 1.5;
    let mesh = extrude(&region, thickness_mm).unwrap();
    mesh.sanity_check().unwrap();
    assert_eq!(mesh.shell_count(), 7);
    let expected = region.area() * thickness_mm;
    assert!((mesh.signed_volume() - expected).abs() < 1e-9 * expected, "{} against {expected}", mesh.signed_volume());
}

#[test]
fn rings_that_cross_in_one_group_are_still_refused_or_repaired() {
    // Two squares overlapping (not a clean region): meshed as given they
    // would cross; the repair merges them into one body.
    let region = Region::new(vec![
        Polygon { outer: square(0.0, 0.0, 4.0), holes: vec![] },
        Polygon { outer: square(2.0, 2.0, 4.0), holes: vec![] },
        Polygon { outer: square(20.0, 0.0, 4.0), holes: vec![] },
    ]);
    let mesh = extrude(&region, 1.0).unwrap();
    mesh.sanity_check().unwrap();
    assert_eq!(mesh.shell_count(), 2);
    assert!((mesh.signed_volume() - (16.0 + 16.0 - 4.0 + 16.0)).abs() < 1e-6);
}

fn circle(centre: DVec2, radius: f64, n: usize, clockwise: bool) -> Vec<DVec2> {
    star(centre, &vec![radius; n], 0.0, clockwise)
}

#[test]
fn a_large_pattern_along_a_loop_is_one_sound_body_of_its_own_volume() {
    // Like a pattern along a loop: one outline whose bounds hold everything,
    // tens of thousands of vertices, holes everywhere (some with islands),
    // and a wavy rim that crosses any vertical line many times.
    let wavy = |radius: f64, n: usize, clockwise: bool| {
        let mut ring: Vec<DVec2> = (0..n)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / n as f64;
                (radius + 1.5 * (60.0 * t).sin()) * DVec2::new(t.cos(), t.sin())
            })
            .collect();
        if clockwise {
            ring.reverse();
        }
        ring
    };
    let mut holes = vec![wavy(30.0, 12_000, true)];
    let mut islands = Vec::new();
    for k in 0..240 {
        let t = std::f64::consts::TAU * k as f64 / 240.0;
        let centre = 37.0 * DVec2::new(t.cos(), t.sin());
        holes.push(circle(centre, 0.3, 48, true));
        if k % 3 == 0 {
            islands.push(Polygon { outer: circle(centre, 0.1, 24, false), holes: vec![] });
        }
    }
    let mut polygons = vec![Polygon { outer: wavy(44.0, 12_000, false), holes }];
    polygons.extend(islands);
    let region = Region::new(polygons);
    let vertices: usize = region.rings().map(|r| r.len()).sum();
    assert!(vertices > 30_000);
    let thickness_mm = 2.0;
    let mesh = extrude(&region, thickness_mm).unwrap();
    mesh.sanity_check().unwrap();
    assert_eq!(mesh.shell_count(), 1 + 80);
    let expected = region.area() * thickness_mm;
    assert!((mesh.signed_volume() - expected).abs() < 1e-6 * expected, "{} against {expected}", mesh.signed_volume());
}

/// A star-shaped ring round `centre`: `radii` at even angles from `turn`
/// (radians), counter-clockwise unless `clockwise`.
fn star(centre: DVec2, radii: &[f64], turn: f64, clockwise: bool) -> Vec<DVec2> {
    let n = radii.len();
    let mut ring: Vec<DVec2> = (0..n)
        .map(|k| {
            let t = turn + std::f64::consts::TAU * k as f64 / n as f64;
            centre + radii[k] * DVec2::new(t.cos(), t.sin())
        })
        .collect();
    if clockwise {
        ring.reverse();
    }
    ring
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 64, ..Default::default() })]

    /// Outlines as a person's drawing or a union can leave them: parts
    /// apart, touching, nested in holes or overlapping. Whichever way the
    /// faces are made (the sweep where the rings are simple, the
    /// constrained triangulation and its repair otherwise), the solid is
    /// sound, with the volume of the outlines' union, counted apart by
    /// `i_overlay`.
    #[test]
    fn any_outline_extrudes_to_a_sound_solid_of_its_own_volume(
        parts in proptest::collection::vec(
            (-8.0f64..8.0, -8.0f64..8.0, proptest::collection::vec(1.0f64..4.0, 3..12), 0.0f64..6.3, proptest::option::of(0.2f64..0.6)),
            1..7,
        ),
    ) {
        let polygons: Vec<Polygon> = parts
            .iter()
            .map(|(x, y, radii, turn, hole)| {
                let centre = DVec2::new(*x, *y);
                // A regular hole well inside the star's smallest radius.
                let smallest = radii.iter().copied().fold(f64::INFINITY, f64::min);
                let holes = hole.map(|h| star(centre, &vec![h * smallest; radii.len()], *turn, true));
                Polygon { outer: star(centre, radii, *turn, false), holes: holes.into_iter().collect() }
            })
            .collect();
        let region = Region::new(polygons);
        let union = tracery_core::geom::union(&[&region]);
        let thickness_mm = 1.0;
        let mesh = extrude(&region, thickness_mm).expect("the outline or its repair meshes");
        proptest::prop_assert!(mesh.sanity_check().is_ok(), "{:?}", mesh.sanity_check());
        let expected = union.area() * thickness_mm;
        proptest::prop_assert!(
            (mesh.signed_volume() - expected).abs() < 1e-5 * expected,
            "{} against {expected}", mesh.signed_volume()
        );
    }
}
