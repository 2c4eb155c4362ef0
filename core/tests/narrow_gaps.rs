//! Closing narrow gaps: where two outlines come closer than the width,
//! the gap between them fills, so that what touched stays joined by
//! material that survives a small erosion; what is farther apart is left
//! alone. Checked with `i_overlay`'s offsets, which the closing does not use.

use glam::DVec2;
use tracery_core::geom::{Polygon, Region, close_narrow_gaps, offset, union, without_slivers};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Polygon {
    let outer = vec![DVec2::new(x0, y0), DVec2::new(x1, y0), DVec2::new(x1, y1), DVec2::new(x0, y1)];
    Polygon { outer, holes: Vec::new() }
}

#[test]
fn a_curl_grazing_a_bar_is_joined_by_material_that_survives_an_erosion() {
    // A curl (a disc) laid on a bar, sunk into it by a millionth: one part
    // through a neck that any erosion pinches off.
    let bar = rect(-5.0, -1.0, 5.0, 0.0);
    let curl = Polygon {
        outer: (0..512)
            .map(|k| DVec2::new(0.0, 2.0 - 1e-6) + 2.0 * DVec2::from_angle(std::f64::consts::TAU * k as f64 / 512.0))
            .collect(),
        holes: Vec::new(),
    };
    let drawn = union(&[&Region::new(vec![bar, curl])]);
    assert_eq!(drawn.component_count(), 1);
    let radius = 0.05;
    assert_eq!(offset(&drawn, -0.2 * radius).component_count(), 2, "the drawing's neck is hairline");
    let closed = close_narrow_gaps(&drawn, radius);
    assert_eq!(closed.component_count(), 1);
    assert_eq!(offset(&closed, -0.2 * radius).component_count(), 1, "the joint survives an erosion");
    // Only near the joint: a sliver, not the wedges' whole length.
    let added = closed.area() - drawn.area();
    assert!(added > 0.0 && added < 0.05, "added {added}");
}

#[test]
fn parts_farther_apart_than_the_width_are_left_alone() {
    let apart = Region::new(vec![rect(0.0, 0.0, 1.0, 1.0), rect(1.5, 0.0, 2.5, 1.0)]);
    assert_eq!(close_narrow_gaps(&apart, 0.1), apart);
    // A gently curved outline: its points are near each other only along it.
    let disc = Region::new(vec![Polygon {
        outer: (0..256).map(|k| 3.0 * DVec2::from_angle(std::f64::consts::TAU * k as f64 / 256.0)).collect(),
        holes: Vec::new(),
    }]);
    assert_eq!(close_narrow_gaps(&disc, 0.1), disc);
}

#[test]
fn parts_a_hair_apart_are_joined_and_a_hairline_hole_fills() {
    let near = Region::new(vec![rect(0.0, 0.0, 1.0, 1.0), rect(1.001, 0.0, 2.0, 1.0)]);
    let joined = close_narrow_gaps(&near, 0.01);
    assert_eq!(joined.component_count(), 1);
    assert!((joined.area() - 2.0).abs() < 1e-6, "the gap is filled, nothing else: {}", joined.area());
    let mut square = rect(0.0, 0.0, 4.0, 4.0);
    let mut hairline = vec![DVec2::new(1.0, 2.0), DVec2::new(3.0, 2.0), DVec2::new(3.0, 2.004), DVec2::new(1.0, 2.004)];
    hairline.reverse();
    let mut wide = vec![DVec2::new(1.0, 0.5), DVec2::new(3.0, 0.5), DVec2::new(3.0, 1.5), DVec2::new(1.0, 1.5)];
    wide.reverse();
    square.holes = vec![hairline, wide];
    // What is left of the hairline are specks at its square ends, thinner than the
    // radius, which the pipeline removes at the same width.
    let closed = without_slivers(&close_narrow_gaps(&Region::new(vec![square]), 0.01), 0.01);
    assert_eq!(closed.hole_count(), 1, "the hairline hole fills, the wide one stays");
    assert!((closed.area() - 14.0).abs() < 1e-6, "area {}", closed.area());
}
