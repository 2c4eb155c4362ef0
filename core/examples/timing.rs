//! Quick timings of the benchmark workloads (median of a few runs), for
//! trying changes before running the criterion benchmarks.
//!
//! `cargo run -p tracery-core --release --example timing [VARIETY]`

use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::vector_brush::{CurveKind, PieceSet, SliceOptions, SolveOptions, Target, builtin, solve};

fn main() {
    let variety: f64 = std::env::args().nth(1).and_then(|v| v.parse().ok()).unwrap_or(0.5);
    for name in ["vine", "braid", "filigree", "tilted"] {
        let set = PieceSet::new(&builtin(name).expect("built-in"), &SliceOptions::default()).expect("slicing");
        for curve in [CurveKind::Open, CurveKind::Closed] {
            let mut options = SolveOptions::new(190.0 * set.exemplar_width / set.len() as f64);
            options.curve = curve;
            options.components = Target::Exactly(1);
            options.closed_pattern = curve == CurveKind::Closed;
            options.variety = variety;
            let mut times = Vec::new();
            let mut states = 0;
            for _ in 0..5 {
                let t = Instant::now();
                states = solve(&set, &options, &Control::default()).expect("solution").states;
                times.push(t.elapsed().as_secs_f64() * 1e3);
            }
            times.sort_by(f64::total_cmp);
            println!("{name:9} {curve:?}: median {:7.1} ms, {states} states", times[2]);
        }
    }
}
