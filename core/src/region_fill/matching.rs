//! Robust neighbourhood matching (section 4.2.3 of the curve-texture
//! paper): each output sample is matched to one input sample, or left
//! unmatched as an outlier at a cost of its own, whichever makes the
//! neighbourhoods agree best. Solved as a sparse assignment problem by
//! shortest augmenting paths: a pair dearer than leaving its output
//! sample unmatched is never needed, so each output keeps only its few
//! near inputs and its own unmatched place.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// The cost of leaving alone an output that must be matched if it can
/// be (an infinite unmatched cost), mm: beyond any sum of real costs.
const NEVER_MM: f64 = 1e9;

/// How the output samples of a neighbourhood are matched.
#[derive(Clone, Debug, PartialEq)]
pub struct Matching {
    /// For each output sample, its input sample, or `None` when it is left unmatched.
    pub input_of: Vec<Option<usize>>,
    /// The total cost: matched pairs' costs plus unmatched samples' costs.
    pub cost: f64,
}

/// Matches `outputs` output samples with `inputs` input samples, each input
/// used at most once, minimizing the sum of `cost(o, i)` over matched pairs
/// and `unmatched[o]` over outputs left alone (the paper's matrix
/// `[C_m | C_u]`). An infinite cost forbids that pair (samples of different
/// kinds); an infinite `unmatched[o]` makes `o` be matched if it can be.
///
/// ```
/// use tracery_core::region_fill::robust_match;
/// // The second output is an outlier: far from both inputs, so it goes unmatched.
/// let cost = |o: usize, i: usize| [[0.1, 5.0], [9.0, 9.0]][o][i];
/// let m = robust_match(2, 2, &cost, &[1.0, 1.0]);
/// assert_eq!(m.input_of, vec![Some(0), None]);
/// assert!((m.cost - 1.1).abs() < 1e-9);
/// ```
pub fn robust_match(outputs: usize, inputs: usize, cost: &dyn Fn(usize, usize) -> f64, unmatched: &[f64]) -> Matching {
    if outputs == 0 {
        return Matching { input_of: Vec::new(), cost: 0.0 };
    }
    // Columns: the inputs, then each output's own unmatched place. Each
    // row keeps the pairs cheaper than its unmatched place (a dearer one
    // can always give way to it), then that place.
    let mut rows = SparseRows { start: Vec::with_capacity(outputs + 1), pairs: Vec::new() };
    for (o, &alone) in unmatched.iter().enumerate().take(outputs) {
        rows.start.push(rows.pairs.len());
        rows.pairs.extend((0..inputs).map(|i| (i, cost(o, i))).filter(|&(_, c)| c < alone));
        rows.pairs.push((inputs + o, alone.min(NEVER_MM)));
    }
    rows.start.push(rows.pairs.len());
    let columns = assign(&rows, inputs + outputs);
    let input_of: Vec<Option<usize>> = columns.iter().map(|&c| (c < inputs).then_some(c)).collect();
    let cost = input_of.iter().enumerate().map(|(o, i)| i.map_or(unmatched[o], |i| cost(o, i))).sum();
    Matching { input_of, cost }
}

/// A cost matrix keeping only its allowed pairs: row `r`'s `(column,
/// cost)` pairs are `pairs[start[r]..start[r + 1]]`.
struct SparseRows {
    start: Vec<usize>,
    pairs: Vec<(usize, f64)>,
}

impl SparseRows {
    fn of(&self, row: usize) -> &[(usize, f64)] {
        &self.pairs[self.start[row]..self.start[row + 1]]
    }
}

/// A column's tentative distance, ordered for the heap.
#[derive(Clone, Copy, PartialEq)]
struct Reach(f64, usize);

impl Eq for Reach {}

impl PartialOrd for Reach {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Reach {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0).then(self.1.cmp(&other.1))
    }
}

const NONE: usize = usize::MAX;

/// One shortest-path search's state over the columns, reset after each
/// row to only what it touched.
struct Search {
    distance: Vec<f64>,
    /// The row each column was last reached from.
    via: Vec<usize>,
    settled: Vec<bool>,
    touched: Vec<usize>,
    heap: BinaryHeap<Reverse<Reach>>,
}

impl Search {
    /// Reaches `row`'s columns from `row`, itself at distance `from`.
    fn relax(&mut self, rows: &SparseRows, row: usize, from: f64, row_potential: &[f64], column_potential: &[f64]) {
        for &(c, cost) in rows.of(row) {
            let d = from + cost - row_potential[row] - column_potential[c];
            if !self.settled[c] && d < self.distance[c] {
                if self.distance[c].is_infinite() {
                    self.touched.push(c);
                }
                self.distance[c] = d;
                self.via[c] = row;
                self.heap.push(Reverse(Reach(d, c)));
            }
        }
    }

    fn reset(&mut self) {
        for &c in &self.touched {
            (self.distance[c], self.via[c], self.settled[c]) = (f64::INFINITY, NONE, false);
        }
        self.touched.clear();
        self.heap.clear();
    }
}

/// The least-cost assignment of every row to its own column, rows added
/// one at a time along a shortest augmenting path (Dijkstra on reduced
/// costs, with row and column potentials keeping them non-negative: the
/// Hungarian method's sparse form). Every row must be able to reach a free
/// column, as each output's unmatched place guarantees. Returns each row's column.
fn assign(rows: &SparseRows, columns: usize) -> Vec<usize> {
    let n = rows.start.len() - 1;
    let (mut row_potential, mut column_potential) = (vec![0.0; n], vec![0.0; columns]);
    let (mut column_of, mut row_of) = (vec![NONE; n], vec![NONE; columns]);
    let mut search = Search {
        distance: vec![f64::INFINITY; columns],
        via: vec![NONE; columns],
        settled: vec![false; columns],
        touched: Vec::new(),
        heap: BinaryHeap::new(),
    };
    let mut popped = Vec::new();
    for first in 0..n {
        search.relax(rows, first, 0.0, &row_potential, &column_potential);
        let (end, length) = loop {
            let Some(Reverse(Reach(d, c))) = search.heap.pop() else {
                unreachable!("every row has its own free column");
            };
            if search.settled[c] || d > search.distance[c] {
                continue;
            }
            search.settled[c] = true;
            if row_of[c] == NONE {
                break (c, d);
            }
            popped.push(c);
            search.relax(rows, row_of[c], d, &row_potential, &column_potential);
        };
        // New potentials keep every reduced cost non-negative and make the
        // path's edges tight: a row reached through column c moves up by
        // the path's length less c's distance, and c down by as much.
        row_potential[first] += length;
        for &c in &popped {
            let slack = length - search.distance[c];
            column_potential[c] -= slack;
            row_potential[row_of[c]] += slack;
        }
        let mut c = end;
        loop {
            let row = search.via[c];
            let previous = column_of[row];
            column_of[row] = c;
            row_of[c] = row;
            if row == first {
                break;
            }
            c = previous;
        }
        search.reset();
        popped.clear();
    }
    column_of
}
