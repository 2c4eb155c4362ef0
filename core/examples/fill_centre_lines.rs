//! Draws what the fill learns from ornaments drawn as filled shapes: each
//! shape filled in grey, and over it the curves `CurveExemplar::curves`
//! reads at the default spacing (centre lines of bands in red, outlines
//! kept as they are in black).
//!
//! `cargo run -p tracery-core --release --example fill_centre_lines -- [NAME ...] [--size MM] [--out OUT.png]`
//! (defaults: a dozen ornaments of `../shared/corpus/ornaments`, 40 mm,
//! `docs/fill-centre-lines.png`).

use tracery_core::geom::Region;
use tracery_core::region_fill::{CurveExemplar, Settings};

#[path = "common/sheet.rs"]
mod sheet;

/// Ornaments shown when none is named: frets, rings, borders and florals.
const DEFAULT_NAMES: [&str; 12] = [
    "pgfhan1",
    "pgfhan10",
    "pgfhan20",
    "pgfhan33",
    "pgfhan45",
    "pgfhan51",
    "pgfhan72",
    "vectorian1",
    "vectorian20",
    "vectorian41",
    "vectorian77",
    "vectorian110",
];

/// One tile's side, pixels.
const TILE_PX: u32 = 360;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let flag = |name: &str| args.iter().position(|a| a == name).and_then(|k| args.get(k + 1).cloned());
    let size_mm: f64 = flag("--size").and_then(|s| s.parse().ok()).unwrap_or(40.0);
    let out = flag("--out").unwrap_or("docs/fill-centre-lines.png".into());
    let mut names: Vec<String> = Vec::new();
    let mut skip = false;
    for a in &args {
        if std::mem::take(&mut skip) {
            continue;
        }
        if a.starts_with("--") {
            skip = true;
        } else {
            names.push(a.clone());
        }
    }
    if names.is_empty() {
        names = DEFAULT_NAMES.iter().map(|s| s.to_string()).collect();
    }
    let delta_mm = Settings::default().delta_mm;
    let mut tiles = Vec::new();
    for name in &names {
        let file = format!("../shared/corpus/ornaments/{name}.svg");
        let exemplar = match CurveExemplar::load(&file) {
            Ok(e) => e,
            Err(e) => {
                eprintln!("{name}: {e}");
                continue;
            }
        };
        let points = || exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied());
        let Some(bounds) = tracery_core::geom::Rect::from_points(points()) else { continue };
        let exemplar = exemplar.scaled(size_mm / bounds.width().max(bounds.height()));
        let shapes = Region::new(exemplar.shapes.iter().map(|s| s.polygon.clone()).collect());
        let mut tile = sheet::render(&shapes, TILE_PX, TILE_PX, 8.0, (205, 205, 205));
        let Some(fit) = sheet::Fit::new(&shapes, TILE_PX, TILE_PX, 8.0) else { continue };
        let curves = exemplar.curves(delta_mm);
        let (mut lines, mut outlines) = (0, 0);
        for path in &curves.paths {
            // A kept outline is one of the exemplar's own paths.
            let kept = exemplar.paths.contains(path);
            let ink = if kept { sheet::paint(20, 20, 20) } else { sheet::paint(210, 30, 30) };
            if kept {
                outlines += 1
            } else {
                lines += 1
            }
            sheet::stroke_polyline(&mut tile, path.points_mm.iter().map(|p| fit.at(*p)), path.closed, &ink, 1.2);
        }
        eprintln!("{name}: {} shapes, {lines} centre lines, {outlines} outlines kept", exemplar.shapes.len());
        tiles.push(tile);
    }
    sheet::sheet(&tiles, 4, 6).save_png(&out).expect("writing the sheet");
    eprintln!("wrote {out}");
}
