//! Fills a 60 × 40 mm rectangle with a built-in curve texture and draws it
//! next to its exemplar, with the time taken: the region fill's synthesis
//! as it stands (see `docs/region-fill.md`).
//!
//! `cargo run -p tracery-core --release --example fill_rect -- NAME|all [OUT.png]`
//! (`all`: every built-in, one row each, into `docs/fill-contact-sheet.png` by default).

use tiny_skia::{Color, Pixmap};
use tracery_core::region_fill::{BUILTIN_CURVES, CurvePath, Settings, builtin_curves, fill_rectangle};

#[path = "common/sheet.rs"]
mod sheet;

/// Pixels per millimetre.
const SCALE: f32 = 8.0;

/// Draws `paths` with their lower-left at `origin_mm` (y up) on `sheet`.
fn draw(sheet: &mut Pixmap, paths: &[CurvePath], origin_mm: (f32, f32), height_mm: f32) {
    let ink = sheet::paint(30, 30, 30);
    for path in paths {
        let at = |p: &tracery_core::DVec2| {
            ((origin_mm.0 + p.x as f32) * SCALE, (origin_mm.1 + height_mm - p.y as f32) * SCALE)
        };
        sheet::stroke_polyline(sheet, path.points_mm.iter().map(at), path.closed, &ink, 2.0);
    }
}

fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "crackle".into());
    let names: Vec<&str> = if name == "all" { BUILTIN_CURVES.to_vec() } else { vec![name.as_str()] };
    let default_out =
        if name == "all" { "docs/fill-contact-sheet.png".to_string() } else { format!("fill-{name}.png") };
    let out = std::env::args().nth(2).unwrap_or(default_out);
    let row_mm = 48.0;
    let mut sheet = Pixmap::new((110.0 * SCALE) as u32, (row_mm * names.len() as f32 * SCALE) as u32).expect("a sheet");
    sheet.fill(Color::WHITE);
    for (row, name) in names.iter().enumerate() {
        let exemplar = builtin_curves(name).expect("a built-in curve exemplar");
        let start = std::time::Instant::now();
        let paths = fill_rectangle(&exemplar, 60.0, 40.0, &Settings::default()).expect("a fill");
        eprintln!("{name}: {} paths in {:.2} s", paths.len(), start.elapsed().as_secs_f64());
        let top = row as f32 * row_mm + 4.0;
        draw(&mut sheet, &exemplar, (2.0, top), 40.0);
        draw(&mut sheet, &paths, (48.0, top), 40.0);
    }
    sheet.save_png(&out).expect("writing the picture");
    eprintln!("wrote {out}");
}
