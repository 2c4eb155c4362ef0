//! SplitMix64 (Steele, Lea and Flood): the one source of reproducible
//! randomness in the engine, as a hash of a number ([`mix`], [`splitmix64`])
//! and as a stream ([`SplitMix64`]). The same seed always gives the same
//! pattern, and no dependency is needed for it.

/// The golden-ratio increment between states.
const GOLDEN: u64 = 0x9e37_79b9_7f4a_7c15;

/// SplitMix64's finalizer: nearby inputs give unrelated outputs.
///
/// ```
/// use tracery_core::random::mix;
/// assert_ne!(mix(1), mix(2));
/// assert_eq!(mix(0), 0);
/// ```
pub fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// One step of SplitMix64 from state `x`: [`mix`] of `x` moved on by the
/// golden-ratio increment.
pub fn splitmix64(x: u64) -> u64 {
    mix(x.wrapping_add(GOLDEN))
}

/// `k` times the golden-ratio increment: the state `k` steps on, for
/// seeds drawn apart from one another.
pub fn steps(k: u64) -> u64 {
    k.wrapping_mul(GOLDEN)
}

/// The top 53 bits of `z` as a number in `[0, 1)`.
pub fn unit(z: u64) -> f64 {
    (z >> 11) as f64 / (1u64 << 53) as f64
}

/// A stream of SplitMix64 numbers.
///
/// ```
/// use tracery_core::random::SplitMix64;
/// let (mut a, mut b) = (SplitMix64::new(7), SplitMix64::new(7));
/// assert_eq!(a.next_u64(), b.next_u64());
/// assert!((0.0..1.0).contains(&a.next_unit()));
/// assert!(a.below(10) < 10);
/// ```
#[derive(Clone, Debug)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// A stream from `seed`.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64 { state: seed }
    }

    /// The next number.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(GOLDEN);
        mix(self.state)
    }

    /// The next number in `[0, 1)`.
    pub fn next_unit(&mut self) -> f64 {
        unit(self.next_u64())
    }

    /// Where the stream stands: a seed for another stream that differs
    /// from this one's next numbers.
    pub fn state(&self) -> u64 {
        self.state
    }

    /// The next number in `[0, n)` (`n` > 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }
}
