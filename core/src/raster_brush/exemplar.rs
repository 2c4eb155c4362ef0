//! [`RasterExemplar`]: a picture with a transparent background, and which
//! of its pixels are opaque (the paper's α).

use std::path::Path;

use super::ExemplarError;
use crate::product::Texture;

/// Alpha (0 to 255) from which a pixel counts as opaque (the paper's α = 1).
pub const OPAQUE_FROM: u8 = 128;

/// The widest exemplar accepted, pixels: the search is quadratic in the
/// exemplar's size.
pub const MAX_WIDTH_PX: u32 = 1024;

/// The tallest exemplar accepted, pixels.
pub const MAX_HEIGHT_PX: u32 = 256;

/// The smallest side accepted, pixels.
pub const MIN_SIDE_PX: u32 = 8;

/// A bitmap exemplar.
///
/// ```
/// use tracery_core::raster_brush::RasterExemplar;
/// let mut rgba = vec![0u8; 4 * 16 * 16];
/// for y in 6..10 {
///     for x in 0..16 {
///         rgba[4 * (y * 16 + x)..][..4].copy_from_slice(&[200, 40, 40, 255]);
///     }
/// }
/// let e = RasterExemplar::from_rgba("bar", 16, 16, rgba).unwrap();
/// assert_eq!(e.opaque_rows(), (6, 9));
/// assert!(e.is_opaque(3, 7) && !e.is_opaque(3, 2) && !e.is_opaque(-1, 7));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RasterExemplar {
    /// Its name (a built-in's, or the file's).
    pub name: String,
    /// The picture.
    pub texture: Texture,
    opaque: Vec<bool>,
    opaque_rows: (u32, u32),
    column_extents: Vec<Option<(i32, i32)>>,
}

impl RasterExemplar {
    /// An exemplar from straight (not premultiplied) RGBA rows, top to bottom.
    pub fn from_rgba(name: &str, width: u32, height: u32, rgba: Vec<u8>) -> Result<RasterExemplar, ExemplarError> {
        if width > MAX_WIDTH_PX || height > MAX_HEIGHT_PX {
            return Err(ExemplarError::TooLarge { width, height, max_width: MAX_WIDTH_PX, max_height: MAX_HEIGHT_PX });
        }
        if width < MIN_SIDE_PX || height < MIN_SIDE_PX {
            return Err(ExemplarError::TooSmall { width, height, min: MIN_SIDE_PX });
        }
        let texture = Texture::new(width, height, rgba)
            .ok_or_else(|| ExemplarError::NotPng("the pixel data does not match the size".into()))?;
        let opaque: Vec<bool> = texture.rgba.chunks_exact(4).map(|p| p[3] >= OPAQUE_FROM).collect();
        if !opaque.iter().any(|&o| o) {
            return Err(ExemplarError::FullyTransparent);
        }
        if opaque.iter().all(|&o| o) {
            return Err(ExemplarError::FullyOpaque);
        }
        let row_has = |y: u32| opaque[(y * width) as usize..((y + 1) * width) as usize].iter().any(|&o| o);
        let top = (0..height).find(|&y| row_has(y)).unwrap_or(0);
        let bottom = (0..height).rev().find(|&y| row_has(y)).unwrap_or(0);
        let column_extents = (0..width)
            .map(|x| {
                let opaque_at = |y: &u32| opaque[(y * width + x) as usize];
                let first = (0..height).find(opaque_at)?;
                let last = (0..height).rev().find(opaque_at)?;
                Some((first as i32, last as i32))
            })
            .collect();
        Ok(RasterExemplar { name: name.to_string(), texture, opaque, opaque_rows: (top, bottom), column_extents })
    }

    /// An exemplar from a PNG file's bytes; it must have an alpha channel.
    pub fn from_png(name: &str, bytes: &[u8]) -> Result<RasterExemplar, ExemplarError> {
        let format = image::guess_format(bytes).map_err(|e| ExemplarError::NotPng(e.to_string()))?;
        if format != image::ImageFormat::Png {
            return Err(ExemplarError::NotPng(format!("it is {format:?}")));
        }
        // The size is read from the header and checked before decoding: a
        // valid picture too large to search is told so, not refused as
        // damaged when the decoder's memory limit stops it.
        let reader = || image::ImageReader::with_format(std::io::Cursor::new(bytes), image::ImageFormat::Png);
        let (width, height) = reader().into_dimensions().map_err(|e| ExemplarError::NotPng(e.to_string()))?;
        if width > MAX_WIDTH_PX || height > MAX_HEIGHT_PX {
            return Err(ExemplarError::TooLarge { width, height, max_width: MAX_WIDTH_PX, max_height: MAX_HEIGHT_PX });
        }
        let decoded = reader().decode().map_err(|e| ExemplarError::NotPng(e.to_string()))?;
        if !decoded.color().has_alpha() {
            return Err(ExemplarError::NoAlpha);
        }
        RasterExemplar::from_rgba(name, width, height, decoded.into_rgba8().into_raw())
    }

    /// An exemplar from a PNG file, named after the file.
    pub fn from_png_file(path: &Path) -> Result<RasterExemplar, ExemplarError> {
        let bytes = std::fs::read(path).map_err(|e| ExemplarError::NotPng(format!("could not read it: {e}")))?;
        let name = path.file_stem().map_or("imported".into(), |s| s.to_string_lossy().into_owned());
        RasterExemplar::from_png(&name, &bytes)
    }

    /// Width, pixels.
    pub fn width(&self) -> u32 {
        self.texture.width_px
    }

    /// Height, pixels.
    pub fn height(&self) -> u32 {
        self.texture.height_px
    }

    /// The first and last rows holding an opaque pixel.
    pub fn opaque_rows(&self) -> (u32, u32) {
        self.opaque_rows
    }

    /// Whether pixel (`x`, `y`) is opaque; pixels outside the picture are not.
    #[inline]
    pub fn is_opaque(&self, x: i64, y: i64) -> bool {
        x >= 0
            && y >= 0
            && x < i64::from(self.texture.width_px)
            && y < i64::from(self.texture.height_px)
            && self.opaque[(y * i64::from(self.texture.width_px) + x) as usize]
    }

    /// The pixel at (`x`, `y`), transparent outside.
    #[inline]
    pub fn pixel(&self, x: i64, y: i64) -> [u8; 4] {
        self.texture.pixel(x, y)
    }

    /// For each column, its first and last opaque rows (none if it has none).
    pub fn column_extents(&self) -> &[Option<(i32, i32)>] {
        &self.column_extents
    }

    /// The fraction of opaque pixels.
    pub fn coverage(&self) -> f64 {
        self.opaque.iter().filter(|&&o| o).count() as f64 / self.opaque.len() as f64
    }
}
