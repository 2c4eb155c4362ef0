//! The cost of joining two pieces (section 3.6.1 of the paper).

use super::Piece;

/// Weight of the endpoint-position term against the tangent term (the paper's α).
pub const MATCH_WEIGHT: f64 = 0.8;

/// What a break costs: a seam without portals, where two pieces sit side by
/// side and nothing joins them. As much as a poor seam, so that a pattern
/// breaks up only where its targets ask for separate parts (or nothing else
/// fits), and end caps do not line up along the curve for free.
pub const BREAK_COST: f64 = 1.0;

/// Weight of the lean term: what stitching a seam leans its two pieces by,
/// against the endpoint and tangent terms. Chosen on the corpus sweep
/// (`docs/quality.md`, *Seams that lean*): higher weights shear less but
/// repeat more, the solver giving up variety for seams that fit.
pub const LEAN_WEIGHT: f64 = 0.5;

/// Leans up to this angle cost nothing: the variety of a pattern comes from
/// seams that do not fit exactly, and a slight lean does not show.
pub const LEAN_FREE_DEG: f64 = 30.0;

/// Weight of the misfit term: how far stitching must move each endpoint
/// across the band once the seam is aligned, squared and summed. The
/// paper's `d_match` (weighted by `α`) is the same gap averaged and measured
/// against the exemplar's height squared, so a seam that moves a fret's bar
/// by more than its own thickness, or squeezes a stem running along a cut
/// into a portal a twentieth of its size, cost less than a few poor
/// tangents, and the variety term bought such seams wherever the exemplar
/// had seams that fit exactly to vary with. Chosen on the corpus sweep
/// (`docs/quality.md`, *Seams that do not fit*).
pub const MISFIT_WEIGHT: f64 = 10.0;

/// Steepest slope the stitch gives a piece per unit of an endpoint's move
/// across the band, over the piece's width: the side maps are blended with a
/// smoothstep, whose slope peaks at 1.5, and each side moves half the gap.
const LEAN_PER_GAP: f64 = 0.75;

/// How well the right side of one piece fits the left side of another.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairCost {
    /// Mean squared distance between matched portal endpoints after the best
    /// vertical alignment, divided by the exemplar's height squared so that
    /// costs do not depend on drawing units.
    pub d_match: f64,
    /// Sum over matched endpoints of `|1 - g_a · g_b|` for their boundary tangents.
    pub d_tangent: f64,
    /// How far stitching leans the two pieces: over matched endpoints, the
    /// mean of both pieces' `sin²` of the lean angle (the endpoint's move
    /// over the piece's width), past [`LEAN_FREE_DEG`] and rescaled to reach
    /// 1 at 90°. Summed like `d_tangent`.
    ///
    /// `d_match` measures the gap against the exemplar's height, so a gap
    /// that two wide pieces take up without a trace costs as much as one
    /// that a sliver of a piece must take up alone, leaning it by 70° or
    /// more; this term tells them apart.
    pub d_lean: f64,
    /// How far stitching moves the matched endpoints once aligned by `tau`:
    /// the sum of their squared gaps, over the exemplar's height squared.
    /// Unlike `d_match` it grows with every endpoint that does not fit.
    pub d_misfit: f64,
    /// The best vertical offset of the second piece relative to the first, in exemplar units.
    pub tau: f64,
    /// `α·d_match + (1-α)·d_tangent + LEAN_WEIGHT·d_lean + MISFIT_WEIGHT·d_misfit`.
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
            return Some(PairCost {
                d_match: 0.0,
                d_tangent: 0.0,
                d_lean: 0.0,
                d_misfit: 0.0,
                tau: 0.0,
                cost: BREAK_COST,
            });
        }
        let tau = ya.iter().zip(&yb).map(|(ra, lb)| ra - lb).sum::<f64>() / m as f64;
        let scale = exemplar_height.max(f64::MIN_POSITIVE);
        let d_misfit = ya.iter().zip(&yb).map(|(ra, lb)| ((lb + tau - ra) / scale).powi(2)).sum::<f64>();
        let d_match = d_misfit / m as f64;
        let ga = a.right.iter().flat_map(|p| [p.top_tangent, p.bottom_tangent]);
        let gb = b.left.iter().flat_map(|p| [p.top_tangent, p.bottom_tangent]);
        let d_tangent = ga.zip(gb).map(|(x, y)| (1.0 - x.dot(y)).abs()).sum::<f64>();
        let free = LEAN_FREE_DEG.to_radians().sin().powi(2);
        let lean = |gap: f64, width: f64| {
            let slope = LEAN_PER_GAP * gap / width.max(f64::MIN_POSITIVE);
            // sin² of the lean angle: bounded, so that however thin a sliver
            // is, its seam costs no more than a few poor tangents; leans the
            // eye does not notice cost nothing.
            let sin2 = if slope.is_finite() { slope * slope / (1.0 + slope * slope) } else { 1.0 };
            ((sin2 - free) / (1.0 - free)).max(0.0)
        };
        let d_lean = ya
            .iter()
            .zip(&yb)
            .map(|(ra, lb)| {
                let gap = lb + tau - ra;
                0.5 * (lean(gap, a.width) + lean(gap, b.width))
            })
            .sum::<f64>();
        let cost =
            MATCH_WEIGHT * d_match + (1.0 - MATCH_WEIGHT) * d_tangent + LEAN_WEIGHT * d_lean + MISFIT_WEIGHT * d_misfit;
        Some(PairCost { d_match, d_tangent, d_lean, d_misfit, tau, cost })
    }

    /// The cost with the misfit term at `misfit_weight` instead of
    /// [`MISFIT_WEIGHT`].
    ///
    /// ```
    /// use tracery_core::vector_brush::{builtin, PieceSet, SliceOptions, MISFIT_WEIGHT};
    /// let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
    /// let pair = (0..set.len()).flat_map(|a| (0..set.len()).map(move |b| (a, b)))
    ///     .filter_map(|(a, b)| set.joining(a, b))
    ///     .find(|p| p.d_misfit > 0.0)
    ///     .unwrap();
    /// assert_eq!(pair.cost_at(MISFIT_WEIGHT), pair.cost);
    /// assert!(pair.cost_at(0.0) < pair.cost);
    /// ```
    pub fn cost_at(&self, misfit_weight: f64) -> f64 {
        // At the default weight the stored cost itself, to the last bit:
        // adding and taking away the term would round it.
        if misfit_weight == MISFIT_WEIGHT {
            self.cost
        } else {
            self.cost + (misfit_weight - MISFIT_WEIGHT) * self.d_misfit
        }
    }
}
