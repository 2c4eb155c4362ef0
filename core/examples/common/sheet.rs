//! Drawing regions into tiles and tiles into contact sheets, shared by the
//! examples that make pictures (sweep, gallery, printability, the fill
//! examples).
#![allow(dead_code)]

use tracery_core::DVec2;
use tracery_core::geom::Region;

/// Grey between the tiles of a sheet.
const SHEET_BACKGROUND: (u8, u8, u8) = (200, 200, 200);

/// Maps millimetres into a `width` × `height` tile, `y` up, the region
/// centred and fitted within a margin.
pub struct Fit {
    scale: f64,
    offset: DVec2,
}

impl Fit {
    /// The map that fits `region` into the tile, or `None` for an empty region.
    pub fn new(region: &Region, width: u32, height: u32, margin: f64) -> Option<Fit> {
        let b = region.bounds()?;
        let (w, h) = (f64::from(width), f64::from(height));
        let scale = ((w - 2.0 * margin) / b.width()).min((h - 2.0 * margin) / b.height());
        let offset = DVec2::new(
            0.5 * (w - scale * b.width()) - scale * b.min.x,
            0.5 * (h + scale * b.height()) + scale * b.min.y,
        );
        Some(Fit { scale, offset })
    }

    /// Where `p` (mm) lands in the tile, pixels.
    pub fn at(&self, p: DVec2) -> (f32, f32) {
        ((self.offset.x + self.scale * p.x) as f32, (self.offset.y - self.scale * p.y) as f32)
    }
}

/// An opaque anti-aliased paint.
pub fn paint(r: u8, g: u8, b: u8) -> tiny_skia::Paint<'static> {
    let mut paint = tiny_skia::Paint::default();
    paint.set_color_rgba8(r, g, b, 255);
    paint.anti_alias = true;
    paint
}

/// A polyline, already in pixels, stroked `width_px` wide (closed back to
/// its start when `closed`).
pub fn stroke_polyline(
    pixmap: &mut tiny_skia::Pixmap,
    points_px: impl IntoIterator<Item = (f32, f32)>,
    closed: bool,
    paint: &tiny_skia::Paint,
    width_px: f32,
) {
    let mut path = tiny_skia::PathBuilder::new();
    for (k, (x, y)) in points_px.into_iter().enumerate() {
        if k == 0 { path.move_to(x, y) } else { path.line_to(x, y) }
    }
    if closed {
        path.close();
    }
    if let Some(path) = path.finish() {
        let stroke = tiny_skia::Stroke { width: width_px, ..Default::default() };
        pixmap.stroke_path(&path, paint, &stroke, tiny_skia::Transform::identity(), None);
    }
}

/// Closed rings, already in pixels, filled together (even-odd).
pub fn fill_rings(pixmap: &mut tiny_skia::Pixmap, rings_px: &[Vec<(f32, f32)>], paint: &tiny_skia::Paint) {
    let mut path = tiny_skia::PathBuilder::new();
    for ring in rings_px {
        for (k, &(x, y)) in ring.iter().enumerate() {
            if k == 0 { path.move_to(x, y) } else { path.line_to(x, y) }
        }
        path.close();
    }
    if let Some(path) = path.finish() {
        pixmap.fill_path(&path, paint, tiny_skia::FillRule::EvenOdd, tiny_skia::Transform::identity(), None);
    }
}

/// `region` drawn filled (even-odd) in `rgb` on a white tile.
pub fn render(region: &Region, width: u32, height: u32, margin: f64, (r, g, b): (u8, u8, u8)) -> tiny_skia::Pixmap {
    let mut pixmap = tiny_skia::Pixmap::new(width, height).expect("tile size");
    pixmap.fill(tiny_skia::Color::WHITE);
    let Some(fit) = Fit::new(region, width, height, margin) else { return pixmap };
    let mut path = tiny_skia::PathBuilder::new();
    for ring in region.rings() {
        for (k, p) in ring.iter().enumerate() {
            let (x, y) = fit.at(*p);
            if k == 0 { path.move_to(x, y) } else { path.line_to(x, y) }
        }
        path.close();
    }
    if let Some(path) = path.finish() {
        let id = tiny_skia::Transform::identity();
        pixmap.fill_path(&path, &paint(r, g, b), tiny_skia::FillRule::EvenOdd, id, None);
    }
    pixmap
}

/// `tiles` (all of one size) laid out `columns` to a row, `gap` pixels apart.
pub fn sheet(tiles: &[tiny_skia::Pixmap], columns: usize, gap: u32) -> tiny_skia::Pixmap {
    let (tile_w, tile_h) = tiles.first().map_or((1, 1), |t| (t.width(), t.height()));
    let columns = columns.clamp(1, tiles.len().max(1));
    let rows = tiles.len().div_ceil(columns).max(1) as u32;
    let mut sheet =
        tiny_skia::Pixmap::new(columns as u32 * (tile_w + gap) + gap, rows * (tile_h + gap) + gap).expect("sheet size");
    let (r, g, b) = SHEET_BACKGROUND;
    sheet.fill(tiny_skia::Color::from_rgba8(r, g, b, 255));
    for (k, tile) in tiles.iter().enumerate() {
        let (col, row) = ((k % columns) as u32, (k / columns) as u32);
        sheet.draw_pixmap(
            (gap + col * (tile_w + gap)) as i32,
            (gap + row * (tile_h + gap)) as i32,
            tile.as_ref(),
            &tiny_skia::PixmapPaint::default(),
            tiny_skia::Transform::identity(),
            None,
        );
    }
    sheet
}
