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

fn render(region: &Region) -> tiny_skia::Pixmap {
    let mut pixmap = tiny_skia::Pixmap::new(TILE, TILE).expect("tile size");
    pixmap.fill(tiny_skia::Color::WHITE);
    let Some(b) = region.bounds() else { return pixmap };
    let scale = (f64::from(TILE) - 8.0) / b.width().max(b.height());
    let (ox, oy) = (
        0.5 * (f64::from(TILE) - scale * b.width()) - scale * b.min.x,
        0.5 * (f64::from(TILE) + scale * b.height()) + scale * b.min.y,
    );
    let mut path = tiny_skia::PathBuilder::new();
    for ring in region.rings() {
        for (k, p) in ring.iter().enumerate() {
            let (x, y) = ((ox + scale * p.x) as f32, (oy - scale * p.y) as f32);
            if k == 0 { path.move_to(x, y) } else { path.line_to(x, y) }
        }
        path.close();
    }
    if let Some(path) = path.finish() {
        let mut paint = tiny_skia::Paint::default();
        paint.set_color_rgba8(40, 40, 48, 255);
        paint.anti_alias = true;
        pixmap.fill_path(&path, &paint, tiny_skia::FillRule::EvenOdd, tiny_skia::Transform::identity(), None);
    }
    pixmap
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
    let gap = 4;
    let columns = ALTERNATIVES;
    let mut sheet = tiny_skia::Pixmap::new(columns * (TILE + gap) + gap, rows.len().max(1) as u32 * (TILE + gap) + gap)
        .expect("sheet size");
    sheet.fill(tiny_skia::Color::from_rgba8(200, 200, 200, 255));
    for (r, row) in rows.iter().enumerate() {
        for (c, region) in row.iter().enumerate() {
            sheet.draw_pixmap(
                (gap + c as u32 * (TILE + gap)) as i32,
                (gap + r as u32 * (TILE + gap)) as i32,
                render(region).as_ref(),
                &tiny_skia::PixmapPaint::default(),
                tiny_skia::Transform::identity(),
                None,
            );
        }
    }
    sheet.save_png(&out).expect("write the sheet");
    println!("\nwrote {}", out.display());
}
