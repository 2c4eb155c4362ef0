//! The ribbon: the band around the curve cut every δ into quadrilateral
//! pieces, each with its own frame, in which the exemplar is laid unrotated
//! and unscaled (the paper's section 1.2), and the pixels of each piece that
//! must stay transparent: where the ribbon folds over itself or overlaps
//! another part of it, and where the person painted an avoided area (3.1).

use glam::DVec2;

use super::{RasterError, RasterExemplar, Settings};
use crate::curve::Curve;
use crate::geom::{PixelFrame, Rect, Region, trace_opaque};

/// Avoidance cells per exemplar pixel side: two, so that every exemplar
/// pixel a piece lays over an avoided area has a cell centre in it, at any
/// rotation.
const CELLS_PER_PX: f64 = 2.0;

/// The most avoidance cells a ribbon may need.
pub const MAX_CELLS: usize = 48_000_000;

/// A piece of the ribbon.
#[derive(Clone, Debug, PartialEq)]
pub struct RibbonPiece {
    /// Corners in the plane, mm: top left, top right, bottom right, bottom left.
    pub corners_mm: [DVec2; 4],
    /// Unit vector along the piece's left edge's frame (the exemplar's `x`), in the plane.
    pub along: DVec2,
    /// Unit vector down its left edge (the exemplar's `y`), in the plane.
    pub down: DVec2,
    /// The right edge's top and bottom, in the piece's exemplar frame
    /// (pixels; the left edge runs from (0, 0) to (0, C)).
    pub right_px: [DVec2; 2],
    /// Where the piece starts along the curve, mm.
    pub start_mm: f64,
    /// Pixels of the piece's frame that must stay transparent, sorted.
    pub avoided_px: Vec<(i32, i32)>,
}

impl RibbonPiece {
    /// A point of the plane in the piece's exemplar frame, pixels.
    pub fn frame_from_plane(&self, p_mm: DVec2, px_per_mm: f64) -> DVec2 {
        let d = p_mm - self.corners_mm[0];
        DVec2::new(d.dot(self.along), d.dot(self.down)) * px_per_mm
    }

    /// A point of the piece's exemplar frame (pixels) in the plane, mm.
    pub fn plane_from_frame(&self, p_px: DVec2, px_per_mm: f64) -> DVec2 {
        self.corners_mm[0] + (self.along * p_px.x + self.down * p_px.y) / px_per_mm
    }
}

/// The ribbon along a curve.
#[derive(Clone, Debug, PartialEq)]
pub struct Ribbon {
    /// The pieces, from the curve's start.
    pub pieces: Vec<RibbonPiece>,
    /// Exemplar pixels per millimetre.
    pub px_per_mm: f64,
    /// Pixels down a piece's left edge (the paper's C).
    pub column_px: usize,
    /// The band's width as laid, mm (`column_px / px_per_mm`).
    pub band_mm: f64,
    /// Whether the curve is a loop (the last piece meets the first).
    pub closed: bool,
    /// The areas left empty (fold-overs, overlaps and avoided areas), mm.
    pub avoided_mm: Region,
}

/// Winding number of a quadrilateral around `p`.
fn winding(quad: &[DVec2; 4], p: DVec2) -> i32 {
    let mut w = 0;
    for k in 0..4 {
        let (a, b) = (quad[k], quad[(k + 1) % 4]);
        let side = (b - a).perp_dot(p - a);
        if a.y <= p.y {
            if b.y > p.y && side > 0.0 {
                w += 1;
            }
        } else if b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

/// The grid of avoidance cells over the ribbon.
struct Cells {
    bounds: Rect,
    size_mm: f64,
    columns: usize,
    rows: usize,
}

impl Cells {
    fn centre(&self, i: usize, j: usize) -> DVec2 {
        self.bounds.min + DVec2::new(i as f64 + 0.5, j as f64 + 0.5) * self.size_mm
    }

    /// The cells whose centres may lie in `quad`, as column and row ranges.
    fn covering(&self, quad: &[DVec2; 4]) -> (std::ops::Range<usize>, std::ops::Range<usize>) {
        let r = Rect::from_points(quad.iter().copied()).unwrap_or(self.bounds);
        let lo = ((r.min - self.bounds.min) / self.size_mm).floor().max(DVec2::ZERO);
        let hi = ((r.max - self.bounds.min) / self.size_mm).ceil();
        (lo.x as usize..(hi.x as usize + 1).min(self.columns), lo.y as usize..(hi.y as usize + 1).min(self.rows))
    }
}

/// Cuts the band along `curve` into pieces for `exemplar` and finds what
/// each must leave transparent (`avoid_mm`: areas the person painted).
pub fn lay_ribbon(
    curve: &Curve,
    exemplar: &RasterExemplar,
    settings: &Settings,
    avoid_mm: &Region,
) -> Result<Ribbon, RasterError> {
    let (top, bottom) = exemplar.opaque_rows();
    let pattern_px = f64::from(bottom - top + 1);
    let px_per_mm = pattern_px / (settings.scale * settings.band_mm);
    let column_px = (pattern_px / settings.scale).ceil() as usize;
    let band_mm = column_px as f64 / px_per_mm;
    let length = curve.length();
    let closed = curve.is_closed();
    if length < settings.step_mm {
        return Err(RasterError::CurveTooShort { length_mm: length, step_mm: settings.step_mm });
    }
    let count = if closed { (length / settings.step_mm).round() } else { (length / settings.step_mm - 1e-9).ceil() };
    let count = (count as usize).max(1);
    let step = length / count as f64;
    let half = 0.5 * band_mm;
    let edge_points: Vec<(DVec2, DVec2)> = (0..=count)
        .map(|i| if closed && i == count { 0.0 } else { step * i as f64 })
        .map(|u| (curve.map(u, half), curve.map(u, -half)))
        .collect();
    let mut pieces: Vec<RibbonPiece> = (0..count)
        .map(|i| {
            let (tl, bl) = edge_points[i];
            let (tr, br) = edge_points[i + 1];
            let down = (bl - tl).normalize_or(DVec2::NEG_Y);
            let along = DVec2::new(-down.y, down.x);
            let mut piece = RibbonPiece {
                corners_mm: [tl, tr, br, bl],
                along,
                down,
                right_px: [DVec2::ZERO; 2],
                start_mm: step * i as f64,
                avoided_px: Vec::new(),
            };
            piece.right_px = [piece.frame_from_plane(tr, px_per_mm), piece.frame_from_plane(br, px_per_mm)];
            piece
        })
        .collect();

    // Overdraw: every cell counts the pieces covering it.
    let bounds =
        Rect::from_points(pieces.iter().flat_map(|p| p.corners_mm)).unwrap_or(Rect::new(DVec2::ZERO, DVec2::ONE));
    let size_mm = 1.0 / (CELLS_PER_PX * px_per_mm);
    let (columns, rows) =
        ((bounds.width() / size_mm).ceil() as usize + 1, (bounds.height() / size_mm).ceil() as usize + 1);
    if columns.saturating_mul(rows) > MAX_CELLS {
        return Err(RasterError::TooLarge { cells: columns.saturating_mul(rows), max: MAX_CELLS });
    }
    let cells = Cells { bounds, size_mm, columns, rows };
    let mut cover = vec![0u8; columns * rows];
    for piece in &pieces {
        let (xs, ys) = cells.covering(&piece.corners_mm);
        for j in ys {
            for i in xs.clone() {
                let w = winding(&piece.corners_mm, cells.centre(i, j)).unsigned_abs();
                let c = &mut cover[j * columns + i];
                *c = c.saturating_add(w.min(255) as u8);
            }
        }
    }
    let avoid_bounds = avoid_mm.bounds();
    let mut avoided = vec![0u8; columns * rows];
    for piece in &mut pieces {
        let (xs, ys) = cells.covering(&piece.corners_mm);
        for j in ys {
            for i in xs.clone() {
                let c = cells.centre(i, j);
                if winding(&piece.corners_mm, c) == 0 {
                    continue;
                }
                let painted = avoid_bounds.is_some_and(|b| {
                    c.x >= b.min.x && c.x <= b.max.x && c.y >= b.min.y && c.y <= b.max.y && avoid_mm.contains(c)
                });
                if cover[j * columns + i] >= 2 || painted {
                    let f = piece.frame_from_plane(c, px_per_mm).floor();
                    piece.avoided_px.push((f.x as i32, f.y as i32));
                    avoided[j * columns + i] = 255;
                }
            }
        }
        piece.avoided_px.sort_unstable();
        piece.avoided_px.dedup();
    }
    let avoided_mm = if avoided.iter().any(|&a| a > 0) {
        // Rows of the trace run top to bottom.
        let flipped: Vec<u8> =
            (0..rows).rev().flat_map(|j| avoided[j * columns..(j + 1) * columns].iter().copied()).collect();
        let frame = PixelFrame { width_px: columns, height_px: rows, origin_mm: bounds.min, mm_per_px: size_mm };
        trace_opaque(&flipped, &frame)
    } else {
        Region::default()
    };
    Ok(Ribbon { pieces, px_per_mm, column_px, band_mm, closed, avoided_mm })
}
