//! The search (the paper's sections 1.3 to 1.5): the positions of all
//! pieces that minimize the summed mismatch Ω of their seams, by dynamic
//! programming over valid positions, exactly.
//!
//! The edge cost D of a seam is the sum of the pixel cost ξ along it: γ
//! where an opaque pixel meets a transparent one, the RGB distance where two
//! opaque pixels meet, and nothing where two transparent ones do (their
//! colour is not seen; the paper compares it too). Opacity along an edge is
//! a bit mask, so the γ part of D is a population count, the same for all
//! previous positions whose right edges have the same mask. A row of the
//! table first tries the positions that continue the exemplar, then visits
//! the groups cheapest first, and each group's positions cheapest first,
//! and stops as soon as nothing left can beat the best found; a colour sum
//! stops as soon as it cannot either.
//! Every cut is exact: the table is the paper's.
//!
//! Loops are solved exactly where the paper approximates: see [`search`].

use rayon::prelude::*;

use super::{PieceSamples, Placements, Position, RasterError, RasterExemplar};
use crate::control::Control;

/// The cost of an opaque pixel meeting a transparent one (the paper's γ).
pub const GAMMA: f32 = 1024.0;

/// The cost of a seam that does not continue the exemplar (a jump to
/// another part of it): worth two mismatched pixels. Without it, a uniform
/// stretch of an exemplar (a chain's straight link, a vine's bare stem)
/// matches itself at no cost, and the cheapest pattern repeats it forever.
pub const JUMP_COST: f64 = 2.0 * GAMMA as f64;

/// The most searches with a fixed start a loop may take to prove its cycle
/// the cheapest; past them the best found is kept, with its gap bound.
pub const MAX_FIXED_STARTS: usize = 4;

/// Opacity (a bit mask) and colours along one edge, for every valid
/// position of a piece.
pub struct EdgeTable {
    count: usize,
    words: usize,
    len: usize,
    alpha: Vec<u64>,
    rgb: Vec<[u8; 3]>,
}

impl EdgeTable {
    fn gather(exemplar: &RasterExemplar, positions: &[Position], offsets: &[(i32, i32)]) -> EdgeTable {
        let len = offsets.len();
        let words = len.div_ceil(64);
        let mut alpha = vec![0u64; words * positions.len()];
        let mut rgb = vec![[0u8; 3]; len * positions.len()];
        for (p, &(x, y)) in positions.iter().enumerate() {
            for (k, &(dx, dy)) in offsets.iter().enumerate() {
                let (px, py) = (i64::from(x + dx), i64::from(y + dy));
                if exemplar.is_opaque(px, py) {
                    alpha[p * words + k / 64] |= 1 << (k % 64);
                    let c = exemplar.pixel(px, py);
                    rgb[p * len + k] = [c[0], c[1], c[2]];
                }
            }
        }
        EdgeTable { count: positions.len(), words, len, alpha, rgb }
    }

    /// The left edges (the paper's L̄) of pieces at `positions`.
    pub fn left(exemplar: &RasterExemplar, positions: &[Position], column_px: usize) -> EdgeTable {
        let offsets: Vec<(i32, i32)> = (0..column_px as i32).map(|k| (0, k)).collect();
        EdgeTable::gather(exemplar, positions, &offsets)
    }

    /// The right edges (R̄) of a piece with `samples` at `positions`.
    pub fn right(exemplar: &RasterExemplar, positions: &[Position], samples: &PieceSamples) -> EdgeTable {
        EdgeTable::gather(exemplar, positions, &samples.right)
    }

    /// Positions in the table.
    pub fn count(&self) -> usize {
        self.count
    }

    /// Whether sample `k` of position `p` is opaque, and its colour.
    pub fn sample(&self, p: usize, k: usize) -> (bool, [u8; 3]) {
        (self.alpha[p * self.words + k / 64] >> (k % 64) & 1 == 1, self.rgb[p * self.len + k])
    }
}

/// The pixel cost ξ of two samples (opacity, colour): γ where opacity
/// differs, the RGB distance between two opaque ones, 0 between two
/// transparent ones.
pub fn pixel_cost(a: (bool, [u8; 3]), b: (bool, [u8; 3])) -> f32 {
    match (a.0, b.0) {
        (true, true) => rgb_distance(a.1, b.1),
        (false, false) => 0.0,
        _ => GAMMA,
    }
}

fn rgb_distance(a: [u8; 3], b: [u8; 3]) -> f32 {
    let d = |k: usize| f32::from(a[k]) - f32::from(b[k]);
    (d(0) * d(0) + d(1) * d(1) + d(2) * d(2)).sqrt()
}

/// The γ part of D: opacity mismatches between right edge `v` and left edge `u`.
fn mismatch_cost(right_alpha: &[u64], left: &EdgeTable, u: usize) -> f32 {
    let la = &left.alpha[u * left.words..][..left.words];
    let mismatched: u32 = right_alpha.iter().zip(la).map(|(a, b)| (a ^ b).count_ones()).sum();
    GAMMA * mismatched as f32
}

/// The colour part of D between right edge `v` and left edge `u` (where
/// both are opaque), or some value at least `bound` once it reaches it.
fn colour_cost(right: &EdgeTable, v: usize, left: &EdgeTable, u: usize, bound: f32) -> f32 {
    let (ra, la) = (&right.alpha[v * right.words..][..right.words], &left.alpha[u * left.words..][..left.words]);
    let (rc, lc) = (&right.rgb[v * right.len..][..right.len], &left.rgb[u * left.len..][..left.len]);
    let mut cost = 0.0;
    for (w, (a, b)) in ra.iter().zip(la).enumerate() {
        let mut both = a & b;
        while both != 0 {
            let k = 64 * w + both.trailing_zeros() as usize;
            both &= both - 1;
            cost += rgb_distance(rc[k], lc[k]);
            if cost >= bound {
                return cost;
            }
        }
    }
    cost
}

/// The edge cost D between right edge `v` of `right` and left edge `u` of
/// `left`, or some value at least `bound` once it reaches `bound`.
pub fn edge_cost(right: &EdgeTable, v: usize, left: &EdgeTable, u: usize, bound: f32) -> f32 {
    let mismatch = mismatch_cost(&right.alpha[v * right.words..][..right.words], left, u);
    if mismatch >= bound {
        return mismatch;
    }
    mismatch + colour_cost(right, v, left, u, bound - mismatch)
}

/// The previous piece's positions grouped by the opacity of their right
/// edges: the γ part of D is the same for a whole group, so a group whose
/// cheapest member plus it cannot beat the best found is skipped whole.
struct Groups {
    /// Each group's opacity mask (as the index of a member), cheapest cost
    /// and members, cheapest first.
    groups: Vec<(usize, f64, Vec<u32>)>,
}

impl Groups {
    fn new(prev: &[f64], right: &EdgeTable) -> Groups {
        let mut order: Vec<u32> = (0..prev.len() as u32).filter(|&v| prev[v as usize].is_finite()).collect();
        order.sort_unstable_by(|&a, &b| prev[a as usize].total_cmp(&prev[b as usize]));
        let mut index: rustc_hash::FxHashMap<&[u64], usize> = rustc_hash::FxHashMap::default();
        let mut groups: Vec<(usize, f64, Vec<u32>)> = Vec::new();
        for v in order {
            let mask = &right.alpha[v as usize * right.words..][..right.words];
            let g = *index.entry(mask).or_insert_with(|| {
                groups.push((v as usize, prev[v as usize], Vec::new()));
                groups.len() - 1
            });
            groups[g].2.push(v);
        }
        Groups { groups }
    }
}

/// Where the next piece continues the exemplar from a previous piece at
/// `v`: its left edge on the previous right edge's top, give or take a pixel.
fn continues(v: Position, u: Position, step: (i32, i32)) -> bool {
    (u.0 - v.0 - step.0).abs() <= 1 && (u.1 - v.1 - step.1).abs() <= 1
}

/// One row of the table (equation 1): for every position `u` of the next
/// piece, the cheapest `prev[v] + D(v, u)` (plus [`JUMP_COST`] unless `u`
/// continues `v`) and its `v`. `step` is the previous piece's right edge's
/// top, rounded: where a continuing piece starts.
fn relax(row: Row<'_>, right: &EdgeTable, left: &EdgeTable) -> (Vec<f64>, Vec<u32>) {
    let Row { prev, prev_positions, positions, step } = row;
    let groups = Groups::new(prev, right);
    let index: rustc_hash::FxHashMap<Position, u32> =
        prev_positions.iter().enumerate().filter(|(v, _)| prev[*v].is_finite()).map(|(v, &p)| (p, v as u32)).collect();
    (0..left.count())
        .into_par_iter()
        .map(|u| {
            let (mut best, mut arg) = (f64::INFINITY, u32::MAX);
            // Continuations first: they pay no jump, so the best is often
            // among them and everything else is cut early.
            let at = positions[u];
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let Some(&v) = index.get(&(at.0 - step.0 + dx, at.1 - step.1 + dy)) else { continue };
                    let room = (best - prev[v as usize]).min(f64::from(f32::MAX)) as f32;
                    if room <= 0.0 {
                        continue;
                    }
                    let total = prev[v as usize] + f64::from(edge_cost(right, v as usize, left, u, room));
                    if total < best {
                        (best, arg) = (total, v);
                    }
                }
            }
            // Groups come cheapest first: once even a group's cheapest
            // member plus a jump cannot win, no later group can.
            for (mask, cheapest, members) in &groups.groups {
                if cheapest + JUMP_COST >= best {
                    break;
                }
                let mismatch = mismatch_cost(&right.alpha[mask * right.words..][..right.words], left, u);
                if cheapest + f64::from(mismatch) + JUMP_COST >= best {
                    continue;
                }
                for &v in members {
                    if continues(prev_positions[v as usize], at, step) {
                        continue;
                    }
                    let base = prev[v as usize] + f64::from(mismatch) + JUMP_COST;
                    if base >= best {
                        break;
                    }
                    let room = (best - base).min(f64::from(f32::MAX)) as f32;
                    let total = base + f64::from(colour_cost(right, v as usize, left, u, room));
                    if total < best {
                        (best, arg) = (total, v);
                    }
                }
            }
            (best, arg)
        })
        .unzip()
}

/// What one row of the table needs besides the edges.
#[derive(Clone, Copy)]
struct Row<'a> {
    prev: &'a [f64],
    prev_positions: &'a [Position],
    positions: &'a [Position],
    step: (i32, i32),
}

/// Whether a piece at `u` continues the exemplar from the previous piece at
/// `v`, whose samples are `samples`.
pub fn is_continuation(samples: &PieceSamples, v: Position, u: Position) -> bool {
    continues(v, u, samples.step())
}

/// How a loop's pattern was closed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Closure {
    /// An open curve.
    Open,
    /// The cheapest cycle, proven.
    Exact,
    /// The cheapest cycle found within [`MAX_FIXED_STARTS`] searches; the
    /// optimum is at most `gap` (a fraction of its cost) cheaper.
    Bounded {
        /// Upper bound of the relative gap to the optimum.
        gap: f64,
    },
}

/// The chosen positions.
#[derive(Clone, Debug, PartialEq)]
pub struct Path {
    /// Index of each piece's position in its placements.
    pub chosen: Vec<usize>,
    /// Each piece's position in the exemplar.
    pub positions: Vec<Position>,
    /// Ω: the summed edge cost of every seam (a loop's closing one included).
    pub cost: f64,
    /// How a loop was closed.
    pub closure: Closure,
}

struct Table {
    /// For every piece after the first, each position's best predecessor.
    args: Vec<Vec<u32>>,
    /// The last row.
    last: Vec<f64>,
}

impl Table {
    fn backtrack(&self, end: usize) -> Vec<usize> {
        let mut chosen = vec![end];
        for arg in self.args.iter().rev() {
            chosen.push(arg[*chosen.last().unwrap_or(&0)] as usize);
        }
        chosen.reverse();
        chosen
    }
}

/// Fills the table over the pieces (and, on loops, a terminal copy of the
/// first), from every start or from `start` only.
fn fill(
    exemplar: &RasterExemplar,
    samples: &[PieceSamples],
    placements: &[Placements],
    column_px: usize,
    closed: bool,
    start: Option<usize>,
    control: &Control,
) -> Result<Table, RasterError> {
    let n = placements.len();
    let rows = if closed { n + 1 } else { n };
    let bias = |row: usize, k: usize| placements[row].bias.get(k).copied().unwrap_or(0.0);
    let mut p: Vec<f64> = match start {
        None => (0..placements[0].positions.len()).map(|k| bias(0, k)).collect(),
        Some(s) => {
            (0..placements[0].positions.len()).map(|k| if k == s { bias(0, k) } else { f64::INFINITY }).collect()
        }
    };
    let mut args = Vec::with_capacity(rows);
    let mut right = EdgeTable::right(exemplar, &placements[0].positions, &samples[0]);
    for i in 1..rows {
        control.check()?;
        let piece = i % n;
        let left = EdgeTable::left(exemplar, &placements[piece].positions, column_px);
        let row = Row {
            prev: &p,
            prev_positions: &placements[i - 1].positions,
            positions: &placements[piece].positions,
            step: samples[i - 1].step(),
        };
        let (mut next, arg) = relax(row, &right, &left);
        // A loop's terminal is the first piece again, whose own cost is
        // already in the first row.
        if i < n && !placements[piece].bias.is_empty() {
            for (k, cost) in next.iter_mut().enumerate() {
                *cost += bias(piece, k);
            }
        }
        args.push(arg);
        p = next;
        if i < n {
            right = EdgeTable::right(exemplar, &placements[i].positions, &samples[i]);
        }
        control.report(i as f32 / rows as f32);
    }
    Ok(Table { args, last: p })
}

/// The positions of every piece with the least Ω. On a loop the last
/// piece's right edge also meets the first piece's left edge.
pub fn search(
    exemplar: &RasterExemplar,
    samples: &[PieceSamples],
    placements: &[Placements],
    column_px: usize,
    closed: bool,
    control: &Control,
) -> Result<Path, RasterError> {
    let path = |mut chosen: Vec<usize>, cost: f64, closure: Closure| {
        if closed {
            // The terminal is the first piece again.
            chosen.pop();
        }
        let positions = chosen.iter().enumerate().map(|(i, &k)| placements[i].positions[k]).collect();
        Path { chosen, positions, cost, closure }
    };
    let table = fill(exemplar, samples, placements, column_px, closed, None, control)?;
    if !closed {
        let end = (0..table.last.len()).min_by(|&a, &b| table.last[a].total_cmp(&table.last[b])).unwrap_or(0);
        return Ok(path(table.backtrack(end), table.last[end], Closure::Open));
    }
    // The unconstrained table's last row is a lower bound for every cycle
    // through a terminal position: the cheapest path that ends there,
    // wherever it starts. Terminals are taken cheapest first; a terminal
    // whose path already starts where it ends is its best cycle, any other
    // gets a search with its start fixed; once the bound of the next
    // terminal reaches the best cycle found, that cycle is the optimum.
    let mut ends: Vec<usize> = (0..table.last.len()).filter(|&j| table.last[j].is_finite()).collect();
    ends.sort_unstable_by(|&a, &b| table.last[a].total_cmp(&table.last[b]));
    let mut best: Option<(f64, Vec<usize>)> = None;
    let mut fixed_searches = 0;
    let mut closure = Closure::Exact;
    for &end in &ends {
        let bound = table.last[end];
        if best.as_ref().is_some_and(|(c, _)| bound >= *c) {
            break;
        }
        let chosen = table.backtrack(end);
        let (cost, chosen) = if chosen[0] == end {
            (bound, chosen)
        } else {
            if fixed_searches == MAX_FIXED_STARTS {
                // Not proven: the best cycle found is within `gap` of the optimum.
                let found = best.as_ref().map_or(f64::INFINITY, |(c, _)| *c);
                closure = Closure::Bounded { gap: (found - bound) / found.max(f64::MIN_POSITIVE) };
                break;
            }
            fixed_searches += 1;
            let fixed = fill(exemplar, samples, placements, column_px, true, Some(end), control)?;
            (fixed.last[end], fixed.backtrack(end))
        };
        if cost.is_finite() && best.as_ref().is_none_or(|(c, _)| cost < *c) {
            best = Some((cost, chosen));
        }
    }
    let (cost, chosen) = best.ok_or(RasterError::Unplaceable { piece: 0, at_mm: 0.0 })?;
    Ok(path(chosen, cost, closure))
}
