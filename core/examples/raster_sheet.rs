//! Contact sheet of the raster brush: every built-in exemplar along a wave,
//! a closed heart and a circle, rendered to PNGs, with timings per piece.
//!
//! `cargo run -p tracery-core --release --example raster_sheet -- OUT_DIR`

use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::export::{encode_png, render_product};
use tracery_core::geom::Region;
use tracery_core::product::Fact;
use tracery_core::raster_brush::{BUILTIN_NAMES, Settings, builtin, make_product};

fn main() {
    let out = std::path::PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "target/raster_sheet".into()));
    std::fs::create_dir_all(&out).expect("output folder");
    let curves = ["wave:160", "heart:70", "circle:25"];
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).expect("built-in");
        for spec in curves {
            let along = Along::parse(spec).expect("curve");
            let start = Instant::now();
            let product =
                match make_product(&exemplar, &along, &Settings::default(), &Region::default(), &Control::default()) {
                    Ok(p) => p,
                    Err(e) => {
                        println!("{name:9} {spec:10} error: {e}");
                        continue;
                    }
                };
            let ms = start.elapsed().as_secs_f64() * 1e3;
            let image = render_product(&product, 12.0).expect("render");
            let file = out.join(format!("{name}-{}.png", spec.replace(':', "-")));
            std::fs::write(&file, encode_png(&image).expect("png")).expect("write");
            let fact = |k: &str| match product.facts.get(k) {
                Some(Fact::Number(x)) => format!("{x:.3}"),
                Some(Fact::Count(n)) => n.to_string(),
                Some(Fact::Text(t)) => t.clone(),
                _ => "-".into(),
            };
            println!(
                "{name:9} {spec:10} pieces {:>4} valid {:>6} per_piece {:>7.2} ms search {:>8.1} ms total {ms:>8.1} ms comps {} holes {} closure {} seams {} -> {}",
                fact("pieces"),
                fact("valid_fraction"),
                product.timings.stage_ms("per_piece").unwrap_or(0.0),
                product.timings.stage_ms("search").unwrap_or(0.0),
                product.topology.components,
                product.topology.holes,
                fact("closure"),
                fact("seam_mismatch_before"),
                fact("seam_mismatch_after"),
            );
        }
    }
}
