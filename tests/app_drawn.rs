//! Loops drawn with the pointer, as a hand draws them (a fast hand's dozen
//! samples round a bracelet, a slow hand's wobbling every half millimetre),
//! give a band that runs round the drawn loop: each point of the band's
//! edges lies half a band from the stroke the document keeps, measured here
//! against that stroke, not against the curve the pipeline followed.

use egui::Pos2;
use tracery_core::curve::{DrawnStroke, Hand, StrokeShape};
use tracery_core::vector_brush::builtin;

#[path = "common/drive.rs"]
mod drive;
#[path = "common/ui.rs"]
mod ui;
use drive::{click_in_side_panel, drag, harness};
use ui::settle;

/// Draws `stroke` on the canvas at its size in mm and returns how far the
/// band's edges lie from the drawn loop: the nearest and the farthest, mm.
fn band_edges_from_the_drawn_loop(stroke: &DrawnStroke, exemplar: &str) -> (f64, f64, f64) {
    let mut harness = harness(vec![]);
    harness.step();
    if exemplar != "lace" {
        click_in_side_panel(&mut harness, exemplar);
    }
    let (view, rect) = harness.state().canvas_view().expect("the canvas was laid out");
    let mut points: Vec<Pos2> = stroke.samples_mm.iter().map(|&p| view.to_screen(rect, p)).collect();
    // The hand comes back to where it started, which closes the loop.
    points.push(points[0]);
    drag(&mut harness, &points);
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.doc.curves.len(), 1);
    let item = &app.doc.curves[0];
    assert!(item.closed, "{}: the stroke closes into a loop", stroke.name());
    let drawn = item.curve().expect("the stroke the document keeps");
    let output = app.output(item.id).unwrap_or_else(|| panic!("{}: no pattern", stroke.name()));
    assert_eq!(output.topology.components, 1, "{}", stroke.name());
    let edges = &output.overlays.band_edges_mm;
    assert!(!edges.is_empty(), "{}: no band edges", stroke.name());
    let distances: Vec<f64> = edges.iter().flatten().map(|&p| drawn.distance(p)).collect();
    let near = distances.iter().copied().fold(f64::INFINITY, f64::min);
    let far = distances.iter().copied().fold(0.0, f64::max);
    let half_band_mm = app.doc.curves[0].mode.band_mm() * 0.5;
    (near, far, half_band_mm)
}

#[test]
fn a_loop_drawn_by_hand_gets_a_band_round_the_loop() {
    assert!(builtin("chain").is_ok());
    // Bracelets and pendants as people draw them: an ellipse and a bean by
    // a fast hand, a circle by a slow one.
    let strokes = [
        DrawnStroke::new(StrokeShape::Ellipse { width_mm: 52.0, height_mm: 32.0 }, Hand::Fast, 11),
        DrawnStroke::new(StrokeShape::Bean { length_mm: 60.0 }, Hand::Fast, 4),
        DrawnStroke::new(StrokeShape::Circle { diameter_mm: 45.0 }, Hand::Slow, 2).reversed(),
    ];
    for (stroke, exemplar) in strokes.iter().zip(["lace", "chain", "chain"]) {
        let (near, far, half_band_mm) = band_edges_from_the_drawn_loop(stroke, exemplar);
        // Half a band either side of the drawn loop, give or take what
        // rounding the loop's tight turns moved it (the fast hand's
        // samples are corners, rounded on 1.25 half bands; the bean's
        // ends turn tighter than that, and the band narrows inside them).
        // A band running elsewhere crosses the drawn loop somewhere.
        let name = stroke.name();
        assert!(near > 0.25 * half_band_mm, "{name} with {exemplar}: an edge {near:.2} mm from the drawn loop");
        assert!(far < 1.6 * half_band_mm, "{name} with {exemplar}: an edge {far:.2} mm from the drawn loop");
    }
}
