//! Quilts a built-in base with a built-in swatch and prints what it did:
//! `cargo run -p tracery-core --release --example quilt_surface -- [BASE] [SWATCH] [SCALE] [OUT.stl]`.

use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::export::write_stl;
use tracery_core::mesh::Mesh;
use tracery_core::mesh_quilt::{GuidanceField, Settings, builtin_swatch, crosses_itself, quilt_surface};
use tracery_core::surface::{SurfaceMesh, builtin_base};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let base = args.get(1).map_or("vase", String::as_str);
    let swatch = args.get(2).map_or("rivets", String::as_str);
    let scale: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1.0);
    let surface = SurfaceMesh::new(builtin_base(base).expect("a built-in base")).expect("a sound base");
    let swatch = builtin_swatch(swatch).expect("a built-in swatch").scaled(scale);
    let start = Instant::now();
    let quilt = quilt_surface(
        &swatch,
        &surface,
        &GuidanceField::around_axis(&surface),
        &Settings::default(),
        &Control::default(),
    )
    .expect("a quilt");
    let mut mesh = Mesh::default();
    for e in &quilt.elements {
        mesh.append(&e.to_mesh());
    }
    println!(
        "{base} + {}: {} ms, {} patches, {} elements ({} crossing), {} faces; {:?}; {:?}",
        swatch.name,
        start.elapsed().as_millis(),
        quilt.counts.patches,
        quilt.elements.len(),
        quilt.elements.iter().filter(|e| crosses_itself(e)).count(),
        mesh.triangles.len(),
        quilt.counts.merges,
        quilt.shell
    );
    if let Some(out) = args.get(4) {
        let mut file = std::fs::File::create(out).expect("create the STL");
        write_stl(&mesh, &mut file).expect("write the STL");
    }
}
