//! Solver benchmarks at the scale of the paper's Table 1: exemplars cut into
//! 10 to 20 pieces, results of 56 to 190 pieces, open and closed curves, one
//! component, autocorrelation on.
//!
//! `cargo bench -p tracery-core --bench solver`

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use tracery_core::control::Control;
use tracery_core::vector_brush::{CurveKind, PieceSet, SliceOptions, SolveOptions, Target, builtin, solve};

/// Exemplars with 10 to 20 pieces under the default slicing.
const EXEMPLARS: &[&str] = &["vine", "braid", "filigree", "tilted"];

fn options(set: &PieceSet, pieces: f64, curve: CurveKind) -> SolveOptions {
    let mean_width = set.exemplar_width / set.len() as f64;
    let mut options = SolveOptions::new(pieces * mean_width);
    options.curve = curve;
    options.components = Target::Exactly(1);
    options.closed_pattern = curve == CurveKind::Closed;
    options.variety = 0.5;
    options
}

fn bench_solver(c: &mut Criterion) {
    for (curve, label) in [(CurveKind::Open, "open"), (CurveKind::Closed, "closed")] {
        let mut group = c.benchmark_group(format!("solve_{label}"));
        group.sample_size(10);
        for name in EXEMPLARS {
            let set = PieceSet::new(&builtin(name).unwrap(), &SliceOptions::default()).unwrap();
            assert!((10..=20).contains(&set.len()), "{name} has {} pieces", set.len());
            // 95 and 190 pieces: the same workload at twice the length.
            for pieces in [56.0, 95.0, 190.0] {
                let options = options(&set, pieces, curve);
                group.bench_with_input(BenchmarkId::new(*name, pieces as u32), &options, |b, options| {
                    b.iter(|| solve(&set, options, &Control::default()).unwrap())
                });
            }
        }
        group.finish();
    }
}

criterion_group!(benches, bench_solver);
criterion_main!(benches);
