//! From a piece sequence to planar geometry: positioning, stitching, mapping.

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::{Curve, map_along, planar_topology};
use tracery_core::geom::count_topology;
use tracery_core::mesh::extrude;
use tracery_core::quality::max_distance_from;
use tracery_core::vector_brush::{
    BAND_MARGIN, CurveKind, PieceSet, Settings, SliceOptions, SolveOptions, builtin, position_offsets, solve,
    spread_offsets, stitch, synthesize,
};

#[test]
fn solver_offsets_keep_every_piece_in_the_band() {
    // Tilted drifts by a step at every jump back in the exemplar: unbounded,
    // the offsets walk away from the axis.
    let exemplar = builtin("tilted").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(6.0 * exemplar.width());
    let free = solve(&set, &options, &Control::default()).unwrap();
    options.band_height = exemplar.height();
    let bounded = solve(&set, &options, &Control::default()).unwrap();
    let half = 0.5 * exemplar.height() * (1.0 + BAND_MARGIN);
    let reach = |s: &tracery_core::vector_brush::Solution| {
        s.pieces.iter().zip(&s.offsets).map(|(&p, d)| d.abs() + set.pieces[p].extent()).fold(0.0, f64::max)
    };
    assert!(reach(&free) > half, "the unbounded search should drift: {}", reach(&free));
    assert!(reach(&bounded) <= half + 1e-6, "{} > {half}", reach(&bounded));
    // On an open curve the stitched offsets are the solver's own.
    assert_eq!(spread_offsets(&set, &bounded.pieces, &bounded.offsets, CurveKind::Open), bounded.offsets);
}

#[test]
fn synthesized_geometry_stays_within_half_the_band_plus_five_percent() {
    let curves = [Curve::line(160.0).unwrap(), Curve::circle(35.0).unwrap(), Curve::wave(160.0).unwrap()];
    for name in ["tilted", "lace", "vine", "filigree"] {
        let exemplar = builtin(name).unwrap();
        for curve in &curves {
            let settings = Settings::default();
            let s = synthesize(&exemplar, curve, &settings, &Control::default()).unwrap();
            // Measured on the final planar geometry, against the curve itself.
            let drift = max_distance_from(&s.planar.region, curve);
            assert!(drift <= 0.5 * settings.band_mm * 1.05, "{name}: {drift} mm from the curve");
        }
    }
}

#[test]
fn stitched_pieces_meet_without_gaps_and_span_the_exact_length() {
    for name in ["lace", "braid", "meander", "vine"] {
        let exemplar = builtin(name).unwrap();
        let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
        let length = 5.3 * exemplar.width();
        let solution = solve(&set, &SolveOptions::new(length), &Control::default()).unwrap();
        let offsets = position_offsets(&set, &solution.pieces, CurveKind::Open);
        let band = stitch(&set, &solution.pieces, &offsets, length, CurveKind::Open, 1e-3 * exemplar.height());
        let bounds = band.region.bounds().unwrap();
        assert!(bounds.min.x.abs() < 1e-9 && (bounds.max.x - length).abs() < 1e-9 * length, "{name}: {bounds:?}");
        // Any gap at a seam would split the pattern; any overlap would merge holes.
        let t = count_topology(&band.region);
        assert_eq!((t.components as u32, t.holes as u32), (solution.components, solution.holes), "{name}");
        assert_eq!(band.seams.len(), solution.pieces.len() - 1);
    }
}

#[test]
fn curves_are_parameterized_by_arc_length() {
    let circle = Curve::circle(10.0).unwrap();
    assert!((circle.length() - std::f64::consts::TAU * 10.0).abs() < 0.01);
    assert!(circle.is_closed());
    // A loop wraps around: its end is its start.
    assert!(circle.point(circle.length()).distance(circle.point(0.0)) < 1e-12);
    // The left normal of a counter-clockwise circle points to its centre.
    let p = circle.point(3.0);
    assert!((p + circle.normal(3.0) * 10.0).length() < 0.01);
    assert!((circle.curvature(5.0, 1.0) - 0.1).abs() < 1e-3);
    let wave = Curve::wave(120.0).unwrap();
    assert!((wave.length() - 120.0).abs() < 1e-6);
    let jittery: Vec<DVec2> =
        (0..200).map(|i| DVec2::new(i as f64 * 0.5, if i % 2 == 0 { 0.0 } else { 0.4 })).collect();
    let smooth = Curve::from_stroke(&jittery, false, 1.0).unwrap();
    let worst = (5..95).map(|u| smooth.curvature(u as f64, 2.0).abs()).fold(0.0, f64::max);
    assert!(worst < 0.2, "stroke smoothing left curvature {worst}");
    assert!(Curve::from_polyline(&[DVec2::ZERO, DVec2::ZERO], false).is_err());
    assert!(Curve::from_polyline(&[DVec2::ZERO, DVec2::new(f64::NAN, 0.0)], false).is_err());
}

#[test]
fn tight_turns_narrow_the_band_instead_of_folding_it() {
    let exemplar = builtin("lace").unwrap();
    let curve = Curve::circle(5.0).unwrap();
    let mut request = Settings::default();
    request.band_mm = 12.0;
    request.variety = 0.0;
    request.closed_pattern = true;
    let synthesis = synthesize(&exemplar, &curve, &request, &Control::default()).unwrap();
    assert!(synthesis.planar.narrowest_band < 1.0);
    assert!(
        synthesis.warnings.iter().any(|w| matches!(w, tracery_core::report::Warning::BandNarrowed { .. })),
        "{:?}",
        synthesis.warnings
    );
    // The output is clean: merging it again changes nothing, and it still
    // has the planned topology.
    let t = count_topology(&synthesis.planar.region);
    assert_eq!(t.components, synthesis.planar.region.component_count());
    assert_eq!(synthesis.topology.components as u32, synthesis.solution.components);
    assert_eq!(synthesis.topology.holes as u32, synthesis.solution.holes);
    assert_eq!(synthesis.topology.loop_openings, 1);
}

#[test]
fn loops_weld_at_their_closing_seam() {
    for name in ["lace", "vine", "tilted", "islands"] {
        let exemplar = builtin(name).unwrap();
        let curve = Curve::circle(30.0).unwrap();
        let mut request = Settings::default();
        request.band_mm = 12.0;
        request.variety = 0.0;
        request.closed_pattern = true;
        let s = synthesize(&exemplar, &curve, &request, &Control::default()).unwrap();
        let again = map_along(&s.band.region, s.scale_mm_per_unit, &curve);
        let t = planar_topology(&again.region, &curve);
        assert_eq!(
            (t.components as u32, t.holes as u32, t.loop_openings),
            (s.solution.components, s.solution.holes, 1),
            "{name}"
        );
        let mesh = extrude(&s.planar.region, 1.5).unwrap();
        assert_eq!(mesh.shell_count(), t.components, "{name}");
    }
}
