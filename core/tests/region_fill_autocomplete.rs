//! Autocomplete: predictions around strokes a person drew, checked on the
//! drawn and predicted paths together by measures the synthesis does not
//! optimize (where the drawn strokes stop, whether anything continues them;
//! crossings; coverage).

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::geom::{Polygon, Rect, Region, clip_polylines};
use tracery_core::quality::{coverage, curve_statistics, element_statistics};
use tracery_core::region_fill::{CurveExemplar, CurvePath, Drawn, Settings, make_product_around, predict};

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
    for name in ["crackle", "meander", "vine", "scales", "waves", "spirals"] {
        let exemplar = CurveExemplar::builtin(name).unwrap();
        let drawn = drawn_strip(&exemplar);
        let predicted =
            predict(&exemplar, &window, &Drawn::paths(drawn.clone()), &settings, &Control::default()).unwrap().paths;
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
    let alone = predict(&exemplar, &window, &Drawn::default(), &settings, &Control::default()).unwrap();
    // Strokes far away are no context: the same paths as with nothing drawn.
    let far = CurvePath { points_mm: vec![DVec2::new(500.0, 500.0), DVec2::new(540.0, 500.0)], closed: false };
    let with_far = predict(&exemplar, &window, &Drawn::paths(vec![far]), &settings, &Control::default()).unwrap();
    assert_eq!(alone, with_far);
}

/// The berries' stalks and berries in the strip, as a person would have
/// drawn and accepted them: what lies wholly in the strip.
fn drawn_berries(exemplar: &CurveExemplar, settings: &Settings) -> (Drawn, Vec<Polygon>) {
    let learned = exemplar.curves(settings.delta_mm);
    let low = Rect::from_points(learned.paths.iter().flat_map(|p| p.points_mm.iter().copied())).unwrap().min;
    let strip = Rect::new(DVec2::ZERO, DVec2::new(WINDOW_MM, STRIP_MM));
    let inside = |p: DVec2| p.cmpge(strip.min).all() && p.cmple(strip.max).all();
    let shapes: Vec<Polygon> = learned
        .elements
        .polygons()
        .into_iter()
        .map(|s| s.map_points(|p| p - low))
        .filter(|s| s.outer.iter().all(|p| inside(*p)))
        .collect();
    // The stalks as learned: the exemplar's paths hold the berries' outlines too.
    let paths = drawn_strip(&CurveExemplar::from_paths("stalks", learned.paths.clone()));
    (Drawn { paths, shapes }, learned.elements.polygons())
}

/// The centre of a shape (the mean of its outer points), as
/// `element_statistics` takes it.
fn centre(shape: &Polygon) -> DVec2 {
    shape.outer.iter().copied().sum::<DVec2>() / shape.outer.len() as f64
}

#[test]
fn berries_drawn_stay_and_predicted_berries_go_on_beside_them() {
    let settings = Settings::default();
    let exemplar = CurveExemplar::builtin("berries").unwrap();
    let (drawn, ex_shapes) = drawn_berries(&exemplar, &settings);
    assert!(drawn.shapes.len() >= 3, "{} berries in the strip", drawn.shapes.len());
    let whole_window = Rect::new(DVec2::ZERO, DVec2::splat(WINDOW_MM));
    let window = Region::rectangle(&whole_window);
    let predicted = predict(&exemplar, &window, &drawn, &settings, &Control::default()).unwrap();
    assert!(!predicted.elements.is_empty(), "no berries suggested");
    // Whole: each an exemplar's shape, by area.
    let areas: Vec<f64> = ex_shapes.iter().map(Polygon::area).collect();
    assert!(predicted.elements.iter().all(|e| areas.iter().any(|a| (a - e.area()).abs() < 1e-9)));
    // Drawn and suggested together, away from the window's edge (where a
    // berry the edge would cut is left out), are dense enough. Suggestions
    // are sparser than the exemplar: 0.65 to 0.8 of it over seeds 1 to 4
    // (`docs/region-fill.md`).
    let learned = exemplar.curves(settings.delta_mm);
    let ex_points = learned.paths.iter().flat_map(|p| p.points_mm.iter().copied());
    let ex_bounds = Rect::from_points(ex_points.chain(ex_shapes.iter().flat_map(|s| s.outer.iter().copied()))).unwrap();
    let ex = element_statistics(&ex_shapes, &[], &ex_bounds, 0.0);
    let all: Vec<Polygon> = drawn.shapes.iter().chain(&predicted.elements).cloned().collect();
    let out = element_statistics(&all, &[], &whole_window, settings.radius_mm());
    assert!(out.per_100mm2 >= 0.6 * ex.per_100mm2, "{out:?} against {ex:?}");
    // Nothing suggested lies on a drawn berry, or nearer one than the
    // exemplar's two closest berries are to each other.
    let all = element_statistics(&all, &[], &whole_window, 0.0);
    assert_eq!(all.overlapping_pairs, 0, "a suggested berry lies on a drawn one");
    let centres: Vec<DVec2> = ex_shapes.iter().map(centre).collect();
    let closest = (0..centres.len())
        .flat_map(|a| (a + 1..centres.len()).map(move |b| (a, b)))
        .map(|(a, b)| centres[a].distance(centres[b]))
        .fold(f64::MAX, f64::min);
    for e in &predicted.elements {
        let gap = drawn.shapes.iter().map(|d| centre(d).distance(centre(e))).fold(f64::MAX, f64::min);
        assert!(
            gap >= 0.8 * closest,
            "a suggested berry {gap:.1} mm from a drawn one; the exemplar's closest {closest:.1}"
        );
    }
    // The stalks suggested cross neither each other nor what was drawn,
    // as the exemplar's never do.
    assert_eq!(curve_statistics(&as_pairs(&learned.paths)).crossings_per_100mm, 0.0);
    let paths: Vec<CurvePath> = drawn.paths.iter().chain(&predicted.paths).cloned().collect();
    assert_eq!(curve_statistics(&as_pairs(&paths)).crossings_per_100mm, 0.0, "suggested stalks cross");
    // The fill around them prints them too: each drawn berry's centre is in the solid.
    let product = make_product_around(&exemplar, &window, &drawn, &settings, &Control::default()).unwrap();
    for shape in &drawn.shapes {
        let c = centre(shape);
        assert!(product.region_mm.contains(c), "the drawn berry at {c} is not printed");
    }
}

/// The longest stretch of `path` lying within `near_mm` of one of the
/// `drawn` strokes, sampled every 0.05 mm.
fn longest_stretch_along(path: &CurvePath, drawn: &[CurvePath], near_mm: f64) -> f64 {
    let (mut longest, mut run) = (0.0f64, 0.0f64);
    let mut previous: Option<DVec2> = None;
    let ends = path.points_mm.iter().skip(1).chain(path.closed.then(|| &path.points_mm[0]));
    for (&a, &b) in path.points_mm.iter().zip(ends) {
        let steps = (a.distance(b) / 0.05).ceil().max(1.0) as usize;
        for j in 0..=steps {
            let p = a.lerp(b, j as f64 / steps as f64);
            let on = drawn.iter().any(|d| d.distance_to(p) <= near_mm);
            let step = previous.map_or(0.0, |q| q.distance(p));
            run = if on { run + step } else { 0.0 };
            longest = longest.max(run);
            previous = Some(p);
        }
    }
    longest
}

#[test]
fn no_prediction_runs_along_a_drawn_stroke() {
    // A hand-drawn wavy stem across the middle of the window, as a person
    // starts a vine or a berry branch, and the exemplar's own strip.
    let stem = CurvePath {
        points_mm: (0..=60).map(|i| DVec2::new(3.0 + 0.55 * i as f64, 22.0 + 2.5 * (0.35 * i as f64).sin())).collect(),
        closed: false,
    };
    let window = Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::splat(WINDOW_MM)));
    let mut worst = (0.0, String::new());
    for name in ["berries", "vine", "waves", "crackle", "meander", "scales", "spirals"] {
        let exemplar = CurveExemplar::builtin(name).unwrap();
        for (what, drawn) in [("stem", vec![stem.clone()]), ("strip", drawn_strip(&exemplar))] {
            for seed in 1..=2 {
                let mut settings = Settings::default();
                settings.seed = seed;
                let predicted =
                    predict(&exemplar, &window, &Drawn::paths(drawn.clone()), &settings, &Control::default()).unwrap();
                for path in &predicted.paths {
                    let along = longest_stretch_along(path, &drawn, 0.3);
                    if along > worst.0 {
                        worst = (along, format!("{name}, {what}, seed {seed}"));
                    }
                }
            }
        }
    }
    // A path meeting a stroke at a slant lies near it for a short way; one
    // doubling it lies on it for millimetres.
    assert!(worst.0 <= 1.5, "a predicted path runs {:.1} mm along a drawn stroke ({})", worst.0, worst.1);
    eprintln!("longest stretch along a drawn stroke: {:.2} mm ({})", worst.0, worst.1);
}
