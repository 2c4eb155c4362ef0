//! Every stage's output keeps its invariants: `sanity_check()` after each
//! stage, for every built-in exemplar along a line, a wave and a loop.

use tracery_core::control::Control;
use tracery_core::curve::{Curve, map_along, planar_topology};
use tracery_core::geom::{count_topology, separate_touching};
use tracery_core::mesh::{Mesh, extrude};
use tracery_core::vector_brush::{
    BUILTIN_NAMES, CurveKind, Exemplar, PieceSet, RESOLUTION_MM, Settings, SliceOptions, SlicingMode, SolveError,
    SolveOptions, Target, builtin, settled_region, solve, spread_offsets, stitch,
};

#[test]
fn every_stage_keeps_its_invariants() {
    let mut checked = 0;
    for name in BUILTIN_NAMES {
        let drawn = builtin(name).unwrap();
        drawn.region.sanity_check().unwrap_or_else(|e| panic!("{name}: exemplar: {e}"));
        // As the pipeline analyses it at a 10 mm band.
        let settled = settled_region(&drawn.region, RESOLUTION_MM * drawn.height() / 10.0);
        let exemplar = Exemplar::from_region(*name, settled).unwrap();
        exemplar.region.sanity_check().unwrap_or_else(|e| panic!("{name}: settled exemplar: {e}"));
        for mode in [SlicingMode::Topology, SlicingMode::Uniform { cuts: 7 }] {
            let mut slicing = SliceOptions::default();
            slicing.mode = mode;
            let set = PieceSet::new(&exemplar, &slicing).unwrap();
            for piece in &set.pieces {
                piece.region.sanity_check().unwrap_or_else(|e| panic!("{name} {mode:?}: piece {}: {e}", piece.index));
            }
            for (curve, kind) in [
                (Curve::line(90.0).unwrap(), CurveKind::Open),
                (Curve::wave(90.0).unwrap(), CurveKind::Open),
                (Curve::circle(22.0).unwrap(), CurveKind::Closed),
            ] {
                let context = format!("{name} {mode:?} {kind:?}");
                let scale = 10.0 / exemplar.height();
                let mut options = SolveOptions::new(curve.length() / scale);
                options.curve = kind;
                options.variety = 0.3;
                // Within the band, as the pipeline asks: unbounded, a drifting
                // exemplar (filigree) strays two band heights off a wave and
                // folds over its turns.
                options.band_height = exemplar.height();
                // One component: "any" still plans side-by-side end caps as
                // separate parts that the geometry welds (a known bug, filed
                // with the vector-brush issue), which would hide what this
                // test is about. Cases with no one-component solution are skipped.
                options.components = Target::Exactly(1);
                let solution = match solve(&set, &options, &Control::default()) {
                    Ok(solution) => solution,
                    Err(SolveError::NoSolution(_)) => continue,
                    Err(e) => panic!("{context}: {e}"),
                };
                checked += 1;
                let offsets = spread_offsets(&set, &solution.pieces, &solution.offsets, kind);
                let band =
                    stitch(&set, &solution.pieces, &offsets, curve.length() / scale, kind, 1e-3 * exemplar.height());
                band.region.sanity_check().unwrap_or_else(|e| panic!("{context}: band: {e}"));
                // Parts that only touch at a point are moved apart, as the
                // pipeline does, before mapping could merge them.
                let band_region = separate_touching(&band.region, RESOLUTION_MM / scale);
                band_region.sanity_check().unwrap_or_else(|e| panic!("{context}: band apart: {e}"));
                let planar = map_along(&band_region, scale, &curve);
                planar.region.sanity_check().unwrap_or_else(|e| panic!("{context}: planar: {e}"));
                // Topology counted on the final geometry equals the plan.
                let counted = planar_topology(&planar.region, &curve);
                assert_eq!(
                    (counted.components as u32, counted.holes as u32),
                    (solution.components, solution.holes),
                    "{context}"
                );
                let mesh = extrude(&planar.region, 2.0).unwrap();
                mesh.sanity_check().unwrap_or_else(|e| panic!("{context}: mesh: {e}"));
                assert_eq!(mesh.shell_count(), count_topology(&planar.region).components, "{context}");
            }
        }
    }
    // 8 exemplars × 2 slicings × 3 curves; a few have no one-component pattern.
    assert!(checked >= 36, "only {checked} of 48 cases checked");
}

#[test]
fn the_checks_find_broken_geometry() {
    // A flipped triangle and a missing one are both caught.
    let mesh = extrude(&builtin("vine").unwrap().region, 1.0).unwrap();
    mesh.sanity_check().unwrap();
    let mut flipped = mesh.clone();
    flipped.triangles[0].swap(0, 1);
    assert!(flipped.sanity_check().is_err());
    let holed = Mesh { triangles: mesh.triangles[1..].to_vec(), ..mesh };
    assert!(holed.sanity_check().is_err());
    // A hole turned the wrong way, and a ring that crosses itself.
    let mut lace = builtin("lace").unwrap().region;
    lace.sanity_check().unwrap();
    lace.polygons[0].holes[0].reverse();
    assert!(lace.sanity_check().is_err());
    let mut crossed = builtin("chain").unwrap().region;
    let outer = &mut crossed.polygons[0].outer;
    let n = outer.len();
    outer.swap(1, n / 2);
    assert!(crossed.sanity_check().is_err());
}

#[test]
fn the_whole_product_is_sane() {
    use tracery_core::curve::Along;
    use tracery_core::vector_brush::make_product;
    for spec in ["line:80", "circle:20", "rect:60x40"] {
        let along = Along::parse(spec).unwrap();
        let product =
            make_product(&builtin("lace").unwrap(), &along, &Settings::default(), &Control::default()).unwrap();
        product.region_mm.sanity_check().unwrap_or_else(|e| panic!("{spec}: {e}"));
        let mesh = product.mesh_mm.as_ref().unwrap();
        mesh.sanity_check().unwrap_or_else(|e| panic!("{spec}: {e}"));
        assert_eq!(mesh.shell_count(), product.topology.components, "{spec}");
        assert!(!product.fill_mm.is_empty());
        assert!(product.timings.stage_ms("solve").is_some());
    }
}
