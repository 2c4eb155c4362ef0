//! Curves on 3D objects: laying the part of a base around the picked
//! points flat (the budget: ≤ 1 s at 50k triangles), and the whole
//! way from picked points to a band's shell on a 20k-triangle base
//! (budget ≤ 200 ms).
//!
//! `cargo bench -p tracery-core --bench surface`

use criterion::{Criterion, criterion_group, criterion_main};
use tracery_core::control::Control;
use tracery_core::mesh::split_edges;
use tracery_core::surface::{Chart, SurfaceMesh, SurfaceSettings, builtin_base};
use tracery_core::vector_brush::{Settings, builtin, make_on_surface};

fn bench_surface(c: &mut Criterion) {
    let mut group = c.benchmark_group("surface");
    group.sample_size(10);

    // The sphere with its long edges halved: about 64k triangles, of which
    // the chart round its equator takes most.
    let fine =
        split_edges(&builtin_base("sphere").unwrap(), |a, b| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>() > 1.0);
    let sphere = SurfaceMesh::new(fine).unwrap();
    let ring = SurfaceSettings::parse_points("30,0,30;0,30,30;-30,0,30;0,-30,30").unwrap();
    let picked: Vec<_> = ring.iter().map(|&p| sphere.closest_point(p)).collect();
    let chart = Chart::around(&sphere, &picked, true, 30.0).unwrap();
    let label = format!("chart_{}k_of_{}k_triangles", chart.triangle_count() / 1000, sphere.triangles().len() / 1000);
    group.bench_function(label, |b| b.iter(|| Chart::around(&sphere, &picked, true, 30.0).unwrap()));

    let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap();
    let mut drawn = SurfaceSettings::default();
    drawn.points_mm = SurfaceSettings::parse_points("30,0,25;0,30,25;-30,0,25;0,-30,25").unwrap();
    drawn.closed = true;
    let mut settings = Settings::default();
    settings.band_mm = 8.0;
    for name in ["chain", "lace"] {
        let exemplar = builtin(name).unwrap();
        group.bench_function(format!("points_to_shell_vase_ring_{name}"), |b| {
            b.iter(|| make_on_surface(&exemplar, &vase, &drawn, &settings, &Control::default()).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, bench_surface);
criterion_main!(benches);
