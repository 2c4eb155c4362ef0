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

/// What an expanded state leaves behind: all backtracking needs. Only the
/// states of the few open lengths are held whole (with their variety
/// history), so memory grows by 12 bytes per state, not by a whole state.
#[derive(Clone, Copy)]
pub(super) struct Trace {
    pub(super) parent: u32,
    pub(super) delta: f32,
    pub(super) piece: u16,
}

/// The open states of one length, found by `descriptor × pieces + piece`.
#[derive(Default)]
pub(super) struct Bucket {
    /// Index into `open` per key, [`NO_PARENT`] where empty.
    slots: Vec<u32>,
    /// The keys of `open`, in the same order, to clear `slots` after.
    keys: Vec<u32>,
    /// The states, in insertion order (which is also the expansion order).
    pub(super) open: Vec<State>,
    /// Their variety histories, only when the variety term is on.
    pub(super) auto: Vec<Autocorrelation>,
}

impl Bucket {
    pub(super) fn get(&self, key: usize) -> Option<usize> {
        self.slots.get(key).copied().filter(|&i| i != NO_PARENT).map(|i| i as usize)
    }

    pub(super) fn insert(&mut self, key: usize, state: State, auto: Option<Autocorrelation>) {
        if key >= self.slots.len() {
            self.slots.resize((key + 1).next_power_of_two(), NO_PARENT);
        }
        self.slots[key] = self.open.len() as u32;
        self.keys.push(key as u32);
        self.open.push(state);
        self.auto.extend(auto);
    }

    /// Moves the states out, leaving the bucket empty for reuse.
    pub(super) fn drain_into(&mut self, states: &mut Vec<State>, autos: &mut Vec<Autocorrelation>) {
        for key in self.keys.drain(..) {
            self.slots[key as usize] = NO_PARENT;
        }
        // The callers' vectors are empty: swapping hands the states over
        // without copying them (an open state with its variety history is
        // about 200 bytes), and keeps both allocations for reuse.
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
