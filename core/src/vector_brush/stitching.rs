//! Gap stitching (section 4.2) and the final contours (section 4.3): the
//! chosen pieces deformed so that they meet exactly, merged into a pattern in
//! band space.
//!
//! Instead of the paper's linear rotation-invariant deformation of piece
//! boundaries, each piece is moved by a smooth closed-form field, which needs
//! no linear solve and cannot tear the piece apart:
//!
//! 1. along `u`, the sequence is stretched uniformly to the exact curve length;
//! 2. across, each side of a piece gets a monotone cubic map (PCHIP) sending its
//!    portal endpoints, raised by the piece's offset `δ`, to the average of the
//!    two sides' endpoints; the two side maps are blended with a smoothstep along
//!    `u`, so the interior moves smoothly and the seam sees only its own side's map;
//! 3. near each seam, a bump that vanishes on the seam line bends the boundary so
//!    that both sides leave each shared endpoint with the same (averaged) slope.
//!
//! Matched endpoints therefore coincide exactly, the portal segments of both
//! sides lie on the same seam line, and tangents agree: no gap, no overlap, no
//! kink. Monotone maps keep every piece free of fold-overs.
//!
//! While each piece is mapped, the map's Jacobian is sampled along its outline
//! ([`Distortion`]), so that the report can say how much the pieces were
//! stretched and sheared.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::{CurveKind, Distortion, PieceSet};
use rayon::prelude::*;
use rustc_hash::FxHashMap;

use crate::geom::{Outline, Polygon, Region, joined_without_union, refine_mapped_thinned_split, union};

/// A synthesized pattern in band space: `u` from 0 to the curve length,
/// `v` across the band, in exemplar units.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BandPattern {
    /// The merged pattern: clean polygons with holes.
    pub region: Region,
    /// Length along `u`.
    pub length: f64,
    /// `u` of every seam between pieces (the closing seam at 0 on loops not repeated).
    pub seams: Vec<f64>,
    /// Whether the pattern is for a loop (`u = 0` and `u = length` are the same line).
    pub curve: CurveKind,
    /// How much stitching (and [`BandPattern::fit_within`]) deformed the
    /// pieces, sampled along their outlines. Bending along the curve comes
    /// after and is not in it.
    pub distortion: Distortion,
    /// For each seam that portals join, in order along `u`, how far apart
    /// its worst-matched pair of endpoints was once the seam was aligned
    /// (their mean offset taken out), as a fraction of the exemplar's
    /// height: what stitching had to close by bending, apart from what the
    /// offsets `δ` move. The gap the seam cost's misfit term prices
    /// (`PairCost::d_misfit` sums its squares), read off the endpoints
    /// stitching moved.
    #[serde(default)]
    pub seam_gaps: Vec<f64>,
}

impl BandPattern {
    /// The largest of [`BandPattern::seam_gaps`], 0 without joined seams.
    pub fn seam_gap_max(&self) -> f64 {
        self.seam_gaps.iter().copied().fold(0.0, f64::max)
    }

    /// How far the pattern reaches from the axis `v = 0`.
    pub fn extent(&self) -> f64 {
        self.region.reach_from_axis()
    }

    /// Scales `v` down uniformly when the pattern reaches past `limit`, so it
    /// stays within `±limit`. Returns the factor applied (1 when none was needed).
    pub fn fit_within(&mut self, limit: f64) -> f64 {
        let extent = self.extent();
        if extent <= limit || extent <= 0.0 {
            return 1.0;
        }
        let factor = limit / extent;
        self.region = self.region.map_points(|p| DVec2::new(p.x, p.y * factor));
        self.distortion.scale_across(factor);
        factor
    }
}

/// A monotone cubic map through `(x_k, y_k)` with `x` increasing, continued
/// with slope 1 beyond the ends (Fritsch–Carlson).
struct MonotoneMap {
    x: Vec<f64>,
    y: Vec<f64>,
    slope: Vec<f64>,
}

impl MonotoneMap {
    fn new(points: &[(f64, f64)]) -> Self {
        // Two portals that meet at one point of the cut (the bottom of one
        // is the top of the next) give that height twice: kept once, since
        // a step of no height has no secant.
        let mut x: Vec<f64> = Vec::with_capacity(points.len());
        let mut y: Vec<f64> = Vec::with_capacity(points.len());
        for &(px, py) in points {
            if x.last().is_some_and(|&last| px <= last) {
                continue;
            }
            x.push(px);
            y.push(py);
        }
        let n = x.len();
        let secant: Vec<f64> = (0..n.saturating_sub(1)).map(|k| (y[k + 1] - y[k]) / (x[k + 1] - x[k])).collect();
        let mut slope = vec![1.0; n];
        // A single height (one portal of no width) is a plain shift.
        for k in 0..if n >= 2 { n } else { 0 } {
            slope[k] = if k == 0 || k == n - 1 {
                let s = secant[if k == 0 { 0 } else { n - 2 }];
                1.0f64.min(3.0 * s)
            } else if secant[k - 1] * secant[k] <= 0.0 {
                0.0
            } else {
                // Harmonic mean keeps the interpolant monotone.
                2.0 / (1.0 / secant[k - 1] + 1.0 / secant[k])
            };
        }
        MonotoneMap { x, y, slope }
    }

    fn eval(&self, v: f64) -> (f64, f64) {
        let Some((k, h, t, value)) = self.inside(v) else {
            return (self.beyond(v), 1.0);
        };
        let t2 = t * t;
        let derivative = (6.0 * t2 - 6.0 * t) / h * self.y[k]
            + (3.0 * t2 - 4.0 * t + 1.0) * self.slope[k]
            + (-6.0 * t2 + 6.0 * t) / h * self.y[k + 1]
            + (3.0 * t2 - 2.0 * t) * self.slope[k + 1];
        (value, derivative)
    }

    /// The image of `v`, as [`Self::eval`] gives it, without the derivative:
    /// what placing each point needs.
    fn value(&self, v: f64) -> f64 {
        self.inside(v).map_or_else(|| self.beyond(v), |(.., value)| value)
    }

    /// The image of `v` at or beyond the lowest or highest height: a shift.
    fn beyond(&self, v: f64) -> f64 {
        let n = self.x.len();
        if v <= self.x[0] { self.y[0] + (v - self.x[0]) } else { self.y[n - 1] + (v - self.x[n - 1]) }
    }

    /// For `v` strictly inside the heights: the interval `k`, its height
    /// `h`, the fraction `t` of it below `v`, and the image of `v`. `None`
    /// at or beyond the lowest or highest height.
    fn inside(&self, v: f64) -> Option<(usize, f64, f64, f64)> {
        let n = self.x.len();
        if v <= self.x[0] || v >= self.x[n - 1] {
            return None;
        }
        // A side has a few portals: a scan beats a binary search.
        let k = self.x[1..n - 1].iter().take_while(|&&x| x <= v).count();
        let h = self.x[k + 1] - self.x[k];
        let t = (v - self.x[k]) / h;
        let (t2, t3) = (t * t, t * t * t);
        let value = (2.0 * t3 - 3.0 * t2 + 1.0) * self.y[k]
            + (t3 - 2.0 * t2 + t) * h * self.slope[k]
            + (-2.0 * t3 + 3.0 * t2) * self.y[k + 1]
            + (t3 - t2) * h * self.slope[k + 1];
        Some((k, h, t, value))
    }
}

/// How one side of a placed piece moves across the band.
enum SideMap {
    /// No portal: a plain shift by the piece's offset.
    Shift(f64),
    /// Portal endpoints sent to their targets.
    Portals(MonotoneMap),
}

impl SideMap {
    fn value(&self, v: f64) -> f64 {
        match self {
            SideMap::Shift(d) => v + d,
            SideMap::Portals(m) => m.value(v),
        }
    }
}

/// The slope correction at one shared endpoint of a seam.
struct Bend {
    /// Target height of the endpoint (after the side maps).
    at: f64,
    /// Heights of the neighbouring endpoints on the seam (support of the weight).
    below: f64,
    above: f64,
    /// Slope to add at the seam.
    coefficient: f64,
}

/// A [`Bend`] as one piece applies it: the reach of its weight above and
/// below it, and along `u` the radius over which it adds its slope, short
/// enough that the piece cannot fold.
struct CappedBend {
    at: f64,
    above: f64,
    below: f64,
    coefficient: f64,
    radius: f64,
}

fn smoothstep(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Smallest gap kept between two pieces at a break, as a fraction of the
/// exemplar's height: material that reaches the exemplar's ends (a flat end
/// face, a tip) would otherwise weld to its neighbour and join parts the
/// plan keeps apart.
pub const BREAK_GAP: f64 = 0.05;

/// Largest slope change a bend adds at a seam (68°). On the corpus, a
/// larger one hardly lowered the kinks at the seams and leaned the strokes
/// beside them further (`docs/geometry.md`, *Each bend its own radius*).
const MAX_BEND: f64 = 2.5;

/// Largest `|∂bend/∂v|` one bend may add: two bends overlap at most, so
/// `v` still grows at least half as fast as before the bending.
const MAX_FOLD_SLOPE: f64 = 0.25;

/// Shortest radius of a bend along `u`, in exemplar heights (0.01 mm on a
/// 10 mm band): a bend that would need a shorter one to stay within
/// [`MAX_FOLD_SLOPE`] adds less slope instead.
const MIN_BEND_RADIUS: f64 = 1e-3;

/// Distances from a cut, in bend radii, at which the edges leaving it are
/// split before they are mapped: a bend acts within its radius of the
/// seam, which may be far shorter than the edge, and refining halves an
/// edge only where its midpoint strays (`geom::refine_mapped`).
const SPLITS_NEAR_CUT: [f64; 4] = [0.125, 0.25, 0.5, 1.0];

/// The union of the stitched pieces' polygons, which touch only along the
/// seams, where both sides of a cut have the same points to the last bit:
/// joined there without a boolean ([`joined_without_union`]) unless that
/// cannot vouch for the result (pieces that overlap or only nearly meet).
///
/// `ends` are the `u` of a loop's two ends, its closing seam, which is
/// welded once mapped by the exact bits of its points on both sides
/// ([`joined_without_union`]); `None` on an open curve.
fn joined_pieces(polygons: Vec<Polygon>, seams_u: &[f64], ends: Option<[f64; 2]>) -> Region {
    let line_of: FxHashMap<u64, u32> = seams_u.iter().enumerate().map(|(k, u)| (u.to_bits(), k as u32)).collect();
    let outlines: Vec<Outline> = polygons
        .iter()
        .enumerate()
        .flat_map(|(p, polygon)| polygon.rings().map(move |ring| (p, ring)))
        .map(|(polygon, ring)| Outline {
            polygon,
            points: ring.clone(),
            lines: ring.iter().map(|q| line_of.get(&q.x.to_bits()).copied()).collect(),
        })
        .collect();
    joined_without_union(polygons.len(), &outlines, ends).unwrap_or_else(|| union(&[&Region::new(polygons)]))
}

/// Pushes onto `out` where to split the edge from `a` to `b`, as
/// fractions of it, if it leaves a cut (or reaches one): at
/// [`SPLITS_NEAR_CUT`] of that cut's shortest bend radius, exemplar units.
/// `cuts` gives each cut's `x` and that radius (infinite without bends).
fn split_near_cuts(a: DVec2, b: DVec2, cuts: [(f64, f64); 2], snap: f64, out: &mut Vec<f64>) {
    let dx = (b.x - a.x).abs();
    if dx <= snap {
        return;
    }
    for (x, reach) in cuts.into_iter().filter(|c| c.1.is_finite()) {
        for f in SPLITS_NEAR_CUT {
            let d = f * reach / dx;
            if d >= 1.0 {
                continue;
            }
            if (a.x - x).abs() <= snap {
                out.push(d);
            }
            if (b.x - x).abs() <= snap {
                out.push(1.0 - d);
            }
        }
    }
}

/// `max_x x·(1 − x)²·(1 + 2x)` over `[0, 1]`, the largest value of the bend's
/// `|u − seam| · falloff` in radii, rounded up.
const FALLOFF_PEAK: f64 = 0.26;

/// Stitches the pieces of `sequence`, raised by `offsets`, into one pattern
/// of exactly `length` exemplar units along `u`. Outlines are refined until
/// the deformed curve is within `tolerance` (exemplar units) of its chords.
pub fn stitch(
    set: &PieceSet,
    sequence: &[usize],
    offsets: &[f64],
    length: f64,
    curve: CurveKind,
    tolerance: f64,
) -> BandPattern {
    let n = sequence.len();
    let pieces: Vec<&super::Piece> = sequence.iter().map(|&i| &set.pieces[i]).collect();
    let total: f64 = pieces.iter().map(|p| p.width).sum();
    let stretch = length / total;
    let mut seam_u = Vec::with_capacity(n + 1);
    let mut acc = 0.0;
    for p in &pieces {
        seam_u.push(acc * stretch);
        acc += p.width;
    }
    seam_u.push(length);

    // For each seam k (between piece k-1 and piece k; seam 0 / n is the loop's
    // closing seam), the shared endpoint targets.
    let joined = |k: usize| -> Option<(usize, usize)> {
        let (a, b) = if k == n { (n - 1, 0) } else { (k - 1, k) };
        let linked = set.joining(sequence[a], sequence[b]).is_some();
        (linked && (k < n || curve == CurveKind::Closed)).then_some((a, b))
    };
    let mut right_maps: Vec<SideMap> = (0..n).map(|i| SideMap::Shift(offsets[i])).collect();
    let mut left_maps: Vec<SideMap> = (0..n).map(|i| SideMap::Shift(offsets[i])).collect();
    let mut right_bends: Vec<Vec<Bend>> = (0..n).map(|_| Vec::new()).collect();
    let mut right_targets: Vec<Vec<f64>> = vec![Vec::new(); n];
    let mut left_targets: Vec<Vec<f64>> = vec![Vec::new(); n];
    let mut left_bends: Vec<Vec<Bend>> = (0..n).map(|_| Vec::new()).collect();
    let seams_to_join: Vec<usize> = match curve {
        CurveKind::Open => (1..n).collect(),
        CurveKind::Closed => (1..=n).collect(),
    };
    let mut seam_gaps = Vec::with_capacity(n);
    for k in seams_to_join {
        let Some((a, b)) = joined(k) else { continue };
        let ya: Vec<f64> = pieces[a].right_endpoints().map(|y| y + offsets[a]).collect();
        let yb: Vec<f64> = pieces[b].left_endpoints().map(|y| y + offsets[b]).collect();
        let mean_gap = ya.iter().zip(&yb).map(|(p, q)| p - q).sum::<f64>() / ya.len().max(1) as f64;
        let gap = ya.iter().zip(&yb).map(|(p, q)| (p - q - mean_gap).abs()).fold(0.0, f64::max);
        seam_gaps.push(gap / set.exemplar_height.max(f64::MIN_POSITIVE));
        let targets: Vec<f64> = ya.iter().zip(&yb).map(|(p, q)| 0.5 * (p + q)).collect();
        // Top-to-bottom lists become increasing in v for the maps.
        let map = |ys: &[f64], delta: f64| {
            let mut points: Vec<(f64, f64)> = ys.iter().zip(&targets).map(|(y, t)| (y - delta, *t)).collect();
            points.reverse();
            MonotoneMap::new(&points)
        };
        let map_a = map(&ya, offsets[a]);
        let map_b = map(&yb, offsets[b]);
        let ga: Vec<DVec2> = pieces[a].right.iter().flat_map(|p| [p.top_tangent, p.bottom_tangent]).collect();
        let gb: Vec<DVec2> = pieces[b].left.iter().flat_map(|p| [p.top_tangent, p.bottom_tangent]).collect();
        let slope = |g: DVec2, derivative: f64| {
            if g.x.abs() < 1e-6 { f64::NAN } else { derivative * g.y / g.x / stretch }
        };
        for e in 0..targets.len() {
            let sa = slope(ga[e], map_a.eval(ya[e] - offsets[a]).1);
            let sb = slope(gb[e], map_b.eval(yb[e] - offsets[b]).1);
            if !(sa.is_finite() && sb.is_finite()) {
                continue;
            }
            let mean = 0.5 * (sa + sb);
            let above = if e == 0 {
                2.0 * targets[0] - targets.get(1).copied().unwrap_or(targets[0] - 1.0)
            } else {
                targets[e - 1]
            };
            let below = if e + 1 == targets.len() {
                2.0 * targets[e] - targets.get(e.wrapping_sub(1)).copied().unwrap_or(targets[e] + 1.0)
            } else {
                targets[e + 1]
            };
            right_bends[a].push(Bend {
                at: targets[e],
                below,
                above,
                coefficient: (mean - sa).clamp(-MAX_BEND, MAX_BEND),
            });
            left_bends[b].push(Bend {
                at: targets[e],
                below,
                above,
                coefficient: (mean - sb).clamp(-MAX_BEND, MAX_BEND),
            });
        }
        right_maps[a] = SideMap::Portals(map_a);
        left_maps[b] = SideMap::Portals(map_b);
        right_targets[a] = targets.clone();
        left_targets[b] = targets;
    }

    // Far below any feature, far above the rounding of the clipping.
    let snap = 1e-6 * set.exemplar_width;
    let snap_v = 1e-6 * set.exemplar_height;
    let no_targets: Vec<f64> = Vec::new();
    // At a break, a piece whose material comes closer to the seam than half
    // the gap is squeezed along u, away from it.
    let gap = BREAK_GAP * set.exemplar_height;
    let is_break = |k: usize| match curve {
        CurveKind::Open => k > 0 && k < n && joined(k).is_none(),
        CurveKind::Closed => joined(if k == 0 { n } else { k }).is_none(),
    };
    // Each piece is deformed on its own, so pieces go to every core.
    let deformed = |(i, piece): (usize, &&super::Piece)| -> (Vec<Polygon>, Distortion) {
        let (x_min, x_max) = piece.region.bounds().map_or((f64::INFINITY, f64::NEG_INFINITY), |b| (b.min.x, b.max.x));
        let left_gap = if is_break(i) { (0.5 * gap - (x_min - piece.u_start)).max(0.0) } else { 0.0 };
        let right_gap = if is_break(i + 1) { (0.5 * gap - (piece.u_end() - x_max)).max(0.0) } else { 0.0 };
        // A piece narrower than the gap is squeezed to half its width at
        // most: squeezed further it would turn inside out.
        // (No gap gives 0/0 or w/0, and `min` turns both into 1.)
        let squeeze = (0.5 * piece.width / (left_gap + right_gap)).min(1.0);
        let (left_gap, right_gap) = (left_gap * squeeze, right_gap * squeeze);
        let (u0, u1) = (seam_u[i] + left_gap * stretch, seam_u[i + 1] - right_gap * stretch);
        let width = u1 - u0;
        let radius = 0.3 * width;
        // Long edges are split first, so that a bend between their ends is seen.
        let max_step = (piece.width / 2.0).min(set.exemplar_height / 4.0).max(1e-9);
        let tolerance = tolerance.max(1e-9 * set.exemplar_height);
        // Each height lies in at most two weights' supports: with each
        // bend's slope across the band held to a quarter, `v` keeps
        // increasing with the exemplar's height, so the map never folds
        // material over itself (a fold splits or merges parts the plan
        // counted). Worked out once per piece, not per point.
        // A bend adds its whole slope change at the seam, over a radius
        // short enough for that: `|∂bend/∂v|` is at most `|c|·r·0.26 /
        // support`. Held to the piece's radius before (0.3 of its width),
        // the cap left the slope change unmade where a steep stroke met a
        // neighbour close above or below it, and a kink at the seam.
        let min_radius = (MIN_BEND_RADIUS * set.exemplar_height * stretch).min(radius);
        let capped = |bends: &[Bend]| -> Vec<CappedBend> {
            bends
                .iter()
                .map(|b| {
                    let support = (b.above - b.at).min(b.at - b.below).max(1e-12);
                    let reach = MAX_FOLD_SLOPE * support / FALLOFF_PEAK;
                    let radius_b = (reach / b.coefficient.abs().max(1e-12)).min(radius).max(min_radius).max(1e-12);
                    let cap = reach / radius_b;
                    CappedBend {
                        at: b.at,
                        above: (b.above - b.at).max(1e-12),
                        below: (b.at - b.below).max(1e-12),
                        coefficient: b.coefficient.clamp(-cap, cap),
                        radius: radius_b,
                    }
                })
                .collect()
        };
        let (left_capped, right_capped) = (capped(&left_bends[i]), capped(&right_bends[i]));
        // The shortest bend radius at each cut, in the exemplar's `x`.
        let x_per_u = piece.width / width.max(1e-12);
        let shortest = |bends: &[CappedBend]| bends.iter().map(|b| b.radius * x_per_u).fold(f64::INFINITY, f64::min);
        let (left_reach, right_reach) = (shortest(&left_capped), shortest(&right_capped));
        let place = |p: DVec2| -> DVec2 {
            // Points on a cut must land exactly on the seam line, whatever
            // rounding the clipping left in them.
            let t = if (p.x - piece.u_start).abs() <= snap {
                0.0
            } else if (p.x - piece.u_end()).abs() <= snap {
                1.0
            } else {
                ((p.x - piece.u_start) / piece.width).clamp(0.0, 1.0)
            };
            let u = (1.0 - t) * u0 + t * u1;
            let h = smoothstep(t);
            let left = left_maps[i].value(p.y);
            let right = right_maps[i].value(p.y);
            let mut v = (1.0 - h) * left + h * right;
            let mut bend = 0.0;
            for (bends, seam) in [(&left_capped, u0), (&right_capped, u1)] {
                let distance = (u - seam).abs();
                if distance >= radius {
                    continue;
                }
                for b in bends.iter() {
                    let x = distance / b.radius;
                    if x >= 1.0 {
                        continue;
                    }
                    let falloff = (1.0 - x) * (1.0 - x) * (1.0 + 2.0 * x);
                    let weight = if v >= b.at {
                        (1.0 - (v - b.at) / b.above).clamp(0.0, 1.0)
                    } else {
                        (1.0 - (b.at - v) / b.below).clamp(0.0, 1.0)
                    };
                    bend += b.coefficient * (u - seam) * falloff * weight;
                }
            }
            v += bend;
            // Endpoints on a seam take the shared target itself, to the last
            // bit, so that both sides weld wherever they are mapped.
            let targets = if t == 0.0 {
                &left_targets[i]
            } else if t == 1.0 {
                &right_targets[i]
            } else {
                &no_targets
            };
            if let Some(&target) = targets.iter().find(|&&target| (v - target).abs() <= snap_v) {
                v = target;
            }
            DVec2::new(u, v)
        };
        let cuts = [(piece.u_start, left_reach), (piece.u_end(), right_reach)];
        let splits = |a: DVec2, b: DVec2, out: &mut Vec<f64>| split_near_cuts(a, b, cuts, snap, out);
        let deform =
            |ring: &Vec<DVec2>| refine_mapped_thinned_split(ring, place, max_step, tolerance, 0.5 * tolerance, splits);
        let polygons = piece
            .region
            .polygons
            .iter()
            .map(|polygon| Polygon { outer: deform(&polygon.outer), holes: polygon.holes.iter().map(deform).collect() })
            .collect();
        // Sampled clear of the cuts, where `place` snaps points onto the
        // seam line; the step is far below any feature and far above the
        // rounding of `place`.
        let distortion = Distortion::sample(
            &piece.region.polygons,
            (piece.u_start, piece.u_end()),
            (4.0 * snap).max(1e-3 * piece.width),
            1e-5 * set.exemplar_height,
            place,
        );
        (polygons, distortion)
    };
    let (polygons, distortions): (Vec<Vec<Polygon>>, Vec<Distortion>) =
        pieces.par_iter().enumerate().map(deformed).unzip();
    let seams = seam_u[1..n].to_vec();
    let ends = (curve == CurveKind::Closed).then_some([0.0, length]);
    let region = joined_pieces(polygons.into_iter().flatten().collect(), &seams, ends);
    BandPattern { region, length, seams, curve, distortion: Distortion::join(distortions), seam_gaps }
}
