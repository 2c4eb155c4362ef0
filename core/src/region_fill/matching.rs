//! Robust neighbourhood matching (section 4.2.3 of the curve-texture
//! paper): each output sample is matched to one input sample, or left
//! unmatched as an outlier at a cost of its own, whichever makes the
//! neighbourhoods agree best. Solved as an assignment problem with
//! `pathfinding`'s Kuhn–Munkres on integer costs.

use pathfinding::kuhn_munkres::kuhn_munkres;
use pathfinding::matrix::Matrix;

/// Costs are rounded to this many units per millimetre for the integer
/// solver: a nanometre, far below any difference between samples.
const UNITS_PER_MM: f64 = 1e6;

/// The integer cost standing for "never": larger than any sum of finite
/// costs the solver can meet, yet far from overflowing.
const NEVER: i64 = 1 << 50;

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
    let scaled = |c: f64| if c.is_finite() { -((c * UNITS_PER_MM).round() as i64).min(NEVER) } else { -NEVER };
    // Columns: the inputs, then one "unmatched" column per output (any of
    // them will do: each row costs the same in all of them).
    let weights = Matrix::from_fn(outputs, inputs + outputs, |(o, column)| match column < inputs {
        true => scaled(cost(o, column)),
        false => scaled(unmatched[o]),
    });
    let (_, columns) = kuhn_munkres(&weights);
    let input_of: Vec<Option<usize>> = columns.iter().map(|&c| (c < inputs).then_some(c)).collect();
    let cost = input_of.iter().enumerate().map(|(o, i)| i.map_or(unmatched[o], |i| cost(o, i))).sum();
    Matching { input_of, cost }
}
