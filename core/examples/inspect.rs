//! Prints how each built-in exemplar is cut and what the solver makes of it.
//!
//! `cargo run -p tracery-core --release --example inspect [LENGTH_FACTOR]`

use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::vector_brush::{
    BUILTIN_NAMES, CurveKind, PieceSet, SliceOptions, SolveOptions, Target, builtin, solve,
};

fn main() {
    let factor: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(5.0);
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).expect("built-in exemplar loads");
        let set = PieceSet::new(&exemplar, &SliceOptions::default()).expect("slicing");
        println!(
            "{name}: {:.1} x {:.1}, {} polygons, {} holes, {} pieces",
            exemplar.width(),
            exemplar.height(),
            exemplar.region.component_count(),
            exemplar.region.hole_count(),
            set.len()
        );
        for p in &set.pieces {
            println!(
                "   piece {:2} w={:6.2} L{:?} R{:?} closed={} holes={}",
                p.index,
                p.width,
                p.descriptor.left(),
                p.descriptor.right(),
                p.descriptor.closed_components(),
                p.descriptor.holes()
            );
        }
        for curve in [CurveKind::Open, CurveKind::Closed] {
            let mut options = SolveOptions::new(factor * exemplar.width());
            options.curve = curve;
            options.closed_pattern = curve == CurveKind::Closed;
            options.components = Target::Exactly(1);
            options.variety = 0.5;
            let t = Instant::now();
            match solve(&set, &options, &Control::default()) {
                Ok(s) => println!(
                    "   {curve:?}: {} pieces, cost {:.3}, length {:.1}/{:.1}, comps {} holes {} wraps {} states {} in {:.1} ms",
                    s.pieces.len(),
                    s.matching_cost,
                    s.length,
                    s.target_length,
                    s.components,
                    s.holes,
                    s.wraps,
                    s.states,
                    t.elapsed().as_secs_f64() * 1e3
                ),
                Err(e) => println!("   {curve:?}: {e} in {:.1} ms", t.elapsed().as_secs_f64() * 1e3),
            }
        }
    }
}
