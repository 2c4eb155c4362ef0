//! Stitching (the paper's section 3.2): at every seam, a dynamic program
//! remaps the pixels along the previous piece's right edge onto the next
//! piece's left edge, and the remapping fades into the previous piece
//! towards its left edge (applied to texture coordinates in
//! [`super::textured_mesh`]).
//!
//! The match cost of two pixels is ξ (γ where opacity differs) rather than
//! the paper's plain RGB distance, since the colour of a transparent pixel
//! is not seen: opaque strokes are lined up with opaque strokes first.

use super::search::{EdgeTable, pixel_cost as xi};

/// The cost of a step that stretches or squeezes opaque pixels (the paper's P).
pub const STRETCH_PENALTY: f32 = 32.0;

/// How far a pixel may move along a seam, as a fraction of the edge.
const MAX_SHIFT_FRACTION: f64 = 0.25;

/// For each pixel `s` of the left edge, the right-edge pixel `T[s]` laid in
/// front of it (no deformation is `T[s] = s`), and the seam's mismatch
/// before and after.
#[derive(Clone, Debug, PartialEq)]
pub struct SeamMap {
    /// `T`, fractional where several right-edge pixels face one left-edge pixel.
    pub remap: Vec<f32>,
    /// Σ ξ along the seam without remapping.
    pub before: f32,
    /// Σ ξ along the seam with it.
    pub after: f32,
}

/// Aligns right edge `v` of `right` with left edge `u` of `left` (equation 2).
pub fn align_seam(right: &EdgeTable, v: usize, left: &EdgeTable, u: usize, column_px: usize) -> SeamMap {
    let n = column_px;
    let band = ((n as f64 * MAX_SHIFT_FRACTION).ceil() as usize).max(1);
    let l: Vec<(bool, [u8; 3])> = (0..n).map(|k| left.sample(u, k)).collect();
    let r: Vec<(bool, [u8; 3])> = (0..n).map(|k| right.sample(v, k)).collect();
    let before: f32 = (0..n).map(|k| xi(l[k], r[k])).sum();
    // M[s][t] over the band |s - t| <= band; moves: diagonal, or a step in s
    // or t alone (paying P where either pixel is opaque).
    let inf = f32::INFINITY;
    let width = 2 * band + 1;
    let mut m = vec![inf; n * width];
    let mut from = vec![0u8; n * width];
    let at = |s: usize, t: usize| s * width + (t + band - s);
    let in_band = |s: usize, t: usize| t + band >= s && t <= s + band && t < n;
    for s in 0..n {
        for t in s.saturating_sub(band)..=(s + band).min(n - 1) {
            let cost = xi(l[s], r[t]);
            let beta = if l[s].0 || r[t].0 { STRETCH_PENALTY } else { 0.0 };
            let mut best = (if s == 0 && t == 0 { 0.0 } else { inf }, 0u8);
            if s > 0 && t > 0 && in_band(s - 1, t - 1) && m[at(s - 1, t - 1)] < best.0 {
                best = (m[at(s - 1, t - 1)], 0);
            }
            if s > 0 && in_band(s - 1, t) && m[at(s - 1, t)] + beta < best.0 {
                best = (m[at(s - 1, t)] + beta, 1);
            }
            if t > 0 && in_band(s, t - 1) && m[at(s, t - 1)] + beta < best.0 {
                best = (m[at(s, t - 1)] + beta, 2);
            }
            m[at(s, t)] = best.0 + cost;
            from[at(s, t)] = best.1;
        }
    }
    // Back from the last pair: each left pixel faces the mean of the right
    // pixels it was matched with.
    let (mut sum, mut count) = (vec![0.0f32; n], vec![0u32; n]);
    let (mut s, mut t) = (n - 1, n - 1);
    loop {
        sum[s] += t as f32;
        count[s] += 1;
        if s == 0 && t == 0 {
            break;
        }
        match from[at(s, t)] {
            0 => (s, t) = (s - 1, t - 1),
            1 => s -= 1,
            _ => t -= 1,
        }
    }
    let remap: Vec<f32> = (0..n).map(|s| sum[s] / count[s].max(1) as f32).collect();
    let after = (0..n).map(|s| xi(l[s], r[(remap[s].round() as usize).min(n - 1)])).sum();
    SeamMap { remap, before, after }
}
