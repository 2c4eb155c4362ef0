//! What a person waits for in the app after each change to a curve: the
//! worker's whole job (`make_product`, then `print::finish`, the printer
//! check), timed stage by stage over the corpus ornaments.
//!
//! ```text
//! cargo run -p tracery-core --release --example app_wait -- \
//!     [--corpus DIR] [--every K] [--curves line:200,circle:40,...] [--targets 1/any,...]
//! ```
//!
//! Runs every K-th ornament (6 unless told) along the sweep's curves with
//! its targets, one run at a time, and prints the milliseconds of each stage
//! summed over the answered runs, with the median and p95 of a run. Runs the
//! solver refuses are counted apart: they end before the check.

#[path = "common/corpus.rs"]
mod corpus;

use std::path::PathBuf;
use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::print::{PrintSettings, finish};
use tracery_core::vector_brush::{Exemplar, LoadOptions, Settings, Target, make_product};

const CURVES: &str = "line:200,circle:40,wave:200,square:70,hexagon:40,star:45";
const TARGETS: &str = "1/any,any/any,1/0,2/any";

fn target(text: &str) -> Target {
    if text == "any" { Target::Any } else { Target::Exactly(text.parse().expect("a target is a number or 'any'")) }
}

fn main() {
    let mut corpus = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus/ornaments"));
    let (mut every, mut curves, mut targets) = (6usize, CURVES.to_string(), TARGETS.to_string());
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().unwrap_or_else(|| panic!("{flag} needs a value"));
        match flag.as_str() {
            "--corpus" => corpus = value.into(),
            "--every" => every = value.parse().expect("--every K"),
            "--curves" => curves = value,
            "--targets" => targets = value,
            _ => panic!("unknown flag {flag}"),
        }
    }
    let files: Vec<PathBuf> = corpus::svg_files(&corpus).into_iter().step_by(every.max(1)).collect();
    let print = PrintSettings::default();
    let mut stages: Vec<(String, f64)> = Vec::new();
    let (mut answered, mut refused) = (Vec::new(), 0usize);
    for file in &files {
        let Ok(exemplar) = Exemplar::from_svg_file(file, &LoadOptions::default()) else { continue };
        for spec in curves.split(',') {
            let along = Along::parse(spec).unwrap_or_else(|e| panic!("{spec}: {e}"));
            for pair in targets.split(',') {
                let (components, holes) = pair.split_once('/').expect("targets as C/H");
                let mut settings = Settings::default();
                settings.components = target(components);
                settings.holes = target(holes);
                settings.closed_pattern = matches!(&along, Along::Curve(curve) if curve.is_closed());
                let start = Instant::now();
                let Ok(product) = make_product(&exemplar, &along, &settings, &Control::default()) else {
                    refused += 1;
                    continue;
                };
                let product = finish(product, &print);
                answered.push(start.elapsed().as_secs_f64() * 1e3);
                for (name, ms) in product.timings.stages() {
                    match stages.iter_mut().find(|(n, _)| n == name) {
                        Some((_, total)) => *total += ms,
                        None => stages.push((name.to_string(), *ms)),
                    }
                }
            }
        }
    }
    answered.sort_by(f64::total_cmp);
    let at = |q: f64| answered.get(((answered.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(0.0);
    println!("{} ornaments, {} answered runs, {} refused", files.len(), answered.len(), refused);
    println!("per answered run: p50 {:.1} ms, p95 {:.1} ms, max {:.1} ms", at(0.5), at(0.95), at(1.0));
    println!("stage totals over the answered runs:");
    for (name, ms) in &stages {
        println!("  {name:<12} {:>9.0} ms", ms);
    }
}
