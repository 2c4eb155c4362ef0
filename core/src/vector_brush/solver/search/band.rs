//! Keeping the pieces in the band: how far each may be raised or lowered,
//! and what holding one back from its alignment costs.

use super::Problem;
use crate::vector_brush::MATCH_WEIGHT;
use crate::vector_brush::solver::BAND_MARGIN;

impl Problem<'_> {
    /// Where piece `b` goes when the alignments put it at `raw`: there, if it
    /// stays in the band; otherwise held at the band's edge, paying for the
    /// mismatch this leaves at the seam, up to [`MAX_HOLD`] of the band.
    /// Returns the offset and the extra seam cost, or `None` when the piece
    /// cannot be held in.
    #[inline]
    pub(super) fn hold_in_band(&self, raw: f32, b: usize) -> Option<(f32, f64)> {
        let allowance = self.allowance[b];
        if raw.abs() <= allowance {
            return Some((raw, 0.0));
        }
        let held = raw.abs() - allowance;
        if held > self.max_hold {
            return None;
        }
        Some((raw.clamp(-allowance, allowance), self.misalignment_cost(held)))
    }

    /// What a seam pays when its pieces sit `by` off their best alignment:
    /// moving every endpoint by `by` adds exactly `(by / H)²` to the pair's
    /// mean squared mismatch, `τ` being its least-squares alignment.
    pub(super) fn misalignment_cost(&self, by: f32) -> f64 {
        let relative = f64::from(by) / self.set.exemplar_height.max(f64::MIN_POSITIVE);
        MATCH_WEIGHT * relative * relative
    }
}

/// Room the band leaves a piece that reaches `extent` from its axis: how far
/// it may be raised or lowered before it pokes out of the band by more than
/// [`BAND_MARGIN`]. Never quite zero, so that a piece as tall as the band can
/// still sit on the axis despite rounding.
pub(super) fn band_allowance(band_height: f64, extent: f64) -> f64 {
    if !band_height.is_finite() {
        return f64::INFINITY;
    }
    let half = 0.5 * band_height;
    (half * (1.0 + BAND_MARGIN) - extent).max(0.02 * half)
}

/// Most a piece may be held back from its alignment at one seam to stay in
/// the band, as a fraction of the band: stitching bends the pieces to close
/// the mismatch, and beyond this the bend would show.
pub(super) const MAX_HOLD: f64 = 0.2;
