//! The variety term: incremental autocorrelation of a piece sequence (section 3.7).
//!
//! The paper defines `A(η) = max_j Σ_i exp(-|η_i - η_{i+j}| / σ)` with the
//! maximum over lags `j ∈ [0, K]`. Lag 0 compares the sequence with itself,
//! gives `K + 1`, and so always wins the maximum: the printed term is a
//! constant. We exclude lag 0 and take lags `1..=LAGS`. We do **not**
//! normalise per lag: with `LAGS` far below the sequence length, the number
//! of terms differs between lags by at most `LAGS`, and the raw sums keep
//! the penalty proportional to how much of the pattern repeats, so it stays
//! comparable to the matching cost, which also grows with the length.
//!
//! Each partial solution carries the last `LAGS` pieces and the running sum
//! per lag, so adding a piece costs `O(LAGS)` instead of rescanning the
//! whole sequence.

/// Lags considered. The cheapest way to repeat is a simple cycle of the
/// pieces that may follow each other, so its period is at most the number
/// of distinct shapes searched: 28 at most on the corpus, 12 or fewer for
/// most ornaments. With 12 lags the search escaped into cycles of period 13
/// and 14 (vectorian15: 19 of 24 sweep runs with a period under a third of
/// the pattern); with 32 it sees every simple cycle. Each open state carries
/// `LAGS` bytes of history and `2·LAGS` of sums (as shortfalls).
pub const LAGS: usize = 32;

/// Fixed-point scale of the per-lag sums. The largest sum is a `u32`: at
/// this scale it would need sixteen million fully matching pairs at one lag
/// to saturate, so the penalty keeps growing with the repetition however
/// long the curve (with `u16` sums it stopped at 256 pairs, a few hundred
/// pieces).
const SCALE: f64 = 256.0;

/// Running autocorrelation of a sequence: the last pieces, the largest sum
/// over the lags, and how far each lag's sum is below it.
///
/// The sums are kept as their shortfalls from the largest, in 16 bits: a
/// history is then 104 bytes instead of 168 (the search holds one per open
/// state, and moves it at every step), and eight lags fit in one SSE2
/// register instead of four. A shortfall stops at `u16::MAX`, 256 whole
/// matches: only a lag that many matches behind the largest and then
/// catching up all of them would be scored differently, which a pattern of
/// fewer than 256 pieces cannot do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Autocorrelation {
    /// `history[k]` is the piece `k + 1` places before the end.
    history: [u8; LAGS],
    /// `max` less the sum at lag `k + 1`, at most `u16::MAX`.
    shortfall: [u16; LAGS],
    /// The largest of the per-lag sums.
    max: u32,
    /// How many entries of `history` are filled.
    filled: u8,
}

impl Default for Autocorrelation {
    fn default() -> Self {
        Autocorrelation::EMPTY
    }
}

/// Precomputed `exp(-d / σ)` for piece-index distances `d`, in fixed point.
#[derive(Clone, Debug)]
pub struct Similarity {
    table: [u16; 256],
    /// The entries for distances 1 to 3, where distance 0 adds 256 (one
    /// whole match) and every farther one rounds to zero (σ = 0.5 gives
    /// 256, 35, 5, 1, then zeros): adding a piece then needs no table
    /// lookups, and runs on eight lags at once.
    near: Option<[u16; NEAR - 1]>,
}

/// How many distances can be told apart without the table (see [`Similarity`]).
const NEAR: usize = 4;

impl Similarity {
    /// The table for a given `σ` (the paper uses 0.5).
    pub fn new(sigma: f64) -> Self {
        let table: [u16; 256] = std::array::from_fn(|d| ((-(d as f64) / sigma).exp() * SCALE).round() as u16);
        let near =
            (table[0] == 256 && table[NEAR..].iter().all(|&t| t == 0)).then(|| std::array::from_fn(|d| table[d + 1]));
        Similarity { table, near }
    }
}

/// `history` one place older, with `p` as the newest piece. Shifted as four
/// 64-bit words in registers: copying the 31 bytes into place compiled to a
/// call to `memcpy`, which took a twentieth of a large loop search's time
/// in `perf`.
#[inline]
fn shifted_in(history: &[u8; LAGS], p: u8) -> [u8; LAGS] {
    const WORDS: usize = LAGS / 8;
    const { assert!(LAGS.is_multiple_of(8)) };
    let word = |i: usize| u64::from_le_bytes(std::array::from_fn(|k| history[8 * i + k]));
    let mut out = [0u8; LAGS];
    let mut carry = u64::from(p);
    for i in 0..WORDS {
        let w = word(i);
        out[8 * i..8 * i + 8].copy_from_slice(&((w << 8) | carry).to_le_bytes());
        carry = w >> 56;
    }
    out
}

/// The largest of the gains, each at most 256: taken in signed 16-bit
/// lanes, which SSE2 compares (it has no unsigned 16-bit maximum), eight
/// chains side by side (a plain fold is one long chain).
#[inline(always)]
fn max_of(gains: &[u16; LAGS]) -> u16 {
    let mut lanes = [0i16; 8];
    for chunk in gains.chunks_exact(8) {
        for (lane, &g) in lanes.iter_mut().zip(chunk) {
            *lane = (*lane).max(g as i16);
        }
    }
    lanes.into_iter().fold(0, i16::max) as u16
}

impl Autocorrelation {
    /// The autocorrelation of the empty sequence.
    pub const EMPTY: Autocorrelation = Autocorrelation { history: [0; LAGS], shortfall: [0; LAGS], max: 0, filled: 0 };

    /// The autocorrelation of the sequence extended by `piece`.
    #[inline]
    pub fn push(&self, piece: usize, similarity: &Similarity) -> Autocorrelation {
        let p = piece.min(255) as u8;
        // What each lag's sum grows by, at most 256.
        let mut add = [0u16; LAGS];
        match similarity.near {
            // A full history and a short reach: the same few operations on
            // every lag, which the compiler runs side by side. Most states
            // of a long search are of this kind.
            Some(near) if usize::from(self.filled) == LAGS => {
                // Worked out in 16-bit lanes, eight lags to an SSE2
                // register: in 32-bit lanes the same steps took a fifth of
                // a large loop search's time in `perf`, and worked out in
                // bytes they had to be interleaved one lag at a time.
                let [n1, n2, n3] = near;
                for (a, &older) in add.iter_mut().zip(self.history.iter()) {
                    let d = u16::from(older.max(p) - older.min(p));
                    *a = (if d == 0 { 256 } else { 0 })
                        | (if d == 1 { n1 } else { 0 })
                        | (if d == 2 { n2 } else { 0 })
                        | (if d == 3 { n3 } else { 0 });
                }
            }
            _ => {
                for (a, &h) in add.iter_mut().zip(self.history.iter()).take(usize::from(self.filled)) {
                    *a = similarity.table[usize::from(h.abs_diff(p))];
                }
            }
        }
        // The largest sum grows by the most any lag gains on it; every
        // shortfall grows by that and shrinks by its own lag's gain.
        let mut gain = [0u16; LAGS];
        for ((g, &a), &short) in gain.iter_mut().zip(add.iter()).zip(self.shortfall.iter()) {
            *g = a.saturating_sub(short);
        }
        let rise = max_of(&gain);
        let mut shortfall = [0u16; LAGS];
        for ((out, &a), &short) in shortfall.iter_mut().zip(add.iter()).zip(self.shortfall.iter()) {
            // `short + rise >= a` wherever it does not saturate: `rise`
            // is at least `a - short`.
            *out = short.saturating_add(rise).saturating_sub(a);
        }
        Autocorrelation {
            history: shifted_in(&self.history, p),
            shortfall,
            max: self.max.saturating_add(u32::from(rise)),
            filled: (self.filled + 1).min(LAGS as u8),
        }
    }

    /// `max` over lags `1..=LAGS` of the per-lag similarity sums.
    pub fn value(&self) -> f64 {
        f64::from(self.max) / SCALE
    }

    /// The autocorrelation of a whole sequence, computed from scratch (for tests and reports).
    ///
    /// ```
    /// use tracery_core::vector_brush::{Autocorrelation, Similarity};
    /// let s = Similarity::new(0.5);
    /// // A sequence that repeats with period 2 correlates fully at lag 2.
    /// let periodic = Autocorrelation::of(&[0, 5, 0, 5, 0, 5], &s).value();
    /// let varied = Autocorrelation::of(&[0, 5, 2, 9, 4, 7], &s).value();
    /// assert!(periodic > 3.9 && varied < 1.0);
    /// ```
    pub fn of(sequence: &[usize], similarity: &Similarity) -> Autocorrelation {
        sequence.iter().fold(Autocorrelation::default(), |a, &p| a.push(p, similarity))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sums as the definition gives them, lag by lag.
    fn sums_by_definition(sequence: &[usize], similarity: &Similarity) -> [u32; LAGS] {
        let mut sums = [0u32; LAGS];
        for (lag, sum) in sums.iter_mut().enumerate().map(|(k, s)| (k + 1, s)) {
            for i in lag..sequence.len() {
                let d = sequence[i].min(255).abs_diff(sequence[i - lag].min(255));
                *sum += u32::from(similarity.table[d]);
            }
        }
        sums
    }

    #[test]
    fn running_sums_agree_with_the_definition() {
        let mut state = 7u64;
        let sequence: Vec<usize> = (0..300)
            .map(|_| {
                state = crate::random::splitmix64(state);
                (state % 12) as usize
            })
            .collect();
        for sigma in [0.5, 1.0, 40.0] {
            let similarity = Similarity::new(sigma);
            // σ = 0.5 takes the path without the table, the others the table.
            assert_eq!(similarity.near.is_some(), sigma == 0.5);
            for len in [0, 1, 5, 31, 32, 33, 300] {
                let running = Autocorrelation::of(&sequence[..len], &similarity);
                let expected = sums_by_definition(&sequence[..len], &similarity);
                let max = expected.iter().copied().max().unwrap_or(0);
                assert_eq!(running.max, max, "σ {sigma}, {len} pieces");
                let sums: Vec<u32> = running.shortfall.iter().map(|&s| max - u32::from(s)).collect();
                assert_eq!(sums, expected, "σ {sigma}, {len} pieces");
            }
        }
    }

    #[test]
    fn the_penalty_keeps_growing_on_long_repetitions() {
        // 2000 copies of one piece: every lag matches 2000 times, far past
        // what 16-bit sums held.
        let s = Similarity::new(0.5);
        let long = Autocorrelation::of(&[3; 2000], &s).value();
        let longer = Autocorrelation::of(&[3; 4000], &s).value();
        assert!(long > 1990.0, "{long}");
        assert!(longer > 1.9 * long, "{longer} vs {long}");
    }
}
