//! The quality and speed of region fill for every built-in curve exemplar,
//! measured from the output alone (`tracery_core::quality`, which the
//! synthesis never reads) against the exemplar measured the same way.
//! Prints the Markdown tables in `docs/quality.md` and `docs/performance.md`,
//! and one of the discrete elements of the built-ins that have them.
//!
//! `cargo run -p tracery-core --release --example fill_quality [-- SEEDS]` (default 3 seeds).

use tracery_core::control::Control;
use tracery_core::geom::{Rect, Region};
use tracery_core::quality::{
    CURVATURE_BIN, CurveStatistics, ElementStatistics, ORIENTATION_BINS, coverage, curve_statistics_within,
    element_statistics, histogram_emd, histogram_emd_circular,
};
use tracery_core::region_fill::{BUILTIN_CURVES, CurveExemplar, Settings, make_product, parse_region};

fn main() {
    let seeds: u64 = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(3);
    let settings = Settings::default();
    let margin = settings.radius_mm();
    let region: Region = parse_region("rect:60x40").expect("a region");
    let bounds = region.bounds().expect("bounds");
    println!("Fills of 60 x 40 mm, seeds 1..={seeds}; exemplar -> mean of fills.\n");
    println!(
        "| exemplar | ends /100 mm | junctions /100 mm | crossings /100 mm | curvature EMD (1/mm) | orientation EMD (°) | coverage | time ms (median, max) | output length mm |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut element_rows = Vec::new();
    for name in BUILTIN_CURVES {
        let exemplar = CurveExemplar::builtin(name).expect("a built-in");
        // What the fill learns as curves: small filled shapes are elements.
        let learned = exemplar.curves(settings.delta_mm);
        let ex_paths: Vec<_> = learned.paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
        let ex_bounds = Rect::from_points(ex_paths.iter().flat_map(|p| p.0.iter().copied())).expect("points");
        let ex = curve_statistics_within(&ex_paths, &ex_bounds, margin);
        let ex_region = Region::rectangle(&ex_bounds);
        let ex_cover = coverage(&ex_paths, &ex_region, margin);
        let ex_shapes = learned.elements.polygons();
        let ex_elements = element_statistics(&ex_shapes, &ex_paths, &ex_bounds, 0.0);
        let mut runs: Vec<(CurveStatistics, f64, f64)> = Vec::new();
        let mut element_runs: Vec<ElementStatistics> = Vec::new();
        for seed in 1..=seeds {
            let mut s = settings.clone();
            s.seed = seed;
            let start = std::time::Instant::now();
            let product = make_product(&exemplar, &region, &s, &Control::default()).expect("a fill");
            let ms = start.elapsed().as_secs_f64() * 1e3;
            let paths: Vec<_> = product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
            runs.push((curve_statistics_within(&paths, &bounds, margin), coverage(&paths, &region, margin), ms));
            element_runs.push(element_statistics(&product.filled_mm.polygons, &paths, &bounds, margin));
        }
        let mean =
            |f: &dyn Fn(&(CurveStatistics, f64, f64)) -> f64| runs.iter().map(f).sum::<f64>() / runs.len() as f64;
        let mut times: Vec<f64> = runs.iter().map(|r| r.2).collect();
        times.sort_by(f64::total_cmp);
        println!(
            "| {name} | {:.1} → {:.1} | {:.1} → {:.1} | {:.2} → {:.2} | {:.3} | {:.1} | {:.2} → {:.2} | {:.0}, {:.0} | {:.0} |",
            ex.ends_per_100mm,
            mean(&|r| r.0.ends_per_100mm),
            ex.junctions_per_100mm,
            mean(&|r| r.0.junctions_per_100mm),
            ex.crossings_per_100mm,
            mean(&|r| r.0.crossings_per_100mm),
            mean(&|r| histogram_emd(&r.0.curvature, &ex.curvature, CURVATURE_BIN)),
            mean(&|r| histogram_emd_circular(&r.0.orientation, &ex.orientation, 180.0 / ORIENTATION_BINS as f64)),
            ex_cover,
            mean(&|r| r.1),
            times[times.len() / 2],
            times[times.len() - 1],
            mean(&|r| r.0.length_mm),
        );
        if ex_elements.count > 0 {
            let n = element_runs.len() as f64;
            element_rows.push(format!(
                "| {name} | {:.2} → {:.2} | {:.2} → {:.2} | {} → {} |",
                ex_elements.per_100mm2,
                element_runs.iter().map(|r| r.per_100mm2).sum::<f64>() / n,
                ex_elements.touching_share,
                element_runs.iter().map(|r| r.touching_share).sum::<f64>() / n,
                ex_elements.overlapping_pairs,
                element_runs.iter().map(|r| r.overlapping_pairs).sum::<usize>(),
            ));
        }
    }
    if !element_rows.is_empty() {
        println!("\nDiscrete elements (window less the radius; overlapping pairs summed over the seeds):\n");
        println!("| exemplar | elements /100 mm² | share touching a path | overlapping pairs |");
        println!("|---|---|---|---|");
        for row in element_rows {
            println!("{row}");
        }
    }
}
