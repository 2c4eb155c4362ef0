//! Printability of patterns, looked at: each exemplar along a curve, checked
//! against a nozzle, drawn with its thin features (red), narrow gaps (blue)
//! and weak bridges (orange), and again after thickening.
//!
//! ```sh
//! cargo run -p tracery-core --release --example printability -- \
//!     [--along circle:25] [--nozzle 0.4] [--out docs/gallery/printability.png] [EXEMPLAR.svg …]
//! ```
//! Without files it runs the built-in exemplars. Prints a table of findings.

#[path = "common/sheet.rs"]
mod sheet;

use std::path::PathBuf;

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::Region;
use tracery_core::print::{PrintSettings, Printability, finish};
use tracery_core::vector_brush::{BUILTIN_NAMES, Exemplar, LoadOptions, Settings, builtin, make_product};

use sheet::{Fit, paint};

const TILE: u32 = 420;

struct Tile {
    region: Region,
    found: Printability,
}

fn render(tile: &Tile) -> tiny_skia::Pixmap {
    const MARGIN: f64 = 8.0;
    let mut pixmap = sheet::render(&tile.region, TILE, TILE, MARGIN, (60, 60, 60));
    let fit = Fit::new(&tile.region, TILE, TILE, MARGIN).expect("a pattern");
    let id = tiny_skia::Transform::identity();
    let mut mark = |spans: &mut dyn Iterator<Item = [DVec2; 2]>, at: &mut dyn Iterator<Item = DVec2>, colour| {
        let mut path = tiny_skia::PathBuilder::new();
        for [a, b] in spans {
            let ((ax, ay), (bx, by)) = (fit.at(a), fit.at(b));
            path.move_to(ax, ay);
            path.line_to(bx, by);
        }
        for p in at {
            let (x, y) = fit.at(p);
            path.push_circle(x, y, 7.0);
        }
        if let Some(path) = path.finish() {
            let stroke = tiny_skia::Stroke { width: 2.0, ..Default::default() };
            pixmap.stroke_path(&path, &colour, &stroke, id, None);
        }
    };
    let f = &tile.found;
    mark(
        &mut f.thin_features.iter().flat_map(|x| x.spans_mm.iter().copied()),
        &mut f.thin_features.iter().map(|x| x.at_mm),
        paint(230, 30, 30),
    );
    mark(
        &mut f.narrow_gaps.iter().flat_map(|x| x.spans_mm.iter().copied()),
        &mut f.narrow_gaps.iter().map(|x| x.at_mm),
        paint(40, 110, 240),
    );
    mark(&mut f.weak_bridges.iter().map(|b| b.ends_mm), &mut std::iter::empty(), paint(250, 150, 0));
    pixmap
}

fn main() {
    let mut along = "circle:25".to_string();
    let mut nozzle = 0.4;
    let mut out = PathBuf::from("printability.png");
    let mut files = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--along" => along = args.next().expect("--along SPEC"),
            "--nozzle" => nozzle = args.next().expect("--nozzle MM").parse().expect("a number"),
            "--out" => out = PathBuf::from(args.next().expect("--out FILE")),
            _ => files.push(PathBuf::from(a)),
        }
    }
    let exemplars: Vec<Exemplar> = if files.is_empty() {
        BUILTIN_NAMES.iter().map(|n| builtin(n).expect("built-in")).collect()
    } else {
        files.iter().filter_map(|f| Exemplar::from_svg_file(f, &LoadOptions::default()).ok()).collect()
    };
    let along = Along::parse(&along).expect("a curve");
    let settings = Settings::default();
    let check = PrintSettings::default().with_nozzle_mm(nozzle);
    let mut rows: Vec<[Tile; 2]> = Vec::new();
    println!(
        "| exemplar | thin | thinnest mm | gaps | narrowest mm | weak bridges | check ms | thickened: thin | topology before → after |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for exemplar in &exemplars {
        let Ok(product) = make_product(exemplar, &along, &settings, &Control::default()) else {
            println!("| {} | no pattern | | | | | | | |", exemplar.name);
            continue;
        };
        let checked = finish(product.clone(), &check);
        let thick = finish(product, &check.with_thicken(true));
        let (a, b) = (checked.printability.clone().expect("checked"), thick.printability.clone().expect("checked"));
        let mm = |x: Option<f64>| x.map_or("–".to_string(), |w| format!("{w:.3}"));
        println!(
            "| {} | {} | {} | {} | {} | {} | {:.1} | {} | {}/{} → {}/{} |",
            exemplar.name,
            a.thin_features.len(),
            mm(a.thinnest_feature_mm),
            a.narrow_gaps.len(),
            mm(a.narrowest_gap_mm),
            a.weak_bridges.len(),
            checked.timings.stage_ms("print check").unwrap_or(0.0),
            b.thin_features.len(),
            checked.topology.components,
            checked.topology.holes,
            thick.topology.components,
            thick.topology.holes,
        );
        rows.push([Tile { region: checked.region_mm, found: a }, Tile { region: thick.region_mm, found: b }]);
    }
    let tiles: Vec<tiny_skia::Pixmap> = rows.iter().flatten().map(render).collect();
    let sheet = sheet::sheet(&tiles, 2, 6);
    sheet.save_png(&out).expect("write the sheet");
    println!("\nwrote {} (left: as synthesized; right: thickened)", out.display());
}
