//! A pattern growing while its stroke is drawn: every step meets the
//! targets on the final geometry, keeps what was laid, and ends within twice
//! the cost of a pattern made from scratch (which the app makes when the
//! stroke ends).

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::{Along, Curve};
use tracery_core::geom::count_topology;
use tracery_core::product::Fact;
use tracery_core::vector_brush::{
    Growing, PieceSet, Settings, SliceOptions, SolveOptions, builtin, make_product, solve,
};

/// The first `length_mm` of a 300 mm wave, as a stroke drawn so far.
fn stroke(length_mm: f64) -> Curve {
    let points: Vec<DVec2> =
        (0..=(length_mm as usize)).map(|x| DVec2::new(x as f64, 12.0 * (x as f64 / 25.0).sin())).collect();
    Curve::from_stroke(&points, false, 0.5).unwrap()
}

#[test]
fn a_growing_stroke_keeps_its_pieces_and_meets_the_targets_at_every_step() {
    for name in ["vine", "lace", "braid"] {
        let exemplar = builtin(name).unwrap();
        let settings = Settings::default();
        let mut growing = Growing::new(&exemplar, &settings).unwrap();
        let mut kept_total = 0;
        let mut last = None;
        for step in 3..=30 {
            let product = growing.grow(&stroke(10.0 * step as f64), &Control::default()).unwrap();
            assert_eq!(count_topology(&product.region_mm).components, 1, "{name} at {} mm", 10 * step);
            kept_total += growing.kept();
            last = Some(product);
        }
        assert!(kept_total > 100, "{name}: only {kept_total} pieces kept over 28 steps");
        let grown = last.unwrap();
        let fresh = make_product(&exemplar, &Along::Curve(stroke(300.0)), &settings, &Control::default()).unwrap();
        let cost = |p: &tracery_core::Product| match p.facts.get("cost") {
            Some(Fact::Number(c)) => *c,
            _ => panic!("no cost"),
        };
        assert!(
            cost(&grown) <= 2.0 * cost(&fresh) + 1e-9,
            "{name}: grown {} vs from scratch {}",
            cost(&grown),
            cost(&fresh)
        );
        assert!(grown.mesh_mm.is_none(), "a preview, no solid");
        let filled: f64 = grown.fill_mm.iter().map(|t| tracery_core::geom::signed_area(t).abs()).sum();
        assert!((filled - grown.region_mm.area()).abs() < 1e-3 * grown.region_mm.area(), "the fill covers the pattern");
    }
}

#[test]
fn the_solver_extends_a_prefix_and_starts_again_when_it_cannot() {
    let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(20.0 * set.pieces.iter().map(|p| p.width).sum::<f64>() / set.len() as f64);
    let full = solve(&set, &options, &Control::default()).unwrap();
    options.prefix = full.pieces[..full.pieces.len() / 2].to_vec();
    let extended = solve(&set, &options, &Control::default()).unwrap();
    assert_eq!(extended.pieces[..options.prefix.len()], options.prefix[..]);
    assert_eq!(extended.components, 1);
    // A prefix that cannot begin a pattern (its first piece has open portals on the left).
    let inner = (0..set.len()).find(|&p| !set.pieces[p].left.is_empty()).unwrap();
    options.prefix = vec![inner];
    let again = solve(&set, &options, &Control::default()).unwrap();
    assert_eq!(again.components, 1);
    assert_ne!(again.pieces[0], inner);
}
