//! The solver's state: lengths on an integer grid, DP states in length
//! buckets, and interned topology descriptors with memoized joins.

use rustc_hash::FxHashMap;

use super::{PieceSet, SolveOptions};
use crate::vector_brush::Autocorrelation;
use crate::vector_brush::TopologyDescriptor;

/// Lengths as integer steps of a quantum: the key under which partial
/// solutions of about the same length compete. Each state also carries its
/// true length, so the quantum never adds up into a length error; it only
/// decides which partial solutions are merged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LengthGrid {
    /// Exemplar units per step.
    pub quantum: f64,
}

impl LengthGrid {
    /// The grid the solver uses for `set` and `options`: by default the
    /// narrowest piece or a tenth of the tolerance, whichever is smaller.
    /// Never wider than the narrowest piece, so every piece moves a state to
    /// a later key and the search runs in order of length.
    pub fn new(set: &PieceSet, options: &SolveOptions) -> Self {
        let narrowest = set.pieces.iter().map(|p| p.width).fold(f64::INFINITY, f64::min);
        let epsilon = options.length_tolerance * options.target_length;
        let quantum =
            options.length_quantum.map_or_else(|| narrowest.min(epsilon / 10.0), |q| q.min(narrowest)).max(1e-12);
        LengthGrid { quantum }
    }

    /// The key of a true length, in steps: rounded to the nearest, halves up.
    ///
    /// ```
    /// use tracery_core::vector_brush::LengthGrid;
    /// let grid = LengthGrid { quantum: 0.5 };
    /// assert_eq!(grid.key(1.2), 2);
    /// assert_eq!(grid.key(1.25), 3);
    /// assert_eq!(grid.key(1.2499), 2);
    /// assert_eq!(grid.key(0.0), 0);
    /// for k in 0..2000 {
    ///     let length = k as f64 * 0.0137;
    ///     assert_eq!(grid.key(length), (length / 0.5).round() as u32);
    /// }
    /// ```
    pub fn key(&self, length: f64) -> u32 {
        // `round`, half away from zero, for the non-negative lengths of a
        // search: it is called for every state and follower, and `round`
        // is a call where the CPU has no rounding instruction.
        let steps = (length / self.quantum).max(0.0);
        let whole = steps as u32;
        if steps - f64::from(whole) >= 0.5 { whole.saturating_add(1) } else { whole }
    }

    /// A width in whole steps, rounded up: the most a piece can advance the key, less one.
    pub fn steps(&self, width: f64) -> u32 {
        ((width / self.quantum).ceil() as u32).max(1)
    }
}

pub(super) const UNKNOWN: u32 = u32::MAX - 1;
pub(super) const PRUNED: u32 = u32::MAX;
pub(super) const NO_PARENT: u32 = u32::MAX;

/// A partial solution waiting in its length bucket to be expanded.
#[derive(Clone, Copy)]
pub(super) struct State {
    pub(super) cost: f64,
    /// True length so far, exemplar units.
    pub(super) length: f64,
    /// The parent's [`Trace`] in the arena.
    pub(super) parent: u32,
    pub(super) descriptor: u32,
    pub(super) delta: f32,
    pub(super) piece: u16,
}

/// What expanded states leave behind: all backtracking needs, the parent
/// and the piece of each, in two arrays (6 bytes a state, where one array
/// of `(parent, offset, piece)` took 12). The offsets are not kept: each
/// follows from the pieces before it ([`super::search`] replays them), so
/// only the states of the few open lengths are held whole.
#[derive(Default)]
pub(super) struct Arena {
    parents: Vec<u32>,
    pieces: Vec<u16>,
}

impl Arena {
    pub(super) fn len(&self) -> usize {
        self.parents.len()
    }

    /// Records an expanded state; returns its index.
    pub(super) fn push(&mut self, parent: u32, piece: u16) -> u32 {
        let index = self.parents.len() as u32;
        self.parents.push(parent);
        self.pieces.push(piece);
        index
    }

    pub(super) fn truncate(&mut self, len: usize) {
        self.parents.truncate(len);
        self.pieces.truncate(len);
    }

    /// The pieces from the first to the state at `end`.
    pub(super) fn pieces_to(&self, end: u32) -> Vec<usize> {
        let mut pieces = Vec::new();
        let mut i = end;
        while i != NO_PARENT {
            pieces.push(usize::from(self.pieces[i as usize]));
            i = self.parents[i as usize];
        }
        pieces.reverse();
        pieces
    }
}

/// The open states of one length, found by `descriptor × pieces + piece`.
///
/// While the keys are few (below [`DIRECT_KEYS`]) they index a table
/// directly. Past that, the bucket finds them through a small
/// open-addressing table sized to the states it holds: with many
/// descriptors a table over every key spans megabytes per length, and its
/// look-ups missed the cache (a fifth of a capped loop search's time in
/// `perf`), where the hashed one holds a few thousand entries.
#[derive(Default)]
pub(super) struct Bucket {
    /// Index into `open` per key, [`NO_PARENT`] where empty (direct keys).
    slots: Vec<u32>,
    /// `(key, index into open)`, [`NO_PARENT`] as key where free; a power
    /// of two, at least twice the states held (hashed keys).
    table: Vec<(u32, u32)>,
    /// Whether the keys have outgrown the direct table; once they have,
    /// they stay hashed, since a search's descriptors only grow.
    hashed: bool,
    /// The keys of `open`, in the same order.
    keys: Vec<u32>,
    /// The states, in insertion order (which is also the expansion order).
    pub(super) open: Vec<State>,
    /// Their variety histories, only when the variety term is on.
    pub(super) auto: Vec<Autocorrelation>,
}

/// Keys below this are looked up directly (a table of at most 16 kB per
/// length); a search that meets a larger key hashes its keys from then on.
const DIRECT_KEYS: usize = 1 << 12;

/// Where probing for `key` starts in a table of `mask + 1` slots.
fn home(key: u32, mask: usize) -> usize {
    // Fibonacci hashing: the keys of one descriptor are consecutive.
    (u64::from(key).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 32) as usize & mask
}

impl Bucket {
    pub(super) fn get(&self, key: usize) -> Option<usize> {
        if !self.hashed {
            return self.slots.get(key).copied().filter(|&i| i != NO_PARENT).map(|i| i as usize);
        }
        let mask = self.table.len() - 1;
        let mut at = home(key as u32, mask);
        loop {
            let (k, i) = self.table[at];
            if k == key as u32 {
                return Some(i as usize);
            }
            if k == NO_PARENT {
                return None;
            }
            at = (at + 1) & mask;
        }
    }

    fn place(table: &mut [(u32, u32)], key: u32, index: u32) {
        let mask = table.len() - 1;
        let mut at = home(key, mask);
        while table[at].0 != NO_PARENT {
            at = (at + 1) & mask;
        }
        table[at] = (key, index);
    }

    /// Adds a state under `key`; returns by how many states the room for
    /// open states grew.
    pub(super) fn insert(&mut self, key: usize, state: State, auto: Option<Autocorrelation>) -> usize {
        let room = self.open.capacity();
        debug_assert!(key < NO_PARENT as usize, "state keys fit in 32 bits");
        if !self.hashed && key >= DIRECT_KEYS {
            self.hashed = true;
            self.slots = Vec::new();
        }
        if self.hashed {
            if self.table.len() < 2 * (self.open.len() + 1) {
                let size = (4 * (self.open.len() + 1)).next_power_of_two().max(64);
                self.table.clear();
                self.table.resize(size, (NO_PARENT, 0));
                for (index, &k) in self.keys.iter().enumerate() {
                    Self::place(&mut self.table, k, index as u32);
                }
            }
            Self::place(&mut self.table, key as u32, self.open.len() as u32);
        } else {
            if key >= self.slots.len() {
                self.slots.resize((key + 1).next_power_of_two(), NO_PARENT);
            }
            self.slots[key] = self.open.len() as u32;
        }
        self.keys.push(key as u32);
        self.open.push(state);
        self.auto.extend(auto);
        self.open.capacity() - room
    }

    /// Moves the states out, leaving the bucket empty for reuse.
    pub(super) fn drain_into(&mut self, states: &mut Vec<State>, autos: &mut Vec<Autocorrelation>) {
        if self.hashed {
            self.keys.clear();
            self.table.fill((NO_PARENT, 0));
        } else {
            for key in self.keys.drain(..) {
                self.slots[key as usize] = NO_PARENT;
            }
        }
        // The callers' vectors are empty: swapping hands the states over
        // without copying them (an open state with its variety history is
        // 136 bytes), and keeps both allocations for reuse.
        if states.is_empty() {
            std::mem::swap(states, &mut self.open);
        } else {
            states.append(&mut self.open);
        }
        if autos.is_empty() {
            std::mem::swap(autos, &mut self.auto);
        } else {
            autos.append(&mut self.auto);
        }
    }
}

/// Descriptors seen in one search, with memoized joins.
pub(super) struct Interner {
    pub(super) ids: FxHashMap<TopologyDescriptor, u32>,
    pub(super) list: Vec<TopologyDescriptor>,
    pub(super) joins: Vec<u32>,
    pub(super) pieces: usize,
}

impl Interner {
    pub(super) fn new(pieces: usize) -> Self {
        Interner { ids: FxHashMap::default(), list: Vec::new(), joins: Vec::new(), pieces }
    }

    pub(super) fn intern(&mut self, d: TopologyDescriptor) -> u32 {
        if let Some(&id) = self.ids.get(&d) {
            return id;
        }
        let id = self.list.len() as u32;
        self.ids.insert(d.clone(), id);
        self.list.push(d);
        self.joins.resize(self.joins.len() + self.pieces, UNKNOWN);
        id
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn state(piece: u16) -> State {
        State { cost: 0.0, length: 0.0, parent: NO_PARENT, descriptor: 0, delta: 0.0, piece }
    }

    /// Keys are found where they were put, before and after they outgrow
    /// the direct table, and a drained bucket holds nothing.
    #[test]
    fn a_bucket_finds_its_keys_direct_and_hashed() {
        let mut bucket = Bucket::default();
        // A hundred direct keys first, then keys past the direct table.
        let keys: Vec<usize> =
            (0..100).map(|k| k * 37).chain((100..3000).map(|k| DIRECT_KEYS + (k * 7919) % (3 * DIRECT_KEYS))).collect();
        for round in 0..2 {
            for (i, &key) in keys.iter().enumerate() {
                assert_eq!(bucket.hashed, round > 0 || i > 100, "round {round}, key {i}");
                assert_eq!(bucket.get(key), None, "round {round}: {key} before it was put");
                bucket.insert(key, state(i as u16), None);
                assert_eq!(bucket.get(key), Some(i), "round {round}: {key}");
            }
            assert!(bucket.hashed);
            for (i, &key) in keys.iter().enumerate() {
                assert_eq!(bucket.get(key), Some(i));
                assert_eq!(bucket.get(key + 4 * DIRECT_KEYS), None);
            }
            let (mut open, mut autos) = (Vec::new(), Vec::new());
            bucket.drain_into(&mut open, &mut autos);
            assert_eq!(open.len(), keys.len());
            assert!(keys.iter().all(|&key| bucket.get(key).is_none()));
        }
    }
}
