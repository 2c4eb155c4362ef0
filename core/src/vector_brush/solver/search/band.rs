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

    /// Where the alignments put piece `b` after piece `a` placed at
    /// `delta`, before the band holds it in: `δ·keep + τ` of the seam (a
    /// break starts back on the axis).
    #[inline]
    pub(super) fn aligned(&self, delta: f32, a: usize, b: usize) -> f32 {
        let seam = a * self.n() + b;
        delta * self.keep[seam] + self.tau[seam] as f32
    }

    /// Where piece `b` goes after piece `a` placed at `delta`, and what
    /// holding it in the band costs ([`Self::hold_in_band`]).
    #[inline]
    pub(super) fn offset_after(&self, delta: f32, a: usize, b: usize) -> Option<(f32, f64)> {
        self.hold_in_band(self.aligned(delta, a, b), b)
    }

    /// The offsets of a sequence the search found, replayed from its
    /// pieces as the search placed them (the first on the axis): the
    /// search keeps no offsets past the open lengths.
    pub(super) fn offsets_of(&self, pieces: &[usize]) -> Vec<f64> {
        let mut delta = 0.0f32;
        let mut offsets = Vec::with_capacity(pieces.len());
        offsets.push(0.0);
        for seam in pieces.windows(2) {
            // Always placed: the search placed every piece it kept.
            delta = self.offset_after(delta, seam[0], seam[1]).map_or(delta, |(placed, _)| placed);
            offsets.push(f64::from(delta));
        }
        offsets
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
