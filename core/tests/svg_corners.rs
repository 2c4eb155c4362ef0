//! Corners of curves read from SVG files: a square picture frame, an L, a
//! star, a rectangle with small rounded corners and a heart, drawn as paths
//! in a file sized in millimetres, as a person exports them from an
//! illustration tool (and the built-in heart). Such a path is sampled every
//! half millimetre, and its corners must be rounded as those of the
//! built-in frames are: the band turns them without being narrowed, and
//! every built-in exemplar comes out as planned, counted on the final
//! geometry. And a corner drawn by hand, wherever its stroke's control
//! points fall, turns on the whole radius.

use glam::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::{Along, Curve, planar_topology};
use tracery_core::quality::{max_distance_from, tightest_turn};
use tracery_core::report::Warning;
use tracery_core::vector_brush::{BUILTIN_NAMES, Settings, Synthesis, builtin, synthesize};

fn curve_from(svg: &str, name: &str) -> Curve {
    let path = std::env::temp_dir().join(format!("tracery-svg-corner-{}-{name}.svg", std::process::id()));
    std::fs::write(&path, svg).unwrap();
    let curve = Along::curve_from_svg(&path).unwrap();
    let _ = std::fs::remove_file(&path);
    curve
}

fn file(d: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><path d="{d}" fill="none" stroke="black"/></svg>"#
    )
}

/// The tightest turn of the curve, mm (`quality::tightest_turn`).
fn tightest_radius_mm(curve: &Curve, step_mm: f64) -> f64 {
    tightest_turn(curve.points(), curve.is_closed(), step_mm)
}

/// One part, as planned (counted on the final geometry), and in the band.
fn assert_one_part_as_planned_in_the_band(s: &Synthesis, half_band_mm: f64, context: &str) {
    let topology = planar_topology(&s.planar.region, &s.curve);
    let counted = (topology.components as u32, topology.holes as u32);
    assert_eq!(counted, (s.solution.components, s.solution.holes), "{context}: counted against planned");
    assert_eq!(counted.0, 1, "{context}: one part asked");
    let drift_mm = max_distance_from(&s.planar.region, &s.curve);
    assert!(drift_mm <= half_band_mm * 1.05, "{context}: {drift_mm:.2} mm off the curve");
}

#[test]
fn frames_stars_and_hearts_drawn_in_svg_turn_their_corners_as_planned() {
    let frame = curve_from(&file("M10 10 H90 V90 H10 Z"), "frame");
    let ell = curve_from(&file("M10 10 L10 90 L90 90"), "ell");
    // A five-pointed star, its tips turning 136° and its inner corners 64°.
    let star_points: Vec<String> = (0..10)
        .map(|i| {
            let a = -std::f64::consts::FRAC_PI_2 + i as f64 * std::f64::consts::PI / 5.0;
            let r = if i % 2 == 0 { 45.0 } else { 20.0 };
            format!("{:.3},{:.3}", 50.0 + r * a.cos(), 50.0 + r * a.sin())
        })
        .collect();
    let star = curve_from(&file(&format!("M{} Z", star_points.join(" L"))), "star");
    // A rectangle whose corners are drawn as arcs of 2 mm, tighter than the band.
    let rounded = curve_from(
        &file("M20,10 H80 A2,2 0 0 1 82,12 V88 A2,2 0 0 1 80,90 H20 A2,2 0 0 1 18,88 V12 A2,2 0 0 1 20,10 Z"),
        "rounded",
    );
    // A heart of two Bézier lobes: its point and its cusp lie between
    // curved stretches, with no straight run beside them.
    let heart = curve_from(
        &file("M50,95 C15,70 2,48 15,28 C28,10 46,18 50,32 C54,18 72,10 85,28 C98,48 85,70 50,95 Z"),
        "heart",
    );
    assert!(frame.is_closed() && !ell.is_closed() && star.is_closed() && rounded.is_closed() && heart.is_closed());
    // The drawn corners are kept where they are, not cut by the sampling.
    assert!((frame.length() - 320.0).abs() < 1e-3, "{}", frame.length());
    let built_in_heart = Curve::heart(90.0).unwrap();
    let shapes = [
        ("frame", &frame),
        ("L", &ell),
        ("star", &star),
        ("rounded rectangle", &rounded),
        ("heart", &heart),
        ("built-in heart", &built_in_heart),
    ];
    for (name, curve) in shapes {
        for exemplar_name in BUILTIN_NAMES {
            let exemplar = builtin(exemplar_name).unwrap();
            let settings = Settings::default();
            let context = format!("{exemplar_name} along the SVG {name}");
            let s = synthesize(&exemplar, curve, &settings, &Control::default()).expect(&context);
            // The curve the pattern follows turns no tighter than the band's
            // half-height: the corners were rounded, not left to fold.
            let half_band_mm = 0.5 * settings.band_mm;
            let tightest = tightest_radius_mm(&s.curve, 0.5);
            assert!(tightest > half_band_mm, "{context}: turns on a radius of {tightest:.2} mm");
            let narrowed = s.warnings.iter().any(|w| matches!(w, Warning::BandNarrowed { .. }));
            let overlapped = s.warnings.iter().any(|w| matches!(w, Warning::BandOverlapsItself { .. }));
            assert!(!narrowed && !overlapped, "{context}: {:?}", s.warnings);
            // As planned, and as asked, counted on the final geometry; in
            // the band round the rounded corners, and that curve near the
            // drawn one: an arc of 1.25 half bands keeps within its radius
            // of the corner it replaces (0.41 of it at a right angle, 0.63
            // at the star's tips).
            assert_one_part_as_planned_in_the_band(&s, half_band_mm, &context);
            let rounding_mm = s.curve.points().iter().map(|&p| curve.distance(p)).fold(0.0, f64::max);
            assert!(rounding_mm < 1.25 * half_band_mm, "{context}: the corners moved {rounding_mm:.2} mm");
        }
    }
}

#[test]
fn a_drawn_corner_is_rounded_on_the_whole_radius_wherever_its_points_fall() {
    // A stroke's control points lie every 6 mm and seldom on its corner,
    // which smoothing then spreads over several vertices: a V of two
    // 70 mm legs at every turn up to 165°, its control points shifted
    // past the corner by a quarter millimetre at a time.
    let radius_mm = 6.25;
    for turn_deg in [20.0f64, 45.0, 90.0, 120.0, 135.0, 150.0, 165.0] {
        let d_out = DVec2::from_angle(turn_deg.to_radians());
        for k in 0..24 {
            let past_mm = k as f64 * 0.25;
            let points: Vec<DVec2> = (0..24)
                .map(|i| -70.0 + past_mm + 6.0 * i as f64)
                .filter(|&s| s < 70.0)
                .map(|s| if s < 0.0 { DVec2::new(s, 0.0) } else { d_out * s })
                .collect();
            let drawn = Curve::from_stroke(&points, false, 0.5).unwrap();
            // Smoothing alone leaves all but the gentlest turns sharp (on
            // a millimetre or two: it takes out the hand's tremor).
            let drawn_tightest = tightest_radius_mm(&drawn, 0.5);
            assert!(
                turn_deg < 45.0 || drawn_tightest < 0.6 * radius_mm,
                "{turn_deg}° {past_mm} mm: {drawn_tightest:.2} mm"
            );
            let tightest = tightest_radius_mm(&drawn.with_rounded_corners(radius_mm), 0.5);
            // Three points half a millimetre apart on an arc of 3° steps
            // read its radius a little short.
            assert!(tightest > 0.9 * radius_mm, "{turn_deg}° {past_mm} mm: turns on {tightest:.2} mm");
        }
    }
}

#[test]
fn a_larger_corner_radius_squeezes_the_pattern_less_inside_each_corner() {
    // The inside of a corner turned on a radius `r` by a band of half
    // height `h` runs on `r − h`: 1.25 mm on the least radius of a 10 mm
    // band, where the pattern is squeezed fivefold. A person who asks for
    // 15 mm gets 10 mm there.
    let frame = curve_from(&file("M10 10 H90 V90 H10 Z"), "frame-radius");
    for exemplar_name in ["lace", "chain", "meander"] {
        let exemplar = builtin(exemplar_name).unwrap();
        let mut settings = Settings::default();
        let half_band_mm = 0.5 * settings.band_mm;
        for asked_mm in [0.0, 15.0] {
            settings.corner_radius_mm = asked_mm;
            let context = format!("{exemplar_name} round the frame, corner radius {asked_mm} mm");
            let s = synthesize(&exemplar, &frame, &settings, &Control::default()).expect(&context);
            let used_mm = settings.corner_radius_used_mm();
            assert_eq!(used_mm, if asked_mm == 0.0 { 1.25 * half_band_mm } else { asked_mm });
            // Measured on the curve the pattern follows, three points 2 mm
            // apart (the arcs are drawn in steps of 3°, 0.8 mm long on
            // 15 mm, which points closer together read as sharper turns):
            // every corner turns on the radius used.
            let tightest = tightest_radius_mm(&s.curve, 2.0);
            assert!(tightest > 0.9 * used_mm && tightest < 1.1 * used_mm, "{context}: {tightest:.2} mm");
            // An arc of radius `r` at a right angle keeps within
            // `(√2 − 1)·r` of the corner it replaces.
            let rounding_mm = s.curve.points().iter().map(|&p| frame.distance(p)).fold(0.0, f64::max);
            assert!(rounding_mm < 0.42 * used_mm + 0.05, "{context}: the corners moved {rounding_mm:.2} mm");
            assert_one_part_as_planned_in_the_band(&s, half_band_mm, &context);
        }
    }
}
