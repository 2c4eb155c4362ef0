//! Autocomplete as the app does it, on every built-in curve exemplar: the
//! "drawn" strokes are the exemplar's own paths in a strip 12 mm high
//! across the bottom of a 40 × 40 mm window, and the predictions fill the
//! rest of the window around them. Drawn strokes are black, predictions
//! blue; the time of each prediction is printed.
//!
//! `cargo run -p tracery-core --release --example fill_autocomplete -- [OUT.png]`
//! (`docs/fill-autocomplete.png` by default).

use tiny_skia::{Color, Pixmap};
use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::geom::{Rect, Region, clip_polylines};
use tracery_core::region_fill::{BUILTIN_CURVES, CurveExemplar, CurvePath, Drawn, Settings, predict};

#[path = "common/sheet.rs"]
mod sheet;

/// Pixels per millimetre.
const SCALE: f32 = 8.0;
/// The window's side, mm.
const WINDOW_MM: f64 = 40.0;
/// The drawn strip's height, mm.
const STRIP_MM: f64 = 12.0;

/// Draws `paths` with the window's lower-left at `origin_px` (y up).
fn draw(sheet: &mut Pixmap, paths: &[CurvePath], origin_px: (f32, f32), rgb: (u8, u8, u8)) {
    let ink = sheet::paint(rgb.0, rgb.1, rgb.2);
    for path in paths {
        let at = |p: &DVec2| (origin_px.0 + p.x as f32 * SCALE, origin_px.1 + (WINDOW_MM - p.y) as f32 * SCALE);
        sheet::stroke_polyline(sheet, path.points_mm.iter().map(at), path.closed, &ink, 2.0);
    }
}

fn main() {
    let out = std::env::args().nth(1).unwrap_or_else(|| "docs/fill-autocomplete.png".into());
    let side = (WINDOW_MM as f32 + 4.0) * SCALE;
    let mut sheet = Pixmap::new((side * BUILTIN_CURVES.len() as f32) as u32, side as u32).expect("a sheet");
    sheet.fill(Color::WHITE);
    let window = Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::splat(WINDOW_MM)));
    for (k, name) in BUILTIN_CURVES.iter().enumerate() {
        let exemplar = CurveExemplar::builtin(name).expect("a built-in curve exemplar");
        let low =
            Rect::from_points(exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied())).expect("bounds").min;
        let moved: Vec<(Vec<DVec2>, bool)> =
            exemplar.paths.iter().map(|p| (p.points_mm.iter().map(|q| *q - low).collect(), p.closed)).collect();
        let strip = Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::new(WINDOW_MM, STRIP_MM)));
        let drawn: Vec<CurvePath> = clip_polylines(&moved, &strip)
            .into_iter()
            .map(|(points_mm, closed)| CurvePath { points_mm, closed })
            .filter(|p| p.length_mm() > 1.0)
            .collect();
        let start = std::time::Instant::now();
        let predicted =
            predict(&exemplar, &window, &Drawn::paths(drawn.clone()), &Settings::default(), &Control::default())
                .map(|p| p.paths);
        let ms = start.elapsed().as_secs_f64() * 1e3;
        let origin = (k as f32 * side + 2.0 * SCALE, 2.0 * SCALE);
        draw(&mut sheet, &drawn, origin, (20, 20, 20));
        match predicted {
            Ok(paths) => {
                eprintln!("{name}: {} drawn, {} predicted paths in {ms:.0} ms", drawn.len(), paths.len());
                draw(&mut sheet, &paths, origin, (40, 110, 230));
            }
            Err(e) => eprintln!("{name}: {e}"),
        }
    }
    sheet.save_png(&out).expect("writing the picture");
    eprintln!("wrote {out}");
}
