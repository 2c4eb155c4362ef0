//! Valid positions (the paper's section 1.3): where in the exemplar a piece
//! may lie. A position is valid when the piece slices the pattern
//! completely (its top and bottom edges cross no opaque pixel, and in every
//! column all of the pattern lies between them, so no piece is empty or
//! shows a sliver) and lays no opaque pixel on a pixel it must leave
//! transparent. Only valid positions are kept, compacted.

use glam::DVec2;

use crate::random::{mix, steps, unit};

use super::{RasterExemplar, RibbonPiece};

/// A position of a piece: its top-left corner in the exemplar, pixels.
pub type Position = (i32, i32);

/// Where a piece samples the exemplar, relative to its top-left corner.
#[derive(Clone, Debug, PartialEq)]
pub struct PieceSamples {
    /// The right edge's samples, top to bottom, one per row of the left
    /// edge (the paper's R̄); the left edge's are `(0, k)` (L̄).
    pub right: Vec<(i32, i32)>,
    /// Columns the piece spans, relative to its left edge.
    pub columns: (i32, i32),
    /// For each column the top and bottom edges cross (relative to the left
    /// edge): the rows of the top and bottom edges in it.
    pub spans: Vec<(i32, i32, i32)>,
    right_top: (i32, i32),
}

impl PieceSamples {
    /// The samples of `piece`, whose left edge is `column_px` pixels tall.
    pub fn new(piece: &RibbonPiece, column_px: usize) -> PieceSamples {
        let [rt, rb] = piece.right_px;
        let c = column_px as f64;
        let right: Vec<(i32, i32)> = (0..column_px)
            .map(|k| {
                let q = rt + (rb - rt) * ((k as f64 + 0.5) / c);
                (q.x.round() as i32, q.y.floor() as i32)
            })
            .collect();
        let mut spans: std::collections::BTreeMap<i32, (i32, i32)> = std::collections::BTreeMap::new();
        let bottom_left = DVec2::new(0.0, c);
        for (from, to, inward) in [(DVec2::ZERO, rt, 0.5), (bottom_left, rb, -0.5)] {
            let steps = (2.0 * (to - from).length()).ceil().max(1.0) as usize;
            for j in 0..steps {
                let p = from + (to - from) * (j as f64 / steps as f64);
                let pixel = (p.x.floor() as i32, (p.y + inward).floor() as i32);
                let span = spans.entry(pixel.0).or_insert((i32::MIN, i32::MAX));
                if inward > 0.0 {
                    span.0 = span.0.max(pixel.1);
                } else {
                    span.1 = span.1.min(pixel.1);
                }
            }
        }
        let xs = right.iter().map(|r| r.0).chain(spans.keys().copied()).chain([0]);
        let columns = (xs.clone().min().unwrap_or(0), xs.max().unwrap_or(0));
        // Columns crossed by one edge only (a steep tilt) bound nothing on the other side.
        let spans = spans.into_iter().map(|(dx, (top, bottom))| (dx, top, bottom)).collect();
        PieceSamples { right, columns, spans, right_top: (rt.x.round() as i32, rt.y.round() as i32) }
    }
}

impl PieceSamples {
    /// Where the next piece starts when it continues the exemplar: the
    /// right edge's top, to the nearest pixel.
    pub fn step(&self) -> (i32, i32) {
        self.right_top
    }
}

/// A piece's valid positions, and how many it had to choose from.
#[derive(Clone, Debug, PartialEq)]
pub struct Placements {
    /// The valid positions, row by row.
    pub positions: Vec<Position>,
    /// Positions tried (the paper's U for this piece).
    pub candidates: usize,
    /// A cost of its own for each position (variety), added to Ω; empty: none.
    pub bias: Vec<f64>,
}

/// Every valid position of a piece with `samples`, `column_px` tall, that
/// must leave `avoided_px` transparent. A piece that must leave pixels
/// transparent also gets one blank position, showing nothing.
pub fn valid_positions(
    exemplar: &RasterExemplar,
    samples: &PieceSamples,
    avoided_px: &[(i32, i32)],
    column_px: usize,
) -> Placements {
    let (w, c) = (exemplar.width() as i32, column_px as i32);
    let (top, bottom) = exemplar.opaque_rows();
    let (top, bottom) = (top as i32, bottom as i32);
    let (x0, x1) = (-samples.columns.0, w - 1 - samples.columns.1);
    let extents = exemplar.column_extents();
    let mut positions = Vec::new();
    let mut candidates = 0;
    for y in (top - c + 1)..=bottom {
        for x in x0..=x1 {
            candidates += 1;
            // The pattern crosses the piece from side to side: in every
            // column, all of it lies strictly between the top and bottom edges.
            let slices = samples.spans.iter().all(|&(dx, t, b)| {
                extents
                    .get((x + dx) as usize)
                    .copied()
                    .flatten()
                    .is_none_or(|(et, eb)| et > y.saturating_add(t) && eb < y.saturating_add(b))
            });
            // Every pixel of the top and bottom edges lies in a span's
            // column at or beyond its row, so `slices` also keeps them clear.
            let clear = |&(dx, dy): &(i32, i32)| !exemplar.is_opaque(i64::from(x + dx), i64::from(y + dy));
            if slices && avoided_px.iter().all(clear) {
                positions.push((x, y));
            }
        }
    }
    if !avoided_px.is_empty() {
        // A piece over a fold-over or an avoided area may also show nothing
        // (a position wholly above the picture): the pattern breaks there
        // rather than nowhere being possible; its seams cost what it breaks.
        positions.push((x0.max(0), top - 2 * c - 1));
    }
    Placements { positions, candidates, bias: Vec::new() }
}

/// Random costs in `[0, amount)` for each of `positions` of piece `piece`,
/// drawn from `seed`: the same arguments give the same costs.
///
/// ```
/// use tracery_core::raster_brush::variety_bias;
/// let a = variety_bias(&[(0, 0), (5, 1)], 3, 7, 100.0);
/// assert_eq!(a, variety_bias(&[(0, 0), (5, 1)], 3, 7, 100.0));
/// assert!(a.iter().all(|&c| (0.0..100.0).contains(&c)));
/// assert_ne!(a, variety_bias(&[(0, 0), (5, 1)], 3, 8, 100.0));
/// ```
pub fn variety_bias(positions: &[Position], piece: usize, seed: u64, amount: f64) -> Vec<f64> {
    // A well-mixed hash of piece, position and seed.
    let base = mix(seed.wrapping_add(steps(1)).wrapping_mul(piece as u64 + 1));
    positions
        .iter()
        .map(|&(x, y)| amount * unit(mix(base ^ (u64::from(x as u32) << 32 | u64::from(y as u32)))))
        .collect()
}
