//! Time per added piece of the raster brush's search, at the paper's two
//! exemplar sizes (chain 199 × 82, braid 325 × 64), on curves of growing
//! length: the median of 3 runs each.
//!
//! `cargo run -p tracery-core --release --example raster_timing`

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::Region;
use tracery_core::raster_brush::{Settings, builtin, make_product};

fn main() {
    println!("| exemplar | curve | pieces | search ms | ms per piece (median of 3) | whole run ms |");
    println!("|---|---|---|---|---|---|");
    for name in ["chain", "braid", "rope", "vine"] {
        let exemplar = builtin(name).expect("built-in");
        for spec in ["wave:80", "wave:160", "wave:320", "circle:25"] {
            let along = Along::parse(spec).expect("curve");
            let mut runs: Vec<(f64, f64, f64, usize)> = (0..3)
                .map(|_| {
                    let p =
                        make_product(&exemplar, &along, &Settings::default(), &Region::default(), &Control::default())
                            .expect("synthesis");
                    let t = &p.timings;
                    (
                        t.stage_ms("per_piece").unwrap_or(0.0),
                        t.stage_ms("search").unwrap_or(0.0),
                        t.total_ms(),
                        p.facts.count("pieces").unwrap_or(0),
                    )
                })
                .collect();
            runs.sort_by(|a, b| a.0.total_cmp(&b.0));
            let (per, search, total, pieces) = runs[1];
            println!(
                "| {name} {}x{} | {spec} | {pieces} | {search:.0} | {per:.1} | {total:.0} |",
                exemplar.width(),
                exemplar.height()
            );
        }
    }
}
