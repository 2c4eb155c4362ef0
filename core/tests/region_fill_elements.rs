//! Discrete elements in region fill: small filled shapes learned whole,
//! checked on the product's shapes and paths by `quality::element_statistics`
//! (which knows nothing of the synthesis) against the exemplar measured
//! the same way.

use glam::DVec2;
use tracery_core::control::Control;
use tracery_core::geom::{Polygon, Rect};
use tracery_core::quality::element_statistics;
use tracery_core::region_fill::{CurveExemplar, Settings, make_product, parse_region};

/// Polylines of a product's or exemplar's paths, for the measures.
fn polylines(points: impl Iterator<Item = (Vec<DVec2>, bool)>) -> Vec<(Vec<DVec2>, bool)> {
    points.collect()
}

#[test]
fn small_filled_shapes_are_elements_and_bands_and_strokes_stay_curves() {
    // Three dots of one size, one larger dot, a filled band 40 mm long and
    // a stroked wave: at 1.5 mm spacing, the dots are two kinds of element.
    let dot = |x: f64, r: f64| format!("<circle cx=\"{x}\" cy=\"10\" r=\"{r}\"/>");
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 60 40">{}{}{}{}
        <rect x="5" y="30" width="40" height="1"/>
        <path d="M0,20 Q15,10 30,20 T60,20" fill="none" stroke="black"/></svg>"#,
        dot(10.0, 1.0),
        dot(20.0, 1.0),
        dot(30.0, 1.0),
        dot(45.0, 2.0)
    );
    let exemplar = CurveExemplar::from_svg_data("dots", svg.as_bytes()).unwrap();
    let learned = exemplar.curves(1.5);
    assert_eq!(learned.elements.placed.len(), 4);
    assert_eq!(learned.elements.kinds.len(), 2, "small dots alike, the large one its own kind");
    let centres: Vec<DVec2> = learned.elements.placed.iter().map(|e| e.centre_mm).collect();
    for (c, x) in centres.iter().zip([10.0, 20.0, 30.0, 45.0]) {
        // y is flipped to point up.
        assert!(c.distance(DVec2::new(x, -10.0)) < 0.01, "{c} for the dot at x = {x}");
    }
    // The band's centre line and the wave remain; no dot outline does.
    assert_eq!(learned.paths.len(), 2);
    assert!(learned.paths.iter().all(|p| p.length_mm() > 30.0));
}

/// The berries' fill against their exemplar: elements whole, as dense,
/// never overlapping, and on their stalks about as often.
#[test]
fn berries_fill_with_whole_elements_as_dense_as_the_exemplar() {
    let settings = Settings::default();
    let margin = settings.radius_mm();
    let exemplar = CurveExemplar::builtin("berries").unwrap();
    let learned = exemplar.curves(settings.delta_mm);
    assert_eq!(learned.elements.kinds.len(), 2, "berries and loose dots");
    let ex_shapes = learned.elements.polygons();
    let ex_paths = polylines(learned.paths.iter().map(|p| (p.points_mm.clone(), p.closed)));
    let ex_bounds = Rect::from_points(
        ex_paths.iter().flat_map(|p| p.0.iter().copied()).chain(ex_shapes.iter().flat_map(|s| s.outer.iter().copied())),
    )
    .unwrap();
    let ex = element_statistics(&ex_shapes, &ex_paths, &ex_bounds, 0.0);
    assert_eq!((ex.count, ex.overlapping_pairs), (20, 0));
    let areas: Vec<f64> = ex_shapes.iter().map(Polygon::area).collect();
    let region = parse_region("rect:50x35").unwrap();
    let bounds = region.bounds().unwrap();
    for seed in [1, 2] {
        let mut settings = Settings::default();
        settings.seed = seed;
        let product = make_product(&exemplar, &region, &settings, &Control::default()).unwrap();
        let shapes = &product.filled_mm.polygons;
        assert_eq!(product.facts.count("elements"), Some(shapes.len()));
        // Whole: each is an exemplar's shape, by area, and wholly inside.
        for shape in shapes {
            assert!(areas.iter().any(|a| (a - shape.area()).abs() < 1e-9), "seed {seed}: a cut or changed element");
            assert!(shape.outer.iter().all(|p| region.contains(*p)), "seed {seed}: an element crosses the edge");
        }
        let paths = polylines(product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)));
        let out = element_statistics(shapes, &paths, &bounds, margin);
        println!(
            "seed {seed}: {} elements, {:.2} per 100 mm² (exemplar {:.2}), {} overlapping, {:.2} touching (exemplar {:.2})",
            out.count, out.per_100mm2, ex.per_100mm2, out.overlapping_pairs, out.touching_share, ex.touching_share
        );
        assert!(
            (out.per_100mm2 - ex.per_100mm2).abs() <= 0.3 * ex.per_100mm2,
            "seed {seed}: {:.2} elements per 100 mm², the exemplar {:.2}",
            out.per_100mm2,
            ex.per_100mm2
        );
        assert_eq!(out.overlapping_pairs, 0, "seed {seed}: elements overlap, where the exemplar's never do");
        assert!(
            (out.touching_share - ex.touching_share).abs() <= 0.25,
            "seed {seed}: {:.2} of elements touch a path, the exemplar's {:.2}",
            out.touching_share,
            ex.touching_share
        );
        // The print holds them: as many bodies as the region has parts.
        assert!(product.mesh_mm.is_some());
    }
}

/// An exemplar of dots alone, two sizes in a staggered grid: a texture of
/// discrete elements with no curve at all.
#[test]
fn dots_alone_fill_a_region_as_densely_and_never_overlap() {
    let dots: String = (0..64)
        .map(|k| {
            let (i, j) = (k % 8, k / 8);
            let (x, y) = (5.0 * i as f64 + 2.5 + 2.5 * (j % 2) as f64, 5.0 * j as f64 + 2.5);
            let r = if (i + j) % 3 == 0 { 1.3 } else { 0.8 };
            format!("<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\"/>")
        })
        .collect();
    let svg = format!(r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 42 40">{dots}</svg>"#);
    let exemplar = CurveExemplar::from_svg_data("dots", svg.as_bytes()).unwrap();
    let settings = Settings::default();
    let learned = exemplar.curves(settings.delta_mm);
    assert!(learned.paths.is_empty() && learned.elements.kinds.len() == 2);
    let ex_shapes = learned.elements.polygons();
    let ex_bounds = Rect::from_points(ex_shapes.iter().flat_map(|s| s.outer.iter().copied())).unwrap();
    let ex = element_statistics(&ex_shapes, &[], &ex_bounds, 0.0);
    let region = parse_region("rect:50x35").unwrap();
    let product = make_product(&exemplar, &region, &settings, &Control::default()).unwrap();
    assert!(product.paths_mm.is_empty(), "no curve where the exemplar has none");
    let out = element_statistics(&product.filled_mm.polygons, &[], &region.bounds().unwrap(), settings.radius_mm());
    println!(
        "dots: {:.2} per 100 mm² (exemplar {:.2}), {} overlapping",
        out.per_100mm2, ex.per_100mm2, out.overlapping_pairs
    );
    assert!((out.per_100mm2 - ex.per_100mm2).abs() <= 0.3 * ex.per_100mm2, "{out:?} against {ex:?}");
    assert_eq!(out.overlapping_pairs, 0);
    // Every dot prints as a body of its own.
    assert_eq!(product.topology.components, product.filled_mm.polygons.len());
}
