//! The whole pipeline as the app and the command line run it: analysis,
//! solver, positioning, stitching, mapping, topology count and meshing.
//!
//! `cargo bench -p tracery-core --bench pipeline`

use criterion::{Criterion, criterion_group, criterion_main};
use tracery_core::control::Control;
use tracery_core::curve::Curve;
use tracery_core::mesh::extrude;
use tracery_core::vector_brush::{Settings, builtin, synthesize};

fn bench_pipeline(c: &mut Criterion) {
    let mut group = c.benchmark_group("pipeline");
    group.sample_size(10);
    let cases = [
        ("lace_bracelet_r30", "lace", Curve::circle(30.0).unwrap(), true),
        ("vine_wave_150", "vine", Curve::wave(150.0).unwrap(), false),
        ("braid_line_300", "braid", Curve::line(300.0).unwrap(), false),
    ];
    for (label, name, curve, closed_pattern) in cases {
        let exemplar = builtin(name).unwrap();
        let mut request = Settings::default();
        request.band_mm = 12.0;
        request.closed_pattern = closed_pattern;
        request.variety = 0.3;
        group.bench_function(label, |b| {
            b.iter(|| {
                let s = synthesize(&exemplar, &curve, &request, &Control::default()).unwrap();
                extrude(&s.planar.region, 2.0).unwrap()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_pipeline);
criterion_main!(benches);
