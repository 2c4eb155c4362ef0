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

/// Lags considered. Periods longer than this are rare in results from
/// exemplars of 10 to 20 pieces and would cost memory in every DP state.
pub const LAGS: usize = 12;

/// Fixed-point scale of the per-lag sums.
const SCALE: f64 = 256.0;

const NONE: u8 = u8::MAX;

/// Running autocorrelation of a sequence: the last pieces and the sum per lag.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Autocorrelation {
    /// `history[k]` is the piece `k + 1` places before the end.
    history: [u8; LAGS],
    sums: [u16; LAGS],
}

impl Default for Autocorrelation {
    fn default() -> Self {
        Autocorrelation { history: [NONE; LAGS], sums: [0; LAGS] }
    }
}

/// Precomputed `exp(-d / σ)` for piece-index distances `d`, in fixed point.
#[derive(Clone, Debug)]
pub struct Similarity {
    table: Vec<u16>,
}

impl Similarity {
    /// The table for a given `σ` (the paper uses 0.5).
    pub fn new(sigma: f64) -> Self {
        let table = (0..256).map(|d| ((-(d as f64) / sigma).exp() * SCALE).round() as u16).collect();
        Similarity { table }
    }
}

impl Autocorrelation {
    /// The autocorrelation of the sequence extended by `piece`.
    pub fn push(&self, piece: usize, similarity: &Similarity) -> Autocorrelation {
        let p = piece.min(254) as u8;
        let mut next = *self;
        for j in 0..LAGS {
            let h = self.history[j];
            if h == NONE {
                break;
            }
            next.sums[j] = next.sums[j].saturating_add(similarity.table[usize::from(h.abs_diff(p))]);
        }
        next.history.copy_within(0..LAGS - 1, 1);
        next.history[0] = p;
        next
    }

    /// `max` over lags `1..=LAGS` of the per-lag similarity sums.
    pub fn value(&self) -> f64 {
        f64::from(*self.sums.iter().max().unwrap_or(&0)) / SCALE
    }

    /// The autocorrelation of a whole sequence, computed from scratch (for tests and reports).
    ///
    /// ```
    /// use tracery_core::{Autocorrelation, Similarity};
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
