//! Geometry matching (the paper's section 2.3): the swatch tried at every
//! grid translation that puts the seed cell inside it, each scored by
//! D = (1 + λ·dist)(1 + |Δn|) both ways, from the output's points to the
//! swatch and from the swatch's points to the output, then refined off the
//! grid. The plane and curved bases share it: on a curved base the search
//! runs in a patch laid flat, and the swatch's points are carried to the
//! output through the patch.

use rustc_hash::FxHashMap;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use super::faces::Faces;
use super::{Element, Settings, Swatch};
use crate::random::SplitMix64;

/// Output vertices sampled for the matching cost of one placement: enough
/// to tell placements apart, few enough to try dozens per patch.
pub(super) const MATCH_SAMPLES: usize = 400;

/// Cells at the swatch's edge that a patch overlaps but does not claim:
/// elements there are often cut short by the swatch's own border.
pub(super) const MARGIN_CELLS: i64 = 1;

/// The swatch indexed for matching: its faces, and its vertices by cell.
pub(super) struct Input {
    pub faces: Faces,
    by_cell: FxHashMap<(i64, i64), Vec<(DVec3, DVec3)>>,
    /// Whole cells across the swatch, along `x` and `y`.
    pub cells: (i64, i64),
    pub cell_mm: f64,
}

impl Input {
    /// `swatch` indexed on cells `cell_mm` wide.
    pub fn new(swatch: &Swatch, cell_mm: f64) -> Input {
        let mut by_cell: FxHashMap<(i64, i64), Vec<(DVec3, DVec3)>> = FxHashMap::default();
        for e in &swatch.elements {
            for (v, n) in e.vertices.iter().zip(e.vertex_normals()) {
                let c = ((v.x / cell_mm).floor() as i64, (v.y / cell_mm).floor() as i64);
                by_cell.entry(c).or_default().push((*v, n));
            }
        }
        let size = swatch.size_mm();
        let cells = ((size.x / cell_mm).floor() as i64, (size.y / cell_mm).floor() as i64);
        Input { faces: Faces::new(&swatch.elements), by_cell, cells, cell_mm }
    }

    /// Cells around the seed, each way, that matching compares.
    pub fn window_half(&self) -> i64 {
        let (sx, sy) = self.cells;
        ((sx.min(sy) - 2 * MARGIN_CELLS - 1) / 4).max(0)
    }
}

/// The output around a seed, as matching sees it.
pub(super) struct Neighbourhood<'a> {
    /// Processed cells around the seed (the seed's frame).
    pub window: &'a [(i64, i64)],
    /// Output points in the window with their normals (the seed's frame).
    pub samples: Vec<(DVec3, DVec3)>,
    /// The output's faces near the window (output space).
    pub faces: Faces,
}

/// Every `stride`-th of `points`, at most [`MATCH_SAMPLES`] of them.
pub(super) fn thin<T: Copy>(points: Vec<T>) -> Vec<T> {
    let stride = points.len().div_ceil(MATCH_SAMPLES).max(1);
    points.into_iter().step_by(stride).collect()
}

/// The matching cost of one pair of a point and its closest face (the
/// paper's equation 1), with distance measured in grid cells.
fn pair_cost(distance_mm: f64, normal: DVec3, face_normal: DVec3, lambda: f64, cell_mm: f64) -> f64 {
    (1.0 + lambda * distance_mm / cell_mm) * (1.0 + (normal - face_normal).length())
}

/// The matching cost of a point with normal `normal` against its closest
/// of `faces`; a point with none costs as one two cells off.
fn closest_cost(faces: &Faces, point_mm: DVec3, normal: DVec3, lambda: f64, cell_mm: f64) -> f64 {
    match faces.closest(point_mm) {
        Some(hit) => pair_cost(hit.distance_mm, normal, hit.normal, lambda, cell_mm),
        None => pair_cost(2.0 * cell_mm, normal, normal, lambda, cell_mm),
    }
}

/// The best translation of the swatch for the patch around `seed`: the grid
/// offset `(a, b)` in cells, and the placement refined from it (turned
/// too when `turn`; each good offset searched off the grid before one is
/// picked when `refine_each`). `to_output` carries a point and normal of
/// the seed's frame to output space, or says it falls off the base.
#[allow(clippy::too_many_arguments)]
pub(super) fn best_translation(
    input: &Input,
    around: &Neighbourhood,
    seed: (i64, i64),
    settings: &Settings,
    reach_mm: f64,
    to_output: impl Fn(DVec3, DVec3) -> Option<(DVec3, DVec3)> + Sync,
    (turn, refine_each): (bool, bool),
    random: &mut SplitMix64,
) -> (i64, i64, Placement) {
    let (sx, sy) = input.cells;
    let half = input.window_half();
    let c = input.cell_mm;
    let low = (seed.0 + half + MARGIN_CELLS + 1 - sx, seed.1 + half + MARGIN_CELLS + 1 - sy);
    let high = (seed.0 - half - MARGIN_CELLS, seed.1 - half - MARGIN_CELLS);
    let candidates: Vec<(i64, i64)> = (low.1..=high.1).flat_map(|b| (low.0..=high.0).map(move |a| (a, b))).collect();
    let (window, samples) = (around.window, &around.samples);
    let lambda = settings.lambda;
    // The least cost found so far, shared by the threads: a candidate is
    // given up as soon as it is sure to cost more than the tolerance above
    // it. Every pair costs at least 1 (equation 1), so a partial sum plus 1
    // for each pair still to come is a lower bound of the whole. The best
    // found only falls, so a candidate given up would have been left out of
    // the good ones anyway: the choice is the same as scoring every one.
    let least = AtomicU64::new(f64::INFINITY.to_bits());
    let tolerance = settings.tolerance;
    let beyond = |lower: f64| {
        let limit = f64::from_bits(least.load(Ordering::Relaxed)) * (1.0 + tolerance) + 1e-9;
        lower > limit * (1.0 + 1e-12)
    };
    let cost = |&(a, b): &(i64, i64)| -> f64 {
        if window.is_empty() {
            return 0.0;
        }
        let t = DVec3::new(a as f64 * c, b as f64 * c, 0.0);
        let mut reverse = Vec::new();
        for &(i, j) in window {
            if let Some(points) = input.by_cell.get(&(i - a, j - b)) {
                reverse.extend(points.iter().map(|&(p, n)| (p + t, n)));
            }
        }
        let reverse = thin(reverse);
        let reverse_least = if reverse.is_empty() { 0.0 } else { 1.0 };
        let (ns, nr) = (samples.len().max(1) as f64, reverse.len().max(1) as f64);
        let mut forward = 0.0;
        for (k, &(p, n)) in samples.iter().enumerate() {
            forward += closest_cost(&input.faces, p - t, n, lambda, c);
            if beyond((forward + (samples.len() - k - 1) as f64) / ns + reverse_least) {
                return f64::INFINITY;
            }
        }
        let forward = forward / ns;
        let mut back = 0.0;
        for (k, &(p, n)) in reverse.iter().enumerate() {
            back += match to_output(p, n) {
                Some((q, m)) => closest_cost(&around.faces, q, m, lambda, c),
                None => pair_cost(2.0 * c, n, n, lambda, c),
            };
            if beyond(forward + (back + (reverse.len() - k - 1) as f64) / nr) {
                return f64::INFINITY;
            }
        }
        let total = forward + back / nr;
        least.fetch_min(total.to_bits(), Ordering::Relaxed);
        total
    };
    let costs: Vec<f64> = candidates.par_iter().map(cost).collect();
    let best = costs.iter().copied().fold(f64::INFINITY, f64::min);
    let good: Vec<usize> =
        (0..candidates.len()).filter(|&k| costs[k] <= best * (1.0 + settings.tolerance) + 1e-9).collect();
    // On a curved base the grid's offsets hold the output's elements only
    // to within half a cell, so the best of them may be half a cell off
    // and the others about as good: one picked at random among them was
    // often a whole cell off, which the search off the grid (below) cannot
    // reach. For a swatch whose elements hang on each other
    // (`refine_each`), each is searched off the grid first, and the pick is
    // made among the best of those: on the cylinder, chain mail's matched
    // links then lie 0.35 mm apart at the median patch, 1.1 mm before.
    let grid_offset = |k: usize| DVec2::new(candidates[k].0 as f64 * c, candidates[k].1 as f64 * c);
    // Each good offset with where the search off the grid took it, when
    // `refine_each`; the grid's offset alone otherwise.
    let good: Vec<(usize, Option<DVec2>)> = if refine_each && good.len() > 1 {
        let refined: Vec<(DVec2, f64)> =
            good.par_iter().map(|&k| finest_offset(input, samples, grid_offset(k), lambda)).collect();
        let best = refined.iter().map(|&(_, cost)| cost).fold(f64::INFINITY, f64::min);
        good.iter()
            .zip(&refined)
            .filter(|&(_, &(_, cost))| cost <= best * (1.0 + settings.tolerance) + 1e-9)
            .map(|(&k, &(offset, _))| (k, Some(offset)))
            .collect()
    } else {
        good.into_iter().map(|k| (k, None)).collect()
    };
    let (k, refined) = good[random.below(good.len() as u64) as usize];
    let (a, b) = candidates[k];
    // Refined off the grid by the mean offset of the close pairs: a swatch
    // whose period is not a whole number of cells still lines up. On a
    // curved base the offset is first searched off the grid (the mean of
    // pairs, taken half a cell off, pairs parts of the wrong elements), and
    // the pairs also turn it (a 2D Procrustes fit): the field is matched
    // only at the seed, and straight threads on the flattened patch drift
    // from the neighbour's.
    let offset_mm = match refined {
        Some(offset) => offset,
        None if turn => finest_offset(input, samples, grid_offset(k), lambda).0,
        None => grid_offset(k),
    };
    let mut placement = Placement { offset_mm, turn: DVec2::X };
    for _ in 0..2 {
        let pairs: Vec<(DVec2, DVec2)> = samples
            .iter()
            .filter_map(|&(p, _)| {
                let hit = input.faces.closest(placement.to_swatch(p))?;
                (hit.distance_mm < reach_mm).then(|| (p.truncate(), hit.point_mm.truncate()))
            })
            .collect();
        if pairs.len() < 8 {
            break;
        }
        if turn {
            let n = pairs.len() as f64;
            let (pm, sm) = pairs.iter().fold((DVec2::ZERO, DVec2::ZERO), |(a, b), &(p, q)| (a + p, b + q));
            let (pm, sm) = (pm / n, sm / n);
            let (dot, cross) = pairs.iter().fold((0.0, 0.0), |(d, x), &(p, q)| {
                let (p, q) = (p - pm, q - sm);
                (d + q.dot(p), x + q.perp_dot(p))
            });
            let angle = cross.atan2(dot).clamp(-MAX_TURN, MAX_TURN);
            let turn = DVec2::from_angle(angle);
            let offset = pm - turn.rotate(sm);
            placement =
                Placement { offset_mm: placement.offset_mm + (offset - placement.offset_mm).clamp_length_max(c), turn };
        } else {
            let sum: DVec2 = pairs.iter().map(|&(p, q)| p - placement.offset_mm - placement.turn.rotate(q)).sum();
            placement.offset_mm += (sum / pairs.len() as f64).clamp_length_max(c);
        }
    }
    (a, b, placement)
}

/// Steps of the search off the grid, in cells, and how many steps it
/// tries each way round the best offset so far: every quarter cell within
/// half a cell of the grid's offset, then an eighth and a sixteenth round
/// the best.
const SUBCELL_STEPS: [(f64, i32); 3] = [(0.25, 2), (0.125, 1), (0.0625, 1)];

/// The offset within half a cell of `offset_mm` at which the output's
/// `samples` lie best on the swatch, with its cost (the forward half of
/// equation 1, summed). On a
/// curved base the seed's frame is the patch's own, so the grid's offsets
/// hold the swatch only to within half a cell of where the output's
/// elements lie: the swatch's links then missed the output's by up to
/// 1.7 mm, did not correspond, and crossed them.
fn finest_offset(input: &Input, samples: &[(DVec3, DVec3)], offset_mm: DVec2, lambda: f64) -> (DVec2, f64) {
    let c = input.cell_mm;
    if samples.is_empty() {
        return (offset_mm, 0.0);
    }
    let cost = |offset: DVec2| -> f64 {
        let t = offset.extend(0.0);
        samples.iter().map(|&(p, n)| closest_cost(&input.faces, p - t, n, lambda, c)).sum()
    };
    let mut best = (cost(offset_mm), offset_mm);
    for (step, reach) in SUBCELL_STEPS {
        let centre = best.1;
        let tries: Vec<DVec2> = (-reach..=reach)
            .flat_map(|j| (-reach..=reach).map(move |i| centre + DVec2::new(i as f64, j as f64) * step * c))
            .filter(|&o| o != centre && (o - offset_mm).abs().max_element() <= 0.5 * c + 1e-9)
            .collect();
        let costs: Vec<(f64, DVec2)> = tries.par_iter().map(|&o| (cost(o), o)).collect();
        for candidate in costs {
            if candidate.0 < best.0 {
                best = candidate;
            }
        }
    }
    (best.1, best.0)
}

/// Largest turn the refinement gives a patch, radians.
const MAX_TURN: f64 = 0.3;

/// Where the swatch goes in the seed's frame: turned, then moved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Placement {
    /// The move, mm.
    pub offset_mm: DVec2,
    /// The turn, as a unit vector (`X` for none).
    pub turn: DVec2,
}

impl Placement {
    /// A swatch point in the seed's frame.
    pub fn to_frame(self, p: DVec3) -> DVec3 {
        (self.turn.rotate(p.truncate()) + self.offset_mm).extend(p.z)
    }

    /// A point of the seed's frame in the swatch's.
    pub fn to_swatch(self, p: DVec3) -> DVec3 {
        let turn_back = DVec2::new(self.turn.x, -self.turn.y);
        turn_back.rotate(p.truncate() - self.offset_mm).extend(p.z)
    }
}

/// The swatch's mean edge, times three: how near two surfaces must be to
/// be taken as one.
pub(super) fn reach_mm(swatch: &Swatch) -> f64 {
    3.0 * swatch.elements.iter().map(Element::mean_edge_mm).sum::<f64>() / swatch.elements.len() as f64
}
