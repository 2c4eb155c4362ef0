//! Loading exemplars from SVG: what is filled, and clear errors on bad input.

use proptest::prelude::*;
use tracery_core::DVec2;
use tracery_core::geom::count_topology;
use tracery_core::vector_brush::{BUILTIN_NAMES, Exemplar, ExemplarError, LoadOptions, builtin, builtin_svg};

fn load(svg: &str) -> Result<Exemplar, ExemplarError> {
    Exemplar::from_svg_str("test", svg, &LoadOptions::default())
}

fn wrap(body: &str) -> String {
    format!(r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">{body}</svg>"#)
}

#[test]
fn fill_rules_decide_holes() {
    let d = "M0,0 H40 V40 H0 Z M10,10 H30 V30 H10 Z";
    let evenodd = load(&wrap(&format!(r#"<path fill-rule="evenodd" d="{d}"/>"#))).unwrap();
    let nonzero = load(&wrap(&format!(r#"<path fill-rule="nonzero" d="{d}"/>"#))).unwrap();
    assert_eq!((evenodd.region.component_count(), evenodd.region.hole_count()), (1, 1));
    assert_eq!((nonzero.region.component_count(), nonzero.region.hole_count()), (1, 0));
    assert!((evenodd.region.area() - 1200.0).abs() < 1e-6);
    assert!((nonzero.region.area() - 1600.0).abs() < 1e-6);
    // A reversed inner square makes a hole under nonzero too.
    let reversed = load(&wrap(r#"<path d="M0,0 H40 V40 H0 Z M10,10 V30 H30 V10 Z"/>"#)).unwrap();
    assert_eq!(reversed.region.hole_count(), 1);
}

#[test]
fn transforms_and_groups_are_applied_and_v_points_up() {
    let svg = wrap(
        r#"<g transform="translate(10,0)"><g transform="scale(2,1)">
             <rect x="0" y="0" width="10" height="5"/></g></g>
           <rect x="60" y="20" width="10" height="10"/>"#,
    );
    let ex = load(&svg).unwrap();
    assert_eq!(ex.region.component_count(), 2);
    // The scaled rectangle spans u 10..30 in the SVG; the exemplar starts at u = 0.
    assert!((ex.width() - 60.0).abs() < 1e-6, "width {}", ex.width());
    assert!((ex.height() - 30.0).abs() < 1e-6);
    assert!((ex.region.area() - 200.0).abs() < 1e-6);
    // SVG y grows downwards; v grows upwards: the rectangle at the top of the
    // SVG (y 0..5) is at the top of the exemplar.
    let top = ex.region.polygons.iter().find(|p| (p.area() - 100.0).abs() < 1e-6).unwrap();
    let top_v = top.outer.iter().map(|p| p.y).fold(f64::MIN, f64::max);
    assert!((top_v - ex.bounds.max.y).abs() < 1e-6);
}

#[test]
fn strokes_become_outlines() {
    let ex = load(&wrap(r#"<circle cx="50" cy="50" r="20" fill="none" stroke="black" stroke-width="4"/>"#)).unwrap();
    assert_eq!((ex.region.component_count(), ex.region.hole_count()), (1, 1));
    let expected = std::f64::consts::PI * (22.0f64.powi(2) - 18.0f64.powi(2));
    assert!((ex.region.area() - expected).abs() / expected < 0.01, "area {}", ex.region.area());
    let line = load(&wrap(r#"<path d="M10,10 L90,10" stroke="black" stroke-width="2"/>"#)).unwrap();
    assert!((line.region.area() - 160.0).abs() < 1e-3);
}

#[test]
fn curves_are_flattened_within_tolerance() {
    let ex = load(&wrap(r#"<circle cx="50" cy="50" r="40"/>"#)).unwrap();
    let exact = std::f64::consts::PI * 1600.0;
    // The default tolerance is a thousandth of the drawing's height: the
    // polygon is inscribed, so its area is a little smaller, never larger.
    let error = (exact - ex.region.area()) / exact;
    assert!((0.0..0.005).contains(&error), "relative area error {error}");
    let mut options = LoadOptions::default();
    options.relative_tolerance = 1e-5;
    let fine = Exemplar::from_svg_str("fine", &wrap(r#"<circle cx="50" cy="50" r="40"/>"#), &options).unwrap();
    assert!(fine.region.vertex_count() > ex.region.vertex_count());
}

/// How far the chord from `a` to `b` strays inside a circle of `radius`
/// round `centre`: its midpoint's depth (the ends lie on the circle).
fn chord_error(a: DVec2, b: DVec2, centre: DVec2, radius: f64) -> f64 {
    radius - (0.5 * (a + b)).distance(centre)
}

#[test]
fn a_small_hole_in_a_wide_drawing_is_flattened_within_a_hundredth_of_a_millimetre() {
    // A 200 x 10 strip with a 3 mm hole: fitted to a 10 mm band, one unit
    // is a millimetre. A tolerance taken from the diagonal (0.2 mm) would
    // make the hole an octagon.
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 10">
        <path fill-rule="evenodd" d="M0,0 H200 V10 H0 Z M101.5,5 A1.5,1.5 0 1 0 98.5,5 A1.5,1.5 0 1 0 101.5,5 Z"/></svg>"#;
    let ex = load(svg).unwrap();
    let hole = &ex.region.polygons[0].holes[0];
    // The exemplar is moved to start at u = 0, centred on v = 0.
    let centre = DVec2::new(100.0, 0.0);
    // usvg draws an arc as cubic Béziers, true to a few micrometres.
    let off = hole.iter().map(|p| (p.distance(centre) - 1.5).abs()).fold(0.0, f64::max);
    assert!(off < 0.002, "a vertex lies {off} mm off the circle");
    let worst =
        (0..hole.len()).map(|k| chord_error(hole[k], hole[(k + 1) % hole.len()], centre, 1.5)).fold(0.0, f64::max);
    assert!(worst <= 0.01 + off, "a chord strays {worst} mm from the hole");
    assert!(hole.len() <= 40, "{} vertices for a 3 mm hole", hole.len());
}

#[test]
fn slivers_of_no_width_are_dropped_and_slender_features_kept() {
    // A strip with a needle out of its side 1e-4 wide at its base, and a
    // sliver part of its own: on a 10 mm band, a tenth of a micrometre.
    let needle = r#"<path d="M0,0 H40 V4 L60,4.00005 L40,4.0001 V10 H0 Z"/>"#;
    let sliver = r#"<path d="M50,8 L70,8.00005 L50,8.0001 Z"/>"#;
    let ex = load(&wrap(&format!("{needle}{sliver}"))).unwrap();
    assert_eq!(ex.region.component_count(), 1);
    assert!((ex.width() - 40.0).abs() < 1e-9, "width {}", ex.width());
    // A thin wedge 0.02 wide at its base (a fiftieth of a millimetre on a
    // 10 mm band) is the drawing's own.
    let wedge = load(&wrap(r#"<path d="M0,0 H40 V4 L60,4.01 L40,4.02 V10 H0 Z"/>"#)).unwrap();
    assert!((wedge.width() - 60.0).abs() < 1e-9, "width {}", wedge.width());
}

#[test]
fn overlapping_shapes_merge() {
    let ex = load(&wrap(r#"<rect x="0" y="0" width="20" height="20"/><rect x="10" y="10" width="20" height="20"/>"#))
        .unwrap();
    assert_eq!(ex.region.component_count(), 1);
    assert!((ex.region.area() - 700.0).abs() < 1e-6);
}

#[test]
fn clear_errors_on_bad_input() {
    assert!(matches!(load("hello"), Err(ExemplarError::NotSvg(_))));
    assert!(matches!(load(""), Err(ExemplarError::NotSvg(_))));
    assert!(matches!(load(&wrap("")), Err(ExemplarError::NothingFilled)));
    assert!(matches!(load(&wrap(r#"<path d="M0,0 L50,50" fill="none"/>"#)), Err(ExemplarError::NothingFilled)));
    assert!(matches!(load(&wrap(r#"<path d="M0,0 L50,50"/>"#)), Err(ExemplarError::ZeroArea)));
    assert!(matches!(load(&wrap(r#"<path d="M0,0 H10 V10 H0 Z M0,0 V10 H10 V0 Z"/>"#)), Err(ExemplarError::ZeroArea)));
    let huge =
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1e9 1e9"><rect width="1e9" height="1e9"/></svg>"#;
    assert!(matches!(load(huge), Err(ExemplarError::AbsurdSize { .. })));
    let tiny = wrap(r#"<rect width="0.0001" height="0.0001"/>"#);
    assert!(matches!(load(&tiny), Err(ExemplarError::AbsurdSize { .. })));
    let missing = Exemplar::from_svg_file(std::path::Path::new("/nonexistent/x.svg"), &LoadOptions::default());
    assert!(matches!(missing, Err(ExemplarError::Io { .. })));
    // Every message reads as a sentence for a person.
    for e in [load("hello").unwrap_err(), load(&wrap("")).unwrap_err(), load(huge).unwrap_err()] {
        assert!(e.to_string().len() > 20, "{e}");
    }
}

#[test]
fn builtins_load_with_the_topology_they_advertise() {
    for name in BUILTIN_NAMES {
        let ex = builtin(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        // Loaded geometry is clean: a second union changes nothing.
        let t = count_topology(&ex.region);
        assert_eq!((t.components, t.holes), (ex.region.component_count(), ex.region.hole_count()), "{name}");
        assert_eq!(ex.bounds.min.x, 0.0);
        assert!(ex.bounds.center().y.abs() < 1e-9);
    }
    let lace = builtin("lace").unwrap();
    assert_eq!(lace.region.component_count(), 1);
    assert!(lace.region.hole_count() >= 10);
    assert_eq!(builtin("chain").unwrap().region.component_count(), 6);
    assert!(builtin("islands").unwrap().region.component_count() > 1);
    assert!(builtin_svg("nope").is_none());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Arbitrary bytes never panic the loader.
    #[test]
    fn random_bytes_never_panic(data in proptest::collection::vec(any::<u8>(), 0..400)) {
        let _ = Exemplar::from_svg_data("fuzz", &data, &LoadOptions::default());
    }

    /// Random paths, with degenerate and extreme numbers, load or fail cleanly.
    #[test]
    fn random_paths_never_panic(
        coords in proptest::collection::vec(prop_oneof![
            -1e3f64..1e3, Just(0.0), Just(1e30), Just(-1e-30), Just(f64::MAX)], 2..40),
        commands in proptest::collection::vec(0u8..5, 1..20),
        evenodd in any::<bool>(),
        stroke in prop_oneof![Just(0.0f64), 0.01f64..10.0],
    ) {
        let mut d = String::new();
        let mut c = coords.iter().cycle();
        for cmd in commands {
            let mut n = || *c.next().unwrap();
            match cmd {
                0 => d += &format!("M{},{} ", n(), n()),
                1 => d += &format!("L{},{} ", n(), n()),
                2 => d += &format!("Q{},{} {},{} ", n(), n(), n(), n()),
                3 => d += &format!("C{},{} {},{} {},{} ", n(), n(), n(), n(), n(), n()),
                _ => d += "Z ",
            }
        }
        let rule = if evenodd { "evenodd" } else { "nonzero" };
        let svg = wrap(&format!(r#"<path fill-rule="{rule}" stroke="black" stroke-width="{stroke}" d="{d}"/>"#));
        if let Ok(ex) = load(&svg) {
            prop_assert!(ex.region.area() > 0.0);
            prop_assert!(ex.width().is_finite() && ex.height().is_finite());
        }
    }
}
