//! Tracing a picture's opaque parts into polygons with holes.
//!
//! Marching squares (the `contour` crate) on the alpha channel, with the
//! crossing points interpolated, so that an anti-aliased edge gives a smooth
//! outline instead of a staircase. Two opaque pixels that touch only at a
//! corner are joined first: marching squares would otherwise decide such a
//! saddle by a fixed table, and the traced topology would depend on it.

use contour::ContourBuilder;
use glam::DVec2;

use super::{FillRule, Region, remove_specks, resolve_contours};

/// Alpha (0 to 1) at and above which a pixel is opaque.
pub const OPAQUE_ALPHA: f64 = 0.5;

/// Passes of corner joining; each can only add opaque pixels, and real
/// pictures settle in one or two.
const MAX_JOIN_PASSES: usize = 8;

/// Where a picture lies in the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelFrame {
    /// Width, pixels.
    pub width_px: usize,
    /// Height, pixels.
    pub height_px: usize,
    /// The picture's lower-left corner, mm.
    pub origin_mm: DVec2,
    /// Millimetres per pixel.
    pub mm_per_px: f64,
}

/// The alpha (rows top to bottom, one byte a pixel) as a grid of 0..1
/// values, rows bottom to top (so that outer rings keep their orientation),
/// with a transparent border of one pixel, so every outline closes.
fn alpha_grid(alpha: &[u8], frame: &PixelFrame) -> (Vec<f64>, usize, usize) {
    let (w, h) = (frame.width_px + 2, frame.height_px + 2);
    let mut values = vec![0.0; w * h];
    for y in 0..frame.height_px {
        for x in 0..frame.width_px {
            values[(frame.height_px - y) * w + x + 1] = f64::from(alpha[y * frame.width_px + x]) / 255.0;
        }
    }
    (values, w, h)
}

/// Makes every pair of opaque pixels that touch only at a corner share an
/// edge, by making the more opaque of the two others opaque.
pub fn join_corners(values: &mut [f64], w: usize, h: usize) {
    for _ in 0..MAX_JOIN_PASSES {
        let mut changed = false;
        for y in 0..h.saturating_sub(1) {
            for x in 0..w.saturating_sub(1) {
                let i = [y * w + x, y * w + x + 1, (y + 1) * w + x, (y + 1) * w + x + 1];
                let o = i.map(|k| values[k] >= OPAQUE_ALPHA);
                let lift = match o {
                    [true, false, false, true] => Some((i[1], i[2])),
                    [false, true, true, false] => Some((i[0], i[3])),
                    _ => None,
                };
                if let Some((a, b)) = lift {
                    let k = if values[a] >= values[b] { a } else { b };
                    values[k] = OPAQUE_ALPHA;
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
}

/// The opaque parts of a picture (`alpha`: one byte a pixel, rows top to
/// bottom; opaque from [`OPAQUE_ALPHA`]) as a clean region in millimetres,
/// placed where `frame` lays the picture in the plane.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{PixelFrame, count_topology, trace_opaque};
/// // A 6 x 6 opaque square with 2 x 2 transparent pixels in the middle: one part, one hole.
/// let mut alpha = vec![255u8; 36];
/// for i in [14, 15, 20, 21] {
///     alpha[i] = 0;
/// }
/// let frame = PixelFrame { width_px: 6, height_px: 6, origin_mm: DVec2::ZERO, mm_per_px: 0.1 };
/// let region = trace_opaque(&alpha, &frame);
/// let t = count_topology(&region);
/// assert_eq!((t.components, t.holes), (1, 1));
/// assert!(region.area() > 0.25 && region.area() < 0.36);
/// ```
pub fn trace_opaque(alpha: &[u8], frame: &PixelFrame) -> Region {
    if alpha.len() != frame.width_px * frame.height_px {
        return Region::default();
    }
    let (mut values, w, h) = alpha_grid(alpha, frame);
    join_corners(&mut values, w, h);
    // Decided on pixels, not on the traced rings' areas, so that what is
    // kept is exactly what a count of the pixels finds.
    remove_specks(&mut values, w, h, OPAQUE_ALPHA);
    let step = frame.mm_per_px;
    // Grid row and column 0 are the border: the picture starts one pixel in.
    let builder = ContourBuilder::new(w, h, true)
        .x_origin(frame.origin_mm.x - step)
        .x_step(step)
        .y_origin(frame.origin_mm.y - step)
        .y_step(step);
    let Ok(contours) = builder.contours(&values, &[OPAQUE_ALPHA]) else {
        return Region::default();
    };
    let rings: Vec<Vec<DVec2>> = contours
        .iter()
        .flat_map(|c| c.geometry().0.iter())
        .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
        .map(|ring| ring.0.iter().map(|c| DVec2::new(c.x, c.y)).collect::<Vec<_>>())
        .filter(|r| r.len() >= 4 && super::signed_area(r) != 0.0)
        .collect();
    resolve_contours(&rings, FillRule::EvenOdd)
}
