//! Region fill over the corpus of real ornaments: every SVG in a folder
//! read as a curve exemplar (its filled shapes' outlines, or the centre
//! lines of those drawn as thin bands), scaled so its
//! larger side is `--size` mm like the built-ins, and filled into a
//! 60 × 40 mm rectangle with a time limit. Prints one line per ornament and
//! a summary (outcomes, times, crossings, coverage and discrete elements
//! measured on the output alone by `tracery_core::quality`), and draws a
//! contact sheet with its index beside it.
//!
//! `cargo run -p tracery-core --release --example fill_corpus -- [DIR] [--size MM] [--limit-s S] [--sheet OUT.png]`
//! (defaults: `../shared/corpus/ornaments`, 40 mm, 20 s, `docs/fill-corpus.png`
//! and `docs/fill-corpus.txt`). The sheet in `docs/` was made with
//! `--limit-s 15` and reduced with ImageMagick
//! (`convert IN -resize 50% -colorspace Gray -colors 8 PNG8:OUT`).

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use tiny_skia::{Color, Paint, Pixmap};
use tracery_core::control::Control;
use tracery_core::geom::{Polygon, Rect, Region};
use tracery_core::quality::{coverage, curve_statistics_within, element_statistics};
use tracery_core::region_fill::{CurveExemplar, FillError, Settings, make_product, parse_region};

#[path = "common/corpus.rs"]
mod corpus;
#[path = "common/sheet.rs"]
mod sheet;

/// Pixels per millimetre on the sheet.
const SCALE: f32 = 3.0;
/// Tiles per row.
const COLUMNS: usize = 12;
/// The region, mm.
const REGION: (f64, f64) = (60.0, 40.0);

/// The discrete elements of a fill and of its exemplar.
#[derive(Default)]
struct ElementsSeen {
    /// The fill's element shapes, mm.
    shapes: Vec<Polygon>,
    /// Elements per 100 mm², the fill's over the exemplar's (`None` when the exemplar has none).
    density_ratio: Option<f64>,
    /// Overlapping pairs in the fill, and in the exemplar.
    overlapping: (usize, usize),
}

/// What became of one ornament.
enum Outcome {
    Filled {
        ms: f64,
        paths: Vec<(Vec<tracery_core::DVec2>, bool)>,
        crossings_ok: bool,
        /// `None` where the exemplar's own bounds have no inside (one
        /// straight line), so there is no coverage to compare with.
        cover_ratio: Option<f64>,
        elements: ElementsSeen,
    },
    Refused(String),
    TimedOut,
}

fn argument(args: &[String], flag: &str) -> Option<String> {
    args.iter().position(|a| a == flag).and_then(|k| args.get(k + 1).cloned())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dir = args.first().filter(|a| !a.starts_with("--")).cloned().unwrap_or("../shared/corpus/ornaments".into());
    let size_mm: f64 = argument(&args, "--size").and_then(|s| s.parse().ok()).unwrap_or(40.0);
    let limit = Duration::from_secs_f64(argument(&args, "--limit-s").and_then(|s| s.parse().ok()).unwrap_or(20.0));
    let sheet_path = argument(&args, "--sheet").unwrap_or("docs/fill-corpus.png".into());
    let files = corpus::svg_files(&dir);
    let region: Region = parse_region(&format!("rect:{}x{}", REGION.0, REGION.1)).expect("a region");
    let bounds = region.bounds().expect("bounds");
    let mut outcomes = Vec::new();
    for file in &files {
        let name = file.file_stem().unwrap().to_string_lossy().into_owned();
        let outcome = match CurveExemplar::load(&file.to_string_lossy()) {
            Err(e) => Outcome::Refused(e.to_string()),
            Ok(exemplar) => fill(&exemplar, &region, &bounds, size_mm, limit),
        };
        match &outcome {
            Outcome::Filled { ms, paths, crossings_ok, cover_ratio, elements } => eprintln!(
                "{name}: {} paths and {} elements in {ms:.0} ms, {}{}{}",
                paths.len(),
                elements.shapes.len(),
                cover_ratio.map_or("no coverage to compare (the exemplar is flat)".into(), |r| format!(
                    "coverage {r:.2} of the exemplar's"
                )),
                elements.density_ratio.map_or(String::new(), |r| format!(", element density {r:.2} of the exemplar's")),
                if *crossings_ok { "" } else { ", crosses where the exemplar does not" }
            ),
            Outcome::Refused(e) => eprintln!("{name}: refused: {e}"),
            Outcome::TimedOut => eprintln!("{name}: over {} s", limit.as_secs_f64()),
        }
        outcomes.push((name, outcome));
    }
    summarize(&outcomes, size_mm, limit);
    draw_sheet(&outcomes, &sheet_path);
}

/// Fills the region with `exemplar` scaled to `size_mm`, stopping at `limit`.
fn fill(exemplar: &CurveExemplar, region: &Region, bounds: &Rect, size_mm: f64, limit: Duration) -> Outcome {
    let Some(ex_bounds) = Rect::from_points(exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied())) else {
        return Outcome::Refused("no points".into());
    };
    let mut settings = Settings::default();
    settings.exemplar_scale = size_mm / ex_bounds.width().max(ex_bounds.height());
    let margin = settings.radius_mm();
    let stop = AtomicBool::new(false);
    let done = AtomicBool::new(false);
    let start = Instant::now();
    let result = std::thread::scope(|scope| {
        scope.spawn(|| {
            while !done.load(Ordering::Relaxed) && start.elapsed() < limit {
                std::thread::sleep(Duration::from_millis(20));
            }
            stop.store(true, Ordering::Relaxed);
        });
        let control = Control { cancel: Some(&stop), progress: None };
        let result = make_product(exemplar, region, &settings, &control);
        done.store(true, Ordering::Relaxed);
        result
    });
    let ms = start.elapsed().as_secs_f64() * 1e3;
    match result {
        Err(FillError::Cancelled(_)) => Outcome::TimedOut,
        Err(e) => Outcome::Refused(e.to_string()),
        Ok(product) => {
            // Compared with what the fill learns: filled bands as their centre lines.
            let scaled = exemplar.scaled(settings.exemplar_scale).curves(settings.delta_mm);
            let ex_paths: Vec<_> = scaled.paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
            let ex_box = Rect::from_points(ex_paths.iter().flat_map(|p| p.0.iter().copied())).expect("points");
            let ex = curve_statistics_within(&ex_paths, &ex_box, margin);
            let ex_cover = coverage(&ex_paths, &Region::rectangle(&ex_box), margin);
            let paths: Vec<_> = product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
            let out = curve_statistics_within(&paths, bounds, margin);
            let crossings_ok = ex.crossings_per_100mm > 0.0 || out.crossings_per_100mm == 0.0;
            let cover_ratio = (ex_cover > 0.0).then(|| coverage(&paths, region, margin) / ex_cover);
            let elements = elements_seen(&scaled, &product.filled_mm.polygons, &paths, bounds, margin);
            Outcome::Filled { ms, paths, crossings_ok, cover_ratio, elements }
        }
    }
}

/// The fill's elements measured against the exemplar's, each within its
/// own bounds less `margin` (the exemplar's whole when it is smaller).
fn elements_seen(
    learned: &CurveExemplar,
    shapes: &[Polygon],
    paths: &[(Vec<tracery_core::DVec2>, bool)],
    bounds: &Rect,
    margin: f64,
) -> ElementsSeen {
    let ex_shapes = learned.elements.polygons();
    let ex_paths: Vec<_> = learned.paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
    let out = element_statistics(shapes, paths, bounds, margin);
    let Some(ex_box) = Rect::from_points(
        ex_paths.iter().flat_map(|p| p.0.iter().copied()).chain(ex_shapes.iter().flat_map(|s| s.outer.iter().copied())),
    ) else {
        return ElementsSeen { shapes: shapes.to_vec(), ..Default::default() };
    };
    let ex = element_statistics(&ex_shapes, &ex_paths, &ex_box, 0.0);
    ElementsSeen {
        shapes: shapes.to_vec(),
        density_ratio: (ex.count > 0).then(|| out.per_100mm2 / ex.per_100mm2),
        overlapping: (out.overlapping_pairs, ex.overlapping_pairs),
    }
}

fn summarize(outcomes: &[(String, Outcome)], size_mm: f64, limit: Duration) {
    let filled: Vec<_> = outcomes
        .iter()
        .filter_map(|(n, o)| match o {
            Outcome::Filled { ms, crossings_ok, cover_ratio, .. } => Some((n, *ms, *crossings_ok, *cover_ratio)),
            _ => None,
        })
        .collect();
    let refused: Vec<_> = outcomes.iter().filter(|(_, o)| matches!(o, Outcome::Refused(_))).collect();
    let timed_out: Vec<_> = outcomes.iter().filter(|(_, o)| matches!(o, Outcome::TimedOut)).map(|(n, _)| n).collect();
    let mut times: Vec<f64> = filled.iter().map(|f| f.1).collect();
    times.sort_by(f64::total_cmp);
    let at = |q: f64| times.get(((times.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(0.0);
    let mut covers: Vec<f64> = filled.iter().filter_map(|f| f.3).collect();
    covers.sort_by(f64::total_cmp);
    let cover_at = |q: f64| covers.get(((covers.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(0.0);
    println!(
        "{} ornaments at {size_mm} mm in {} x {} mm, limit {} s",
        outcomes.len(),
        REGION.0,
        REGION.1,
        limit.as_secs_f64()
    );
    println!("filled: {}; refused: {}; over the limit: {}", filled.len(), refused.len(), timed_out.len());
    println!("time ms: median {:.0}, p95 {:.0}, max {:.0}", at(0.5), at(0.95), at(1.0));
    println!(
        "coverage against the exemplar's: p5 {:.2}, median {:.2}, p95 {:.2}",
        cover_at(0.05),
        cover_at(0.5),
        cover_at(0.95)
    );
    let mut densities: Vec<f64> = outcomes
        .iter()
        .filter_map(|(_, o)| match o {
            Outcome::Filled { elements, .. } => elements.density_ratio,
            _ => None,
        })
        .collect();
    densities.sort_by(f64::total_cmp);
    let density_at = |q: f64| densities.get(((densities.len() as f64 - 1.0) * q).round() as usize).copied();
    let overlapping: Vec<&str> = outcomes
        .iter()
        .filter_map(|(n, o)| match o {
            Outcome::Filled { elements, .. } if elements.overlapping.0 > 0 && elements.overlapping.1 == 0 => {
                Some(n.as_str())
            }
            _ => None,
        })
        .collect();
    println!(
        "with elements: {}; their density against the exemplar's: p5 {:.2}, median {:.2}, p95 {:.2}; overlapping where the exemplar's never do: {} {overlapping:?}",
        densities.len(),
        density_at(0.05).unwrap_or(0.0),
        density_at(0.5).unwrap_or(0.0),
        density_at(0.95).unwrap_or(0.0),
        overlapping.len()
    );
    let crossing: Vec<_> = filled.iter().filter(|f| !f.2).map(|f| f.0.as_str()).collect();
    println!("crossing where the exemplar never does: {} {:?}", crossing.len(), crossing);
    let mut reasons: std::collections::BTreeMap<String, usize> = Default::default();
    for (_, o) in &refused {
        if let Outcome::Refused(e) = o {
            *reasons.entry(e.split(':').next().unwrap_or(e).to_string()).or_default() += 1;
        }
    }
    for (reason, n) in reasons {
        println!("refused ({n}): {reason}");
    }
    println!("over the limit: {timed_out:?}");
}

/// Every fill on a sheet, `COLUMNS` to a row, with the index of names beside it.
fn draw_sheet(outcomes: &[(String, Outcome)], path: &str) {
    let (tile_w, tile_h) = ((REGION.0 as f32 + 4.0) * SCALE, (REGION.1 as f32 + 4.0) * SCALE);
    let rows = outcomes.len().div_ceil(COLUMNS);
    let mut sheet = Pixmap::new((tile_w * COLUMNS as f32) as u32, (tile_h * rows as f32) as u32).expect("a sheet");
    sheet.fill(Color::WHITE);
    let mut index = String::new();
    for (k, (name, outcome)) in outcomes.iter().enumerate() {
        let (row, column) = (k / COLUMNS, k % COLUMNS);
        index += &format!("row {} col {}: {name}\n", row + 1, column + 1);
        let (ox, oy) = (column as f32 * tile_w + 2.0 * SCALE, row as f32 * tile_h + 2.0 * SCALE);
        let mut ink = Paint { anti_alias: true, ..Default::default() };
        let at = |p: &tracery_core::DVec2| (ox + p.x as f32 * SCALE, oy + (REGION.1 - p.y) as f32 * SCALE);
        let paths = match outcome {
            Outcome::Filled { paths, elements, .. } => {
                ink.set_color_rgba8(20, 20, 20, 255);
                for shape in &elements.shapes {
                    let rings: Vec<Vec<(f32, f32)>> = shape.rings().map(|r| r.iter().map(at).collect()).collect();
                    sheet::fill_rings(&mut sheet, &rings, &ink);
                }
                paths.clone()
            }
            // A red cross where there is no fill.
            _ => {
                ink.set_color_rgba8(220, 40, 40, 255);
                let (w, h) = (REGION.0, REGION.1);
                vec![
                    (vec![tracery_core::DVec2::ZERO, tracery_core::DVec2::new(w, h)], false),
                    (vec![tracery_core::DVec2::new(0.0, h), tracery_core::DVec2::new(w, 0.0)], false),
                ]
            }
        };
        for (points, closed) in &paths {
            sheet::stroke_polyline(&mut sheet, points.iter().map(at), *closed, &ink, 1.0);
        }
    }
    sheet.save_png(path).expect("writing the sheet");
    std::fs::write(std::path::Path::new(path).with_extension("txt"), index).expect("writing the index");
    eprintln!("wrote {path}");
}
