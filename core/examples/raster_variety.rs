//! How much a raster result repeats, measured on the output alone: along a
//! long wave, the exemplar positions the pieces show (x in 4-pixel bins),
//! their near period and longest repeated run, and how often the pattern
//! jumps elsewhere in the exemplar.
//!
//! `cargo run -p tracery-core --release --example raster_variety`

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::Region;
use tracery_core::quality::{longest_repeat, near_period};
use tracery_core::raster_brush::{BUILTIN_NAMES, Settings, builtin, is_continuation, synthesize};

fn main() {
    let variety: f64 = std::env::args().nth(1).map_or(0.0, |v| v.parse().expect("a number"));
    println!("variety {variety}");
    println!("| exemplar | pieces | jumps | near period | longest repeat | distinct bins |");
    println!("|---|---|---|---|---|---|");
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).expect("built-in");
        let Along::Curve(curve) = Along::parse("wave:400").expect("curve") else { unreachable!() };
        let mut settings = Settings::default();
        settings.variety = variety;
        let s = synthesize(&exemplar, &curve, &settings, &Region::default(), &Control::default()).expect("synthesis");
        let xs: Vec<usize> = s.path.positions.iter().map(|p| (p.0.max(0) / 4) as usize).collect();
        let n = xs.len();
        let jumps = (1..n)
            .filter(|&i| !is_continuation(&s.samples[i - 1], s.path.positions[i - 1], s.path.positions[i]))
            .count();
        let mut bins = xs.clone();
        bins.sort_unstable();
        bins.dedup();
        println!("| {name} | {n} | {jumps} | {} | {} | {} |", near_period(&xs), longest_repeat(&xs), bins.len());
    }
}
