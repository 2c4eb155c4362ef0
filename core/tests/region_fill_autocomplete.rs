//! Autocomplete: predictions around strokes a person drew, checked on the
//! drawn and predicted paths together by measures the synthesis does not
//! optimize (where the drawn strokes stop, whether anything continues them;
//! crossings; coverage).

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::geom::{Rect, Region, clip_polylines};
use tracery_core::quality::{coverage, curve_statistics};
use tracery_core::region_fill::{CurveExemplar, CurvePath, Settings, predict};

const WINDOW_MM: f64 = 40.0;
const STRIP_MM: f64 = 12.0;

/// The exemplar's own paths in a strip across the bottom of the window:
/// what a person drew in its style.
fn drawn_strip(exemplar: &CurveExemplar) -> Vec<CurvePath> {
    let low = Rect::from_points(exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied())).unwrap().min;
    let moved: Vec<(Vec<DVec2>, bool)> =
        exemplar.paths.iter().map(|p| (p.points_mm.iter().map(|q| *q - low).collect(), p.closed)).collect();
    let strip = Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::new(WINDOW_MM, STRIP_MM)));
    clip_polylines(&moved, &strip)
        .into_iter()
        .map(|(points_mm, closed)| CurvePath { points_mm, closed })
        .filter(|p| p.length_mm() > 1.0)
        .collect()
}

fn as_pairs(paths: &[CurvePath]) -> Vec<(Vec<DVec2>, bool)> {
    paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect()
}

#[test]
fn predictions_continue_what_was_drawn_without_crossing_it() {
    let settings = Settings::default();
    let window = Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::splat(WINDOW_MM)));
    let above = Region::rectangle(&Rect::new(DVec2::new(0.0, STRIP_MM), DVec2::splat(WINDOW_MM)));
    for name in ["crackle", "meander", "vine", "scales"] {
        let exemplar = CurveExemplar::builtin(name).unwrap();
        let drawn = drawn_strip(&exemplar);
        let predicted = predict(&exemplar, &window, &drawn, &settings, &Control::default()).unwrap();
        assert!(!predicted.is_empty(), "{name}: nothing predicted");
        // Where the strip cut a drawn path off inside the window, the
        // pattern goes on: a predicted path starts there, or runs through
        // it (a junction, as crackle has).
        let cut_ends: Vec<DVec2> = drawn
            .iter()
            .filter(|p| !p.closed)
            .flat_map(|p| [p.points_mm[0], *p.points_mm.last().unwrap()])
            .filter(|e| (e.y - STRIP_MM).abs() < 1e-6 && e.x > 4.0 && e.x < WINDOW_MM - 4.0)
            .collect();
        let continued = cut_ends.iter().filter(|e| predicted.iter().any(|p| p.distance_to(**e) < 0.05)).count() as f64;
        if !cut_ends.is_empty() {
            let share = continued / cut_ends.len() as f64;
            assert!(share >= 0.6, "{name}: {continued} of {} cut strokes continued", cut_ends.len());
        }
        // Where the exemplar never crosses itself, neither may the drawing with its predictions.
        let all: Vec<CurvePath> = drawn.iter().chain(&predicted).cloned().collect();
        if curve_statistics(&as_pairs(&exemplar.paths)).crossings_per_100mm == 0.0 {
            assert_eq!(curve_statistics(&as_pairs(&all)).crossings_per_100mm, 0.0, "{name}: predictions cross");
        }
        // And the window above the strip is filled about as densely as the
        // exemplar is (a little less asked than of a whole fill's 0.8: a
        // strip 28 mm high is more edge than middle; the vine gives 0.79).
        let ex_bounds = Rect::from_points(exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied())).unwrap();
        let reach = settings.radius_mm();
        let ex_cover = coverage(&as_pairs(&exemplar.paths), &Region::rectangle(&ex_bounds), reach);
        let cover = coverage(&as_pairs(&all), &above, reach);
        assert!(cover >= 0.75 * ex_cover, "{name}: covers {cover:.2} above the strokes, the exemplar {ex_cover:.2}");
    }
}

#[test]
fn with_nothing_drawn_the_prediction_is_a_plain_fill() {
    let exemplar = CurveExemplar::builtin("waves").unwrap();
    let window = Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::splat(WINDOW_MM)));
    let settings = Settings::default();
    let alone = predict(&exemplar, &window, &[], &settings, &Control::default()).unwrap();
    // Strokes far away are no context: the same paths as with nothing drawn.
    let far = CurvePath { points_mm: vec![DVec2::new(500.0, 500.0), DVec2::new(540.0, 500.0)], closed: false };
    let with_far = predict(&exemplar, &window, &[far], &settings, &Control::default()).unwrap();
    assert_eq!(alone, with_far);
}
