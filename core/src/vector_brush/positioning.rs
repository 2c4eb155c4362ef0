//! Global positioning of the pieces (section 4.1 of the paper).

use super::{CurveKind, PieceSet};

/// Pull of every offset towards the band's axis, relative to the seam terms.
/// It keeps the system well posed where a seam has no portal (pieces side by
/// side, nothing to align) and is too small to matter elsewhere.
const AXIS_WEIGHT: f64 = 1e-3;

/// Vertical offsets `δ` of the pieces of `sequence`, in exemplar units.
///
/// Minimizes `Σ M_i (δ_i + τ_i − δ_{i+1})²` over the seams, `M_i` being the
/// number of portal endpoints of seam `i` and `τ_i` its best alignment. On an
/// open curve both ends sit on the axis (`δ_0 = δ_N = 0`); on a loop the seam
/// from the last piece back to the first counts too and `δ_0 = 0`. The normal
/// equations are tridiagonal and solved in linear time.
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
    // Seams (i, i+1, weight, tau), the closing one included on loops.
    let mut seams: Vec<(usize, usize, f64, f64)> = sequence
        .windows(2)
        .enumerate()
        .map(|(i, w)| {
            let pair = set.pair(w[0], w[1]);
            (i, i + 1, pair.map_or(0.0, |_| 2.0 * set.pieces[w[0]].right.len() as f64), pair.map_or(0.0, |p| p.tau))
        })
        .collect();
    if let Some(pair) = set.pair(sequence[n - 1], sequence[0]).filter(|_| curve == CurveKind::Closed) {
        seams.push((n - 1, 0, 2.0 * set.pieces[sequence[n - 1]].right.len() as f64, pair.tau));
    }
    // Unknowns: δ_1 .. δ_{n-1} on loops, δ_1 .. δ_{n-2} on open curves.
    let last = if curve == CurveKind::Closed { n - 1 } else { n - 2 };
    let m = last;
    if m == 0 {
        return vec![0.0; n];
    }
    let mut diag = vec![AXIS_WEIGHT; m];
    let mut off = vec![0.0; m.saturating_sub(1)];
    let mut rhs = vec![0.0; m];
    let unknown = |i: usize| (1..=last).contains(&i).then(|| i - 1);
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
