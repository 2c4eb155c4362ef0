//! Rendering a product to pixels: textured triangles (the raster brush) or
//! filled regions (every other mode), and PNG encoding.
//!
//! Triangles are rasterized with the top-left rule on integer coordinates
//! (8 bits below the pixel), so two triangles that share an edge cover every
//! pixel centre along it exactly once: pieces of a pattern meet without a
//! crack, which the traced outline would otherwise turn into a cut.

use glam::DVec2;

use crate::geom::Rect;
use crate::product::{Product, RasterImage, Texture, TexturedMesh};

/// Sub-pixel bits of the rasterizer's fixed-point coordinates.
const SUBPIXEL_BITS: u32 = 8;

/// The most pixels a render may have (about 64 MB of RGBA floats).
pub const MAX_RENDER_PX: usize = 16_000_000;

/// Colour of filled regions in a render of a product without texture.
const FILL_RGBA: [f32; 4] = [0.12, 0.12, 0.14, 1.0];

/// Why a render failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RenderError {
    /// Nothing to draw.
    #[error("nothing to render: the result is empty")]
    Empty,
    /// The picture would be too large.
    #[error(
        "a render of {} x {} pixels is too large; lower the resolution (at most {max} pixels)",
        crate::setting::count(*width_px),
        crate::setting::count(*height_px)
    )]
    TooLarge {
        /// Width asked for.
        width_px: usize,
        /// Height asked for.
        height_px: usize,
        /// The limit, in pixels.
        max: usize,
    },
    /// The resolution is not a positive number.
    #[error("the resolution must be a positive number of pixels per millimetre, not {0}")]
    BadResolution(f64),
}

/// A premultiplied RGBA canvas in pixel space (`x` right, `y` down) over `bounds_mm`.
struct Canvas {
    width: usize,
    height: usize,
    px_per_mm: f64,
    bounds_mm: Rect,
    premultiplied: Vec<[f32; 4]>,
}

impl Canvas {
    fn new(bounds_mm: Rect, px_per_mm: f64) -> Result<Canvas, RenderError> {
        if !(px_per_mm.is_finite() && px_per_mm > 0.0) {
            return Err(RenderError::BadResolution(px_per_mm));
        }
        let width = (bounds_mm.width() * px_per_mm).ceil().max(1.0);
        let height = (bounds_mm.height() * px_per_mm).ceil().max(1.0);
        if width * height > MAX_RENDER_PX as f64 {
            return Err(RenderError::TooLarge {
                width_px: width as usize,
                height_px: height as usize,
                max: MAX_RENDER_PX,
            });
        }
        let (width, height) = (width as usize, height as usize);
        Ok(Canvas { width, height, px_per_mm, bounds_mm, premultiplied: vec![[0.0; 4]; width * height] })
    }

    /// `p` in fixed-point pixel coordinates.
    fn fixed(&self, p: DVec2) -> (i64, i64) {
        let scale = self.px_per_mm * f64::from(1u32 << SUBPIXEL_BITS);
        (((p.x - self.bounds_mm.min.x) * scale).round() as i64, ((self.bounds_mm.max.y - p.y) * scale).round() as i64)
    }

    /// Calls `shade(pixel, barycentric)` for every pixel whose centre the
    /// triangle covers (top-left rule).
    fn triangle(&mut self, corners_mm: [DVec2; 3], mut shade: impl FnMut([f64; 3]) -> [f32; 4]) {
        let mut v = corners_mm.map(|p| self.fixed(p));
        let area = edge(v[0], v[1], v[2]);
        if area == 0 {
            return;
        }
        let mut order = [0usize, 1, 2];
        if area < 0 {
            v.swap(1, 2);
            order.swap(1, 2);
        }
        let area = area.abs() as f64;
        let one = 1i64 << SUBPIXEL_BITS;
        let half = one / 2;
        let x0 = (v.iter().map(|p| p.0).min().unwrap_or(0) - half).div_euclid(one).max(0);
        let x1 = ((v.iter().map(|p| p.0).max().unwrap_or(0) - half).div_euclid(one) + 1).min(self.width as i64);
        let y0 = (v.iter().map(|p| p.1).min().unwrap_or(0) - half).div_euclid(one).max(0);
        let y1 = ((v.iter().map(|p| p.1).max().unwrap_or(0) - half).div_euclid(one) + 1).min(self.height as i64);
        for y in y0..y1 {
            for x in x0..x1 {
                let p = (x * one + half, y * one + half);
                let w = [edge(v[1], v[2], p), edge(v[2], v[0], p), edge(v[0], v[1], p)];
                let covered = (0..3).all(|k| {
                    let (a, b) = (v[(k + 1) % 3], v[(k + 2) % 3]);
                    w[k] > 0 || (w[k] == 0 && is_top_left(a, b))
                });
                if !covered {
                    continue;
                }
                let mut bary = [0.0; 3];
                for k in 0..3 {
                    bary[order[k]] = w[k] as f64 / area;
                }
                let src = shade(bary);
                let dst = &mut self.premultiplied[y as usize * self.width + x as usize];
                // Source over destination, premultiplied.
                for c in 0..4 {
                    dst[c] = src[c] + dst[c] * (1.0 - src[3]);
                }
            }
        }
    }

    fn into_image(self) -> RasterImage {
        let mut rgba = Vec::with_capacity(4 * self.premultiplied.len());
        for p in &self.premultiplied {
            let a = p[3].clamp(0.0, 1.0);
            let un = |c: f32| if a > 0.0 { (c / a * 255.0).round().clamp(0.0, 255.0) as u8 } else { 0 };
            rgba.extend_from_slice(&[un(p[0]), un(p[1]), un(p[2]), (a * 255.0).round() as u8]);
        }
        RasterImage {
            width_px: self.width as u32,
            height_px: self.height as u32,
            rgba,
            origin_mm: DVec2::new(self.bounds_mm.min.x, self.bounds_mm.max.y - self.height as f64 / self.px_per_mm),
            mm_per_px: 1.0 / self.px_per_mm,
        }
    }
}

/// Twice the signed area of (a, b, p), positive when p is to the right of
/// a→b in `y`-down pixel space.
fn edge(a: (i64, i64), b: (i64, i64), p: (i64, i64)) -> i64 {
    (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0)
}

/// The top-left rule for a triangle wound clockwise on screen (`y` down).
fn is_top_left(a: (i64, i64), b: (i64, i64)) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    (dy == 0 && dx > 0) || dy < 0
}

/// The texture's colour at `uv` (pixels), bilinear and premultiplied.
fn sample(texture: &Texture, uv: DVec2) -> [f32; 4] {
    let p = uv - DVec2::splat(0.5);
    let (x, y) = (p.x.floor(), p.y.floor());
    let (fx, fy) = ((p.x - x) as f32, (p.y - y) as f32);
    let mut out = [0.0f32; 4];
    for (dx, dy, w) in
        [(0, 0, (1.0 - fx) * (1.0 - fy)), (1, 0, fx * (1.0 - fy)), (0, 1, (1.0 - fx) * fy), (1, 1, fx * fy)]
    {
        let c = texture.pixel(x as i64 + dx, y as i64 + dy);
        let a = f32::from(c[3]) / 255.0;
        for k in 0..3 {
            out[k] += w * a * f32::from(c[k]) / 255.0;
        }
        out[3] += w * a;
    }
    out
}

/// Renders textured triangles at `px_per_mm` over their own bounds, with a
/// transparent background.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::export::render_textured;
/// use tracery_core::product::{TexturedMesh, Texture};
/// let red = Texture::new(2, 2, [255, 0, 0, 255].repeat(4)).unwrap();
/// let square = TexturedMesh {
///     texture: Some(red),
///     positions_mm: vec![DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(1.0, 1.0), DVec2::new(0.0, 1.0)],
///     uvs_px: vec![DVec2::new(0.0, 2.0), DVec2::new(2.0, 2.0), DVec2::new(2.0, 0.0), DVec2::ZERO],
///     triangles: vec![[0, 1, 2], [0, 2, 3]],
/// };
/// let image = render_textured(&square, 10.0).unwrap();
/// assert_eq!((image.width_px, image.height_px), (10, 10));
/// // Every pixel covered, red, none missed along the diagonal (the border
/// // pixels blend with the transparent outside of the texture).
/// assert!(image.rgba.chunks(4).all(|p| p[0] >= 250 && p[1] == 0 && p[3] >= 64));
/// ```
pub fn render_textured(mesh: &TexturedMesh, px_per_mm: f64) -> Result<RasterImage, RenderError> {
    let texture = mesh.texture.as_ref().ok_or(RenderError::Empty)?;
    let bounds = Rect::from_points(mesh.positions_mm.iter().copied()).ok_or(RenderError::Empty)?;
    let mut canvas = Canvas::new(bounds, px_per_mm)?;
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| i as usize);
        let uv = [mesh.uvs_px[a], mesh.uvs_px[b], mesh.uvs_px[c]];
        canvas.triangle([mesh.positions_mm[a], mesh.positions_mm[b], mesh.positions_mm[c]], |w| {
            sample(texture, uv[0] * w[0] + uv[1] * w[1] + uv[2] * w[2])
        });
    }
    Ok(canvas.into_image())
}

/// Renders a product at `px_per_mm`: its textured triangles where it has
/// them, otherwise its filled region in a dark ink.
pub fn render_product(product: &Product, px_per_mm: f64) -> Result<RasterImage, RenderError> {
    if let Some(mesh) = product.textured_mm.as_ref().filter(|m| !m.triangles.is_empty()) {
        return render_textured(mesh, px_per_mm);
    }
    let bounds = Rect::from_points(product.fill_mm.iter().flatten().copied()).ok_or(RenderError::Empty)?;
    let mut canvas = Canvas::new(bounds, px_per_mm)?;
    for t in &product.fill_mm {
        canvas.triangle(*t, |_| FILL_RGBA.map(|c| c * FILL_RGBA[3]));
    }
    Ok(canvas.into_image())
}

/// Encodes a picture as an 8-bit RGBA PNG.
pub fn encode_png(image: &RasterImage) -> Result<Vec<u8>, image::ImageError> {
    let mut out = Vec::new();
    let encoder = image::codecs::png::PngEncoder::new(&mut out);
    image::ImageEncoder::write_image(
        encoder,
        &image.rgba,
        image.width_px,
        image.height_px,
        image::ExtendedColorType::Rgba8,
    )?;
    Ok(out)
}
