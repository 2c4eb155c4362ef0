//! Meshing where outlines touch at a single point: the configurations that
//! real ornaments produce (a hole whose tip touches the outline, two strokes
//! that meet tip to tip at a shallow angle, a loop closing onto itself), each
//! checked for a watertight, manifold mesh with the right number of bodies.

use glam::DVec2;
use tracery_core::geom::{Polygon, Region, closest_on_segment, count_topology, without_slivers};
use tracery_core::mesh::extrude;

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

fn check(region: &Region, bodies: usize) {
    let mesh = extrude(region, 1.0).expect("meshes");
    mesh.sanity_check().expect("watertight and manifold");
    assert_eq!(mesh.shell_count(), bodies);
}

#[test]
fn a_hole_whose_tip_touches_the_outline_meshes_as_one_body() {
    // The hole's apex is a vertex of the outer ring's straight bottom edge.
    let outer = vec![v(0.0, 0.0), v(5.0, 0.0), v(10.0, 0.0), v(10.0, 10.0), v(0.0, 10.0)];
    let hole = vec![v(5.0, 0.0), v(4.0, 5.0), v(6.0, 5.0)];
    let region = Region::new(vec![Polygon { outer, holes: vec![hole] }]);
    check(&region, 1);
}

#[test]
fn strokes_meeting_tip_to_tip_at_a_shallow_angle_stay_two_bodies() {
    // Two thin spikes whose tips meet at the origin, nearly collinear: moving
    // both tips along their own bisectors used to cross the other spike.
    let right = vec![v(0.0, 0.0), v(3.0, 0.01), v(3.0, 0.2)];
    let left = vec![v(0.0, 0.0), v(-3.0, -0.01), v(-3.0, 0.15)];
    let mut left = left;
    left.reverse();
    let region = Region::new(vec![Polygon { outer: right, holes: vec![] }, Polygon { outer: left, holes: vec![] }]);
    assert!(tracery_core::geom::signed_area(&region.polygons[1].outer) > 0.0);
    check(&region, 2);
}

#[test]
fn a_part_inside_a_hole_touching_its_edge_meshes() {
    // A frame with a square hole and, in the hole, a diamond touching the
    // hole's bottom edge at one point: the hole's copy is a straight run,
    // the diamond's a convex corner.
    let outer = vec![v(0.0, 0.0), v(10.0, 0.0), v(10.0, 10.0), v(0.0, 10.0)];
    let hole = vec![v(2.0, 2.0), v(2.0, 8.0), v(8.0, 8.0), v(8.0, 2.0), v(5.0, 2.0)];
    let diamond = vec![v(5.0, 2.0), v(6.0, 4.0), v(5.0, 6.0), v(4.0, 4.0)];
    let region = Region::new(vec![Polygon { outer, holes: vec![hole] }, Polygon { outer: diamond, holes: vec![] }]);
    check(&region, 2);
}

#[test]
fn hairline_slivers_are_not_holes() {
    // A frame with a real hole and a sliver 2 µm wide: only the real hole counts.
    let outer = vec![v(0.0, 0.0), v(10.0, 0.0), v(10.0, 10.0), v(0.0, 10.0)];
    let real = vec![v(2.0, 2.0), v(2.0, 4.0), v(4.0, 4.0), v(4.0, 2.0)];
    let sliver = vec![v(2.0, 6.0), v(2.0, 6.002), v(8.0, 6.002), v(8.0, 6.0)];
    let region = Region::new(vec![Polygon { outer, holes: vec![real, sliver] }]);
    assert_eq!(count_topology(&region).holes, 2);
    let cleaned = without_slivers(&region, 0.01);
    assert_eq!(count_topology(&cleaned).holes, 1);
    check(&cleaned, 1);
}

#[test]
fn holes_meeting_tip_to_tip_mesh_as_one_body() {
    // Two thin holes whose tips meet at one point at a shallow angle, as
    // where two loops of a rosette graze each other: the material wraps
    // around both tips, so neither corner is convex.
    let outer = vec![v(-5.0, -5.0), v(5.0, -5.0), v(5.0, 5.0), v(-5.0, 5.0)];
    let right = vec![v(0.0, 0.0), v(3.0, 1.3), v(3.0, 0.02)];
    let left = vec![v(0.0, 0.0), v(-3.0, -1.0), v(-3.0, -0.02)];
    for hole in [&right, &left] {
        assert!(tracery_core::geom::signed_area(hole) < 0.0, "holes run clockwise");
    }
    let region = Region::new(vec![Polygon { outer, holes: vec![right, left] }]);
    check(&region, 1);
}

#[test]
fn a_vertex_on_another_rings_edge_meshes() {
    // A triangle whose tip lies exactly on the middle of the square's top
    // edge, which has no vertex there: the triangulation cannot keep that edge
    // whole, so the tip is inserted into it and the parts separate there.
    let square = vec![v(0.0, 0.0), v(4.0, 0.0), v(4.0, 4.0), v(0.0, 4.0)];
    let tip = vec![v(2.0, 4.0), v(3.0, 6.0), v(1.0, 6.0)];
    let region = Region::new(vec![Polygon { outer: square, holes: vec![] }, Polygon { outer: tip, holes: vec![] }]);
    check(&region, 2);
}

/// The smallest distance between two closed rings' vertices and edges.
fn gap(r: &[DVec2], s: &[DVec2]) -> f64 {
    let one_way = |r: &[DVec2], s: &[DVec2]| {
        r.iter()
            .flat_map(|&p| (0..s.len()).map(move |j| (p, j)))
            .map(|(p, j)| closest_on_segment(p, s[j], s[(j + 1) % s.len()]).1.distance(p))
            .fold(f64::INFINITY, f64::min)
    };
    one_way(r, s).min(one_way(s, r))
}

#[test]
fn a_tip_touching_the_middle_of_another_parts_edge_is_moved_off_it() {
    // A spike whose tip lies on the middle of a bar's top edge, not on one
    // of its vertices. Parts that only touch are apart in the plan, and
    // mapped onto a curve, rounding may push the tip across the edge: the
    // tip must come a step away from the bar, which stays whole.
    let bar = vec![v(0.0, 0.0), v(10.0, 0.0), v(10.0, 1.0), v(0.0, 1.0)];
    let spike = vec![v(4.0, 1.0), v(5.0, 4.0), v(3.0, 4.0)];
    assert_eq!(gap(&bar, &spike), 0.0);
    let region = Region::new(vec![Polygon { outer: bar, holes: vec![] }, Polygon { outer: spike, holes: vec![] }]);
    let step = 1e-3;
    let separated = tracery_core::geom::separate_contacts(&region, step);
    let (bar, spike) = (&separated.polygons[0].outer, &separated.polygons[1].outer);
    assert!(gap(bar, spike) > 0.5 * step, "{}", gap(bar, spike));
    assert!((separated.area() - region.area()).abs() < 10.0 * step, "only a hair moved");
    assert_eq!(count_topology(&separated).components, 2);
    check(&separated, 2);
}

#[test]
fn a_needle_thinner_than_f32_on_an_outline_meshes_as_one_body() {
    // The shape of a tip on a stitched and mapped corpus pattern
    // (vectorian159 along a wave): the outline runs 0.05 mm out to a tip
    // and back with its two sides 2e-7 mm apart. Rounded to `f32`, the way
    // back crossed the way out and the tip meshed as a body of its own.
    let outer = vec![
        v(58.4, 12.4),
        v(64.222763487, 12.4),
        v(64.222763487, 12.539346024),
        v(64.228464581, 12.492905011),
        v(64.200664302, 12.719373910),
        v(64.18, 16.8),
        v(58.4, 16.8),
    ];
    let region = Region::new(vec![Polygon { outer, holes: vec![] }]);
    assert_eq!(count_topology(&region).components, 1);
    check(&region, 1);
}
