//! The cost of joining two pieces (section 3.6.1 of the paper).

use super::Piece;

/// Weight of the endpoint-position term against the tangent term (the paper's α).
pub const MATCH_WEIGHT: f64 = 0.8;

/// What a break costs: a seam without portals, where two pieces sit side by
/// side and nothing joins them. As much as a poor seam, so that a pattern
/// breaks up only where its targets ask for separate parts (or nothing else
/// fits), and end caps do not line up along the curve for free.
pub const BREAK_COST: f64 = 1.0;

/// How well the right side of one piece fits the left side of another.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairCost {
    /// Mean squared distance between matched portal endpoints after the best
    /// vertical alignment, divided by the exemplar's height squared so that
    /// costs do not depend on drawing units.
    pub d_match: f64,
    /// Sum over matched endpoints of `|1 - g_a · g_b|` for their boundary tangents.
    pub d_tangent: f64,
    /// The best vertical offset of the second piece relative to the first, in exemplar units.
    pub tau: f64,
    /// `α·d_match + (1-α)·d_tangent`.
    pub cost: f64,
}

impl PairCost {
    /// The cost of putting `b` right after `a`; `None` when their portal counts differ.
    pub fn between(a: &Piece, b: &Piece, exemplar_height: f64) -> Option<PairCost> {
        if a.right.len() != b.left.len() {
            return None;
        }
        let ya: Vec<f64> = a.right_endpoints().collect();
        let yb: Vec<f64> = b.left_endpoints().collect();
        let m = ya.len();
        if m == 0 {
            // Nothing to join: the pieces just sit side by side (stitching
            // keeps them apart, so the break is a real one).
            return Some(PairCost { d_match: 0.0, d_tangent: 0.0, tau: 0.0, cost: BREAK_COST });
        }
        let tau = ya.iter().zip(&yb).map(|(ra, lb)| ra - lb).sum::<f64>() / m as f64;
        let scale = exemplar_height.max(f64::MIN_POSITIVE);
        let d_match = ya.iter().zip(&yb).map(|(ra, lb)| ((lb + tau - ra) / scale).powi(2)).sum::<f64>() / m as f64;
        let ga = a.right.iter().flat_map(|p| [p.top_tangent, p.bottom_tangent]);
        let gb = b.left.iter().flat_map(|p| [p.top_tangent, p.bottom_tangent]);
        let d_tangent = ga.zip(gb).map(|(x, y)| (1.0 - x.dot(y)).abs()).sum::<f64>();
        let cost = MATCH_WEIGHT * d_match + (1.0 - MATCH_WEIGHT) * d_tangent;
        Some(PairCost { d_match, d_tangent, tau, cost })
    }
}
