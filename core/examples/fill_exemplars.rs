//! Draws the built-in curve exemplars with their finest sample graphs, as
//! the curve-texture paper's Figure 5 does: ends orange, samples along
//! paths green, junctions blue.
//!
//! `cargo run -p tracery-core --release --example fill_exemplars -- [OUT.png]`
//! (default `docs/fill-exemplars.png`).

use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Transform};
use tracery_core::region_fill::{BUILTIN_CURVES, SampleGraph, SampleKind, builtin_curves};

#[path = "common/sheet.rs"]
mod sheet;

/// Pixels per millimetre.
const SCALE: f32 = 9.0;
/// One tile's side, mm (the built-ins are drawn in about 40 mm), with a margin.
const TILE_MM: f32 = 46.0;

fn main() {
    let out = std::env::args().nth(1).unwrap_or_else(|| "docs/fill-exemplars.png".into());
    let side = (TILE_MM * SCALE) as u32;
    let mut sheet = Pixmap::new(side * 3, side * 2).expect("a sheet");
    sheet.fill(Color::WHITE);
    for (k, name) in BUILTIN_CURVES.iter().enumerate() {
        let paths = builtin_curves(name).expect("a built-in");
        let graph = SampleGraph::new(&paths, 1.0).expect("sampled");
        let (ox, oy) = ((k % 3) as f32 * TILE_MM + 3.0, (k / 3) as f32 * TILE_MM + 3.0);
        // y up in the exemplar, down in the picture.
        let at = |p: tracery_core::DVec2| ((ox + p.x as f32) * SCALE, (oy + TILE_MM - 6.0 - p.y as f32) * SCALE);
        let mut ink = Paint::default();
        ink.set_color_rgba8(60, 60, 60, 255);
        ink.anti_alias = true;
        for path in &paths {
            sheet::stroke_polyline(&mut sheet, path.points_mm.iter().map(|p| at(*p)), path.closed, &ink, 1.5);
        }
        for (s, sample) in graph.samples.iter().enumerate() {
            let (x, y) = at(sample.position_mm);
            let (r, g, b, radius) = match graph.kind(s) {
                SampleKind::End => (240, 140, 20, 4.0),
                SampleKind::Path => (40, 170, 80, 2.0),
                SampleKind::Junction => (40, 90, 230, 4.5),
            };
            let mut dot = Paint::default();
            dot.set_color_rgba8(r, g, b, 255);
            dot.anti_alias = true;
            if let Some(circle) = PathBuilder::from_circle(x, y, radius) {
                sheet.fill_path(&circle, &dot, FillRule::Winding, Transform::identity(), None);
            }
        }
        eprintln!("{name}: {} samples, {} edges", graph.samples.len(), graph.edges().len());
    }
    sheet.save_png(&out).expect("writing the sheet");
    eprintln!("wrote {out}");
}
