//! The raster brush over the real ornaments: each SVG of the corpus drawn
//! into a bitmap exemplar (72 pixels tall, anti-aliased, transparent
//! around it, as a scanned or exported picture would be), then synthesized
//! along a wave (and, with `--loops`, a circle), with timings, topology and
//! failures. Pictures of every answered run go to `--out DIR`.
//!
//! ```text
//! cargo run -p tracery-core --release --example raster_sweep -- \
//!     [--corpus DIR] [--every K] [--loops] [--out DIR]
//! ```

#[path = "common/corpus.rs"]
mod corpus;
#[path = "common/sheet.rs"]
mod sheet;

use std::collections::BTreeMap;
use std::path::PathBuf;

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::export::{encode_png, render_product};
use tracery_core::geom::Region;
use tracery_core::product::Fact;
use tracery_core::raster_brush::{MAX_WIDTH_PX, RasterExemplar, Settings, make_product};
use tracery_core::vector_brush::{Exemplar, LoadOptions};

/// The exemplar's height in pixels when its width allows.
const HEIGHT_PX: u32 = 72;
/// Ink of the drawn ornaments.
const INK: (u8, u8, u8) = (120, 80, 40);

/// `exemplar`'s filled shapes as a picture with a transparent background.
fn picture(exemplar: &Exemplar) -> Option<RasterExemplar> {
    let aspect = exemplar.width() / exemplar.height();
    let height = (f64::from(HEIGHT_PX).min(f64::from(MAX_WIDTH_PX - 4) / aspect)).round().max(8.0) as u32;
    let width = ((f64::from(height) * aspect).round() as u32 + 4).min(MAX_WIDTH_PX);
    let mut pixmap = tiny_skia::Pixmap::new(width, height + 4)?;
    let fit = sheet::Fit::new(&exemplar.region, width, height + 4, 2.0)?;
    let mut path = tiny_skia::PathBuilder::new();
    for ring in exemplar.region.rings() {
        for (k, p) in ring.iter().enumerate() {
            let (x, y) = fit.at(*p);
            if k == 0 { path.move_to(x, y) } else { path.line_to(x, y) }
        }
        path.close();
    }
    let (r, g, b) = INK;
    pixmap.fill_path(
        &path.finish()?,
        &sheet::paint(r, g, b),
        tiny_skia::FillRule::EvenOdd,
        tiny_skia::Transform::identity(),
        None,
    );
    let rgba: Vec<u8> = pixmap
        .pixels()
        .iter()
        .flat_map(|p| {
            let c = p.demultiply();
            [c.red(), c.green(), c.blue(), c.alpha()]
        })
        .collect();
    RasterExemplar::from_rgba(&exemplar.name, pixmap.width(), pixmap.height(), rgba).ok()
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

fn main() {
    let mut folder = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus/ornaments"));
    let (mut every, mut loops, mut out) = (1usize, false, None::<PathBuf>);
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--corpus" => folder = args.next().expect("a folder").into(),
            "--every" => every = args.next().expect("a number").parse().expect("a number"),
            "--loops" => loops = true,
            "--out" => out = Some(args.next().expect("a folder").into()),
            other => panic!("unknown argument {other}"),
        }
    }
    if let Some(dir) = &out {
        std::fs::create_dir_all(dir).expect("output folder");
    }
    let files = corpus::svg_files(&folder);
    let curves: Vec<&str> = if loops { vec!["wave:160", "circle:25"] } else { vec!["wave:160"] };
    let mut not_pictures = 0;
    for curve in &curves {
        let along = Along::parse(curve).expect("curve");
        let (mut answered, mut runs) = (0, 0);
        let mut per_piece = Vec::new();
        let mut components: BTreeMap<usize, usize> = BTreeMap::new();
        let mut failures: BTreeMap<String, usize> = BTreeMap::new();
        let mut gains = Vec::new();
        for path in files.iter().step_by(every.max(1)) {
            let Ok(vector) = Exemplar::from_svg_file(path, &LoadOptions::default()) else {
                not_pictures += 1;
                continue;
            };
            let Some(exemplar) = picture(&vector) else {
                not_pictures += 1;
                continue;
            };
            runs += 1;
            match make_product(&exemplar, &along, &Settings::default(), &Region::default(), &Control::default()) {
                Ok(product) => {
                    answered += 1;
                    per_piece.push(product.timings.stage_ms("per_piece").unwrap_or(f64::NAN));
                    *components.entry(product.topology.components).or_default() += 1;
                    let fact = |n: &str| match product.facts.get(n) {
                        Some(Fact::Number(x)) => Some(*x),
                        _ => None,
                    };
                    if let (Some(before), Some(after)) = (fact("seam_mismatch_before"), fact("seam_mismatch_after"))
                        && before > 0.0
                    {
                        gains.push(1.0 - after / before);
                    }
                    if let Some(dir) = &out
                        && let Ok(image) = render_product(&product, 6.0)
                        && let Ok(png) = encode_png(&image)
                    {
                        let stem = path.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into_owned());
                        let name = format!("{stem}-{}.png", curve.replace(':', "-"));
                        std::fs::write(dir.join(name), png).expect("writing a picture");
                    }
                }
                Err(e) => {
                    let text = e.to_string();
                    let key: String = text.split(|c: char| c.is_ascii_digit()).next().unwrap_or(&text).to_string();
                    *failures.entry(key).or_default() += 1;
                    eprintln!("{}: {curve}: {text}", path.display());
                }
            }
        }
        per_piece.sort_by(f64::total_cmp);
        gains.sort_by(f64::total_cmp);
        println!("## {curve}");
        println!("- answered {answered} of {runs}");
        println!(
            "- ms per piece: median {:.1}, p95 {:.1}, max {:.1}",
            percentile(&per_piece, 0.5),
            percentile(&per_piece, 0.95),
            percentile(&per_piece, 1.0)
        );
        println!("- stitching lowers Σξ by a median {:.0}%", 100.0 * percentile(&gains, 0.5));
        println!("- components: {components:?}");
        for (why, n) in &failures {
            println!("- failed {n}: {why}…");
        }
    }
    println!("- not drawable as pictures: {not_pictures}");
}
