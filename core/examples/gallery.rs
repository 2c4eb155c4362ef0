//! The gallery of alternatives, measured and looked at: for each exemplar
//! along a curve, the best pattern and the next ones made to differ from
//! all before them, with how distinct each pair is (share of the length
//! showing different shapes, loops compared at every rotation) and what
//! each costs compared with the best.
//!
//! ```sh
//! cargo run -p tracery-core --release --example gallery -- \
//!     [--along circle:30] [--out gallery.png] [EXEMPLAR.svg …]
//! ```

#[path = "common/sheet.rs"]
mod sheet;

use std::path::PathBuf;
use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::Region;
use tracery_core::quality::distinctness;
use tracery_core::vector_brush::{
    ALTERNATIVES, BUILTIN_NAMES, Exemplar, LoadOptions, Settings, Synthesis, builtin, synthesize_alternatives,
};

const TILE: u32 = 260;

/// The pattern's pieces as (shape class, width along the band).
fn pieces(s: &Synthesis) -> Vec<(usize, f64)> {
    let mut bounds: Vec<f64> = std::iter::once(0.0).chain(s.band.seams.iter().copied()).collect();
    bounds.push(s.band.length);
    bounds.sort_by(f64::total_cmp);
    bounds.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let widths: Vec<f64> = bounds.windows(2).map(|w| w[1] - w[0]).collect();
    if widths.len() == s.shape_classes.len() {
        s.shape_classes.iter().copied().zip(widths).collect()
    } else {
        s.shape_classes.iter().map(|&c| (c, 1.0)).collect()
    }
}

fn main() {
    let mut along = "circle:30".to_string();
    let mut out = PathBuf::from("gallery.png");
    let mut files = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--along" => along = args.next().expect("--along SPEC"),
            "--out" => out = PathBuf::from(args.next().expect("--out FILE")),
            _ => files.push(PathBuf::from(a)),
        }
    }
    let exemplars: Vec<Exemplar> = if files.is_empty() {
        BUILTIN_NAMES.iter().map(|n| builtin(n).expect("built-in")).collect()
    } else {
        files.iter().filter_map(|f| Exemplar::from_svg_file(f, &LoadOptions::default()).ok()).collect()
    };
    let Along::Curve(curve) = Along::parse(&along).expect("a curve") else { panic!("a curve, not a rectangle") };
    let closed = curve.is_closed();
    println!(
        "| exemplar | alternatives | least distinct pair | mean distinctness | worst seam cost / best | ms for all |"
    );
    println!("|---|---|---|---|---|---|");
    let mut rows: Vec<Vec<Region>> = Vec::new();
    for exemplar in &exemplars {
        let start = Instant::now();
        let found = synthesize_alternatives(exemplar, &curve, &Settings::default(), ALTERNATIVES, &Control::default())
            .unwrap_or_default();
        let ms = start.elapsed().as_secs_f64() * 1e3;
        if found.is_empty() {
            println!("| {} | none | | | | |", exemplar.name);
            continue;
        }
        let sequences: Vec<Vec<(usize, f64)>> = found.iter().map(pieces).collect();
        let mut pairs = Vec::new();
        for i in 0..sequences.len() {
            for j in i + 1..sequences.len() {
                pairs.push(distinctness(&sequences[i], &sequences[j], closed));
            }
        }
        let least = pairs.iter().copied().fold(f64::INFINITY, f64::min);
        let mean = pairs.iter().sum::<f64>() / pairs.len().max(1) as f64;
        // Seam costs alone: the alternatives' own totals include what they
        // paid for differing.
        let best = found[0].solution.matching_cost.max(1e-9);
        let worst = found.iter().map(|s| s.solution.matching_cost / best).fold(0.0, f64::max);
        println!(
            "| {} | {} | {:.0}% | {:.0}% | {:.2} | {:.0} |",
            exemplar.name,
            found.len(),
            100.0 * least,
            100.0 * mean,
            worst,
            ms
        );
        rows.push(found.into_iter().map(|s| s.planar.region).collect());
    }
    let tiles: Vec<tiny_skia::Pixmap> =
        rows.iter().flatten().map(|region| sheet::render(region, TILE, TILE, 4.0, (40, 40, 48))).collect();
    let sheet = sheet::sheet(&tiles, ALTERNATIVES as usize, 4);
    sheet.save_png(&out).expect("write the sheet");
    println!("\nwrote {}", out.display());
}
