//! Every built-in exemplar along a ring and an open curve on each built-in
//! base: whether the shell written as STL (so in `f32`) reads back closed
//! and manifold, with as many shells as the plan's components, and how long
//! each took. Prints one line per run and a summary.
//!
//! With `emboss`, each band is united with its base, and the body must be
//! one shell.
//!
//! `cargo run -p tracery-core --release --example surface_sweep [-- BAND_MM [emboss]]`

use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::export::write_stl;
use tracery_core::mesh::read_stl;
use tracery_core::surface::{SurfaceMesh, SurfaceOutput, SurfaceSettings, builtin_base};
use tracery_core::vector_brush::{BUILTIN_NAMES, Settings, builtin, make_on_surface};

const CURVES: [(&str, &str, &str, bool); 12] = [
    ("vase", "ring", "30,0,25;0,30,25;-30,0,25;0,-30,25", true),
    ("vase", "open", "30,0,25;21,21,40;0,30,55", false),
    ("egg", "ring", "21,0,30;0,21,30;-21,0,30;0,-21,30", true),
    ("egg", "open", "21,0,20;15,-15,30;0,-19,40", false),
    ("cylinder", "ring", "25,0,30;0,25,30;-25,0,30;0,-25,30", true),
    ("cylinder", "open", "25,0,10;0,-25,30;-25,0,50", false),
    ("cone", "ring", "20,0,20;0,20,20;-20,0,20;0,-20,20", true),
    ("cone", "open", "20,0,10;0,-15,30", false),
    ("sphere", "ring", "30,0,30;0,30,30;-30,0,30;0,-30,30", true),
    ("sphere", "open", "30,0,30;21,-21,45;0,-30,50", false),
    ("torus", "ring", "40,0,10;0,40,10;-40,0,10;0,-40,10", true),
    ("torus", "tube", "30,0,20;40,0,10;30,0,0;20,0,10", true),
];

fn main() {
    let band_mm: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(8.0);
    let emboss = std::env::args().nth(2).as_deref() == Some("emboss");
    let (mut runs, mut sound, mut slowest_ms, mut most_triangles) = (0, 0, 0.0_f64, 0);
    for (base, kind, points, closed) in CURVES {
        let surface = SurfaceMesh::new(builtin_base(base).unwrap()).unwrap();
        let mut drawn = SurfaceSettings::default();
        drawn.points_mm = SurfaceSettings::parse_points(points).unwrap();
        drawn.closed = closed;
        if emboss {
            drawn.output = SurfaceOutput::Emboss;
        }
        for name in BUILTIN_NAMES {
            let mut settings = Settings::default();
            settings.band_mm = band_mm;
            runs += 1;
            let start = Instant::now();
            let made = make_on_surface(&builtin(name).unwrap(), &surface, &drawn, &settings, &Control::default());
            let ms = start.elapsed().as_secs_f64() * 1e3;
            slowest_ms = slowest_ms.max(ms);
            let verdict = match made {
                Err(e) => format!("FAILED: {e}"),
                Ok(product) => {
                    let shell = product.mesh_mm.expect("a surface product has a solid");
                    most_triangles = most_triangles.max(shell.triangles.len());
                    let mut bytes = Vec::new();
                    write_stl(&shell, &mut bytes).unwrap();
                    let back = read_stl(&bytes, "sweep").unwrap();
                    let shells = back.shell_count();
                    match back.sanity_check() {
                        Err(defect) => format!("OPEN in f32: {defect}"),
                        Ok(()) if shells != if emboss { 1 } else { product.topology.components } => {
                            format!("{shells} shells for {} components", product.topology.components)
                        }
                        Ok(()) => {
                            sound += 1;
                            format!("ok, {shells} shell(s), {} triangles", shell.triangles.len())
                        }
                    }
                }
            };
            println!("{base:9} {kind:5} {name:9} {ms:7.1} ms  {verdict}");
        }
    }
    println!("{sound} of {runs} sound; slowest {slowest_ms:.0} ms; most triangles {most_triangles}");
}
