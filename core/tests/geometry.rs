//! From a piece sequence to planar geometry: positioning, stitching, mapping.

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::{Curve, map_along, planar_topology};
use tracery_core::geom::count_topology;
use tracery_core::mesh::extrude;
use tracery_core::vector_brush::{
    CurveKind, PieceSet, Settings, SliceOptions, SolveOptions, builtin, position_offsets, solve, stitch, synthesize,
};

#[test]
fn offsets_keep_open_ends_on_the_axis_and_follow_alignments() {
    let exemplar = builtin("tilted").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let solution = solve(&set, &SolveOptions::new(4.0 * exemplar.width()), &Control::default()).unwrap();
    let offsets = position_offsets(&set, &solution.pieces, CurveKind::Open);
    assert_eq!(offsets[0], 0.0);
    assert_eq!(*offsets.last().unwrap(), 0.0);
    // The accumulated alignments drift; the least-squares offsets stay closer to the axis.
    let drift = solution.offsets.iter().fold(0.0f64, |m, o| m.max(o.abs()));
    let kept = offsets.iter().fold(0.0f64, |m, o| m.max(o.abs()));
    assert!(kept <= drift + 1e-9, "{kept} vs {drift}");
}

#[test]
fn stitched_pieces_meet_without_gaps_and_span_the_exact_length() {
    for name in ["lace", "braid", "meander", "vine"] {
        let exemplar = builtin(name).unwrap();
        let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
        let length = 5.3 * exemplar.width();
        let solution = solve(&set, &SolveOptions::new(length), &Control::default()).unwrap();
        let offsets = position_offsets(&set, &solution.pieces, CurveKind::Open);
        let band = stitch(&set, &solution.pieces, &offsets, length, CurveKind::Open);
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
