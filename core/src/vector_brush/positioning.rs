//! Global positioning of the pieces (section 4.1 of the paper).

use super::{CurveKind, PieceSet};

/// Pull of every offset towards the band's axis, relative to the seam terms.
/// It keeps the system well posed where a seam has no portal (pieces side by
/// side, nothing to align) and is too small to matter elsewhere.
const AXIS_WEIGHT: f64 = 1e-3;

/// Vertical offsets `δ` of the pieces of `sequence`, in exemplar units.
///
/// Minimizes `Σ M_i (δ_i + τ_i − δ_{i+1})²` over the seams, `M_i` being the
/// number of portal endpoints of seam `i` and `τ_i` its best alignment. The
/// first piece sits on the axis (`δ_0 = 0`), and so does every piece after a
/// break (a seam without portals): these are the offsets the solver bounded
/// to the band, so on an open curve each seam is aligned exactly. On a loop
/// the seam from the last piece back to the first counts too, and what the
/// loop does not close is spread over its seams. The normal equations are
/// tridiagonal and solved in linear time.
///
/// ```
/// use tracery_core::vector_brush::{builtin, position_offsets, PieceSet, SliceOptions, CurveKind};
/// let set = PieceSet::new(&builtin("vine").unwrap(), &SliceOptions::default()).unwrap();
/// let sequence: Vec<usize> = (0..set.len()).collect();
/// // The exemplar in its own order needs no offset at all.
/// let offsets = position_offsets(&set, &sequence, CurveKind::Open);
/// assert!(offsets.iter().all(|d| d.abs() < 1e-9));
/// ```
pub fn position_offsets(set: &PieceSet, sequence: &[usize], curve: CurveKind) -> Vec<f64> {
    let n = sequence.len();
    if n < 2 {
        return vec![0.0; n];
    }
    let steps: Vec<Option<f64>> = (0..n)
        .map(|i| {
            let (a, b) = (sequence[i], sequence[(i + 1) % n]);
            let closing = i + 1 == n;
            if closing && curve == CurveKind::Open {
                return None;
            }
            set.joining(a, b).map(|p| p.tau)
        })
        .collect();
    least_squares_offsets(set, sequence, &steps)
}

/// Minimizes `Σ M_i (δ_i + step_i − δ_{i+1})²` over the seams with a step
/// (`steps[i]` joins piece `i` to `i + 1`, the last one closing a loop),
/// with `δ_0 = 0` and every piece after a break pinned at 0 too.
fn least_squares_offsets(set: &PieceSet, sequence: &[usize], steps: &[Option<f64>]) -> Vec<f64> {
    let n = sequence.len();
    let seams: Vec<(usize, usize, f64, f64)> = steps
        .iter()
        .enumerate()
        .filter_map(|(i, step)| step.map(|tau| (i, (i + 1) % n, 2.0 * set.pieces[sequence[i]].right.len() as f64, tau)))
        .collect();
    // Unknowns: δ_1 .. δ_{n-1}, except right after a break, pinned at 0 like δ_0.
    let last = n - 1;
    let m = last;
    if m == 0 {
        return vec![0.0; n];
    }
    let pinned: Vec<bool> = (0..n).map(|i| i == 0 || set.joining(sequence[i - 1], sequence[i]).is_none()).collect();
    let mut diag = vec![AXIS_WEIGHT; m];
    let mut off = vec![0.0; m.saturating_sub(1)];
    let mut rhs = vec![0.0; m];
    let unknown = |i: usize| (!pinned[i]).then(|| i - 1);
    // Each seam contributes w·(δ_a + τ − δ_b)² to the energy.
    for &(a, b, w, tau) in &seams {
        match (unknown(a), unknown(b)) {
            (Some(ia), Some(ib)) => {
                diag[ia] += w;
                diag[ib] += w;
                off[ia.min(ib)] -= w;
                rhs[ia] -= w * tau;
                rhs[ib] += w * tau;
            }
            (Some(ia), None) => {
                diag[ia] += w;
                rhs[ia] -= w * tau;
            }
            (None, Some(ib)) => {
                diag[ib] += w;
                rhs[ib] += w * tau;
            }
            (None, None) => {}
        }
    }
    let solved = solve_tridiagonal(&diag, &off, &rhs);
    let mut offsets = vec![0.0; n];
    for (k, value) in solved.into_iter().enumerate() {
        offsets[k + 1] = value;
    }
    offsets
}

/// The offsets to stitch `sequence` with, from the ones the solver chose
/// (`solved`, which keeps every piece in the band): on an open curve they are
/// used as they are; on a loop, what the loop does not close is spread over
/// its seams by least squares, each seam keeping the step the solver gave it.
///
/// ```
/// use tracery_core::vector_brush::{builtin, solve, spread_offsets, CurveKind, PieceSet, SliceOptions, SolveOptions};
/// use tracery_core::control::Control;
/// let set = PieceSet::new(&builtin("vine").unwrap(), &SliceOptions::default()).unwrap();
/// let solution = solve(&set, &SolveOptions::new(3.0 * set.exemplar_width), &Control::default()).unwrap();
/// let offsets = spread_offsets(&set, &solution.pieces, &solution.offsets, CurveKind::Open);
/// assert_eq!(offsets, solution.offsets);
/// ```
pub fn spread_offsets(set: &PieceSet, sequence: &[usize], solved: &[f64], curve: CurveKind) -> Vec<f64> {
    let n = sequence.len();
    if curve == CurveKind::Open || n < 2 || solved.len() != n {
        return solved.to_vec();
    }
    let steps: Vec<Option<f64>> = (0..n)
        .map(|i| {
            let (a, b) = (sequence[i], sequence[(i + 1) % n]);
            set.joining(a, b).map(|p| if i + 1 < n { solved[i + 1] - solved[i] } else { p.tau })
        })
        .collect();
    least_squares_offsets(set, sequence, &steps)
}

/// Solves a symmetric positive definite tridiagonal system (Thomas algorithm).
fn solve_tridiagonal(diag: &[f64], off: &[f64], rhs: &[f64]) -> Vec<f64> {
    let m = diag.len();
    let mut c = vec![0.0; m];
    let mut d = vec![0.0; m];
    let mut denom = diag[0];
    c[0] = if m > 1 { off[0] / denom } else { 0.0 };
    d[0] = rhs[0] / denom;
    for i in 1..m {
        denom = diag[i] - off[i - 1] * c[i - 1];
        c[i] = if i + 1 < m { off[i] / denom } else { 0.0 };
        d[i] = (rhs[i] - off[i - 1] * d[i - 1]) / denom;
    }
    let mut x = vec![0.0; m];
    x[m - 1] = d[m - 1];
    for i in (0..m - 1).rev() {
        x[i] = d[i] - c[i] * x[i + 1];
    }
    x
}
