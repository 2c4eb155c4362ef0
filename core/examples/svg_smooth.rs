//! How the SVG export's smooth outlines fare on real ornaments: every K-th
//! corpus ornament along a line and a closed circle, with the default
//! targets. For each run: whether the smoothed outlines passed the check
//! (or the chords were kept), how many segments became curves, the joins
//! that show as facets (turning 5° to 20°) among all joins before, and
//! after flattening the curves again at 5°, and the time the smoothing and
//! its check took.
//!
//! `cargo run -p tracery-core --release --example svg_smooth -- [EVERY] [CORPUS]`

use std::time::Instant;

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::{Along, Curve};
use tracery_core::geom::{OutlineSegment, SmoothOptions, smooth_region};
use tracery_core::vector_brush::{Exemplar, LoadOptions, Settings, synthesize};

#[path = "common/corpus.rs"]
mod corpus;

/// Joins of a closed ring that show as facets: where successive edges,
/// both at least 50 µm long, turn by more than 5° but less than 20°, which
/// no smoothing treats as a corner; and all joins, of edges at least 10 µm
/// long.
fn facets(ring: &[DVec2]) -> (usize, usize) {
    // Points closer than 10 µm to the last one kept are one point: what
    // turns over a shorter edge is rounding, and no one sees it.
    let mut kept: Vec<DVec2> = Vec::with_capacity(ring.len());
    for &p in ring {
        if kept.last().is_none_or(|q| q.distance(p) >= 0.01) {
            kept.push(p);
        }
    }
    while kept.len() > 1 && kept[0].distance(kept[kept.len() - 1]) < 0.01 {
        kept.pop();
    }
    let ring = kept;
    let n = ring.len();
    let turns = (0..n).filter_map(|k| {
        let a = ring[k] - ring[(k + n - 1) % n];
        let b = ring[(k + 1) % n] - ring[k];
        (a.length() >= 0.05 && b.length() >= 0.05).then(|| a.angle_to(b).abs().to_degrees())
    });
    (turns.filter(|t| (5.0..=20.0).contains(t)).count(), n)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let every: usize = args.next().and_then(|v| v.parse().ok()).unwrap_or(10);
    let folder = args.next().unwrap_or_else(|| "../shared/corpus/ornaments".into());
    let files = corpus::svg_files(&folder);
    let options = SmoothOptions::default();
    let (mut runs, mut kept, mut times) = (0, 0, Vec::new());
    let (mut before, mut after) = ((0, 0), (0, 0));
    println!("| ornament | curve | rings | curves / segments | facets before | facets after | ms |");
    println!("|---|---|---|---|---|---|---|");
    for file in files.iter().step_by(every.max(1)) {
        let Ok(exemplar) = Exemplar::from_svg_file(file, &LoadOptions::default()) else { continue };
        for spec in ["line:200", "circle:40"] {
            let Ok(Along::Curve(curve)) = Along::parse(spec) else { continue };
            let mut settings = Settings::default();
            settings.closed_pattern = Curve::is_closed(&curve);
            let Ok(synthesis) = synthesize(&exemplar, &curve, &settings, &Control::default()) else { continue };
            let region = &synthesis.planar.region;
            runs += 1;
            let start = Instant::now();
            let smooth = smooth_region(region, &options);
            let ms = start.elapsed().as_secs_f64() * 1e3;
            times.push(ms);
            let name = file.file_stem().unwrap_or_default().to_string_lossy();
            let sum = |(a, b): (usize, usize), (c, d): (usize, usize)| (a + c, b + d);
            let facets_before = region.rings().map(|r| facets(r)).fold((0, 0), sum);
            let Some(smooth) = smooth else {
                kept += 1;
                println!("| {name} | {spec} | {} | chords kept | | | {ms:.1} |", region.rings().count());
                continue;
            };
            let segments: Vec<&OutlineSegment> = smooth.iter().flatten().flat_map(|r| &r.segments).collect();
            let curves = segments.iter().filter(|s| matches!(s, OutlineSegment::Cubic(..))).count();
            let facets_after = smooth.iter().flatten().map(|r| facets(&r.flattened(&options))).fold((0, 0), sum);
            before = sum(before, facets_before);
            after = sum(after, facets_after);
            println!(
                "| {name} | {spec} | {} | {curves} / {} | {} of {} | {} of {} | {ms:.1} |",
                region.rings().count(),
                segments.len(),
                facets_before.0,
                facets_before.1,
                facets_after.0,
                facets_after.1
            );
        }
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    };
    println!(
        "\n{runs} runs; smoothed {}, chords kept {kept}; facets {} of {} joins before, {} of {} after; smoothing and check, median {:.1} ms, max {:.1} ms",
        runs - kept,
        before.0,
        before.1,
        after.0,
        after.1,
        median(&mut times),
        times.iter().copied().fold(0.0, f64::max)
    );
}
