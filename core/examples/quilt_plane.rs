//! Quilts the plane with each built-in swatch and prints what happened:
//! patches, merges, elements, faces, closedness and time. With an output
//! folder, writes each quilt as STL there for `mesh_png`, its threads cut at
//! the area's edge as `tracery quilt` cuts them (the time is the quilting's).
//!
//! `cargo run -p tracery-core --release --example quilt_plane -- [WIDTH_MM] [DEPTH_MM] [OUT_DIR] [SWATCH]`

use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::export::write_stl;
use tracery_core::mesh_quilt::{SWATCH_NAMES, Settings, builtin_swatch, crosses_itself, quilt_plane, trim_to_area};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let width: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(80.0);
    let depth: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(width);
    let out_dir = args.get(3);
    let only = args.get(4);
    for name in SWATCH_NAMES.iter().filter(|n| only.is_none_or(|o| o == *n)) {
        let swatch = builtin_swatch(name).expect("built-in swatch");
        let start = Instant::now();
        let mut quilt = quilt_plane(&swatch, width, depth, &Settings::default(), &Control::default()).expect("quilt");
        let ms = start.elapsed().as_secs_f64() * 1000.0;
        // As `tracery quilt` does: threads cut at the area's edge.
        let edge = trim_to_area(&mut quilt.elements, width, depth, swatch.fragment_volume_mm3()).expect("edge cut");
        let faces: usize = quilt.elements.iter().map(|e| e.triangles.len()).sum();
        let open = quilt.elements.iter().filter(|e| !e.is_closed()).count();
        let crossing = quilt.elements.iter().filter(|e| crosses_itself(e)).count();
        println!(
            "{name:10} {width:.0}x{depth:.0} mm: {:5.0} ms, {} patches, {} elements ({open} open, {crossing} crossing), {faces} faces; {:?}, outside {}, fragments {}, cut at the edge {} ({} crumbs)",
            ms,
            quilt.counts.patches,
            quilt.elements.len(),
            quilt.counts.merges,
            quilt.counts.outside,
            quilt.counts.fragments,
            edge.cut,
            edge.crumbs
        );
        if let Some(dir) = out_dir {
            let mut mesh = tracery_core::mesh::Mesh::default();
            for e in &quilt.elements {
                mesh.append(&e.to_mesh());
            }
            let mut file = std::fs::File::create(format!("{dir}/{name}.stl")).expect("create STL");
            write_stl(&mesh, &mut file).expect("write STL");
        }
    }
}
