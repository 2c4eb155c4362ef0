//! Neighbourhoods and their similarity (section 4.2 of the curve-texture
//! paper): the samples within a radius of a sample, compared with another
//! pattern's by robust matching, where each pair costs the difference of
//! their offsets from the centres plus the difference of their edges.

use glam::DVec2;
use pathfinding::kuhn_munkres::kuhn_munkres;
use pathfinding::matrix::Matrix;
use rustc_hash::FxHashMap;

use super::{Matching, SampleGraph, robust_match};

/// Weight of the edge difference against the offset difference (the
/// paper's γ).
pub const EDGE_WEIGHT: f64 = 0.5;

/// Finds the samples of a graph near a point, on a grid of square cells.
#[derive(Clone, Debug)]
pub struct SampleGrid {
    cell_mm: f64,
    cells: FxHashMap<(i64, i64), Vec<u32>>,
}

impl SampleGrid {
    /// The samples of `graph` in cells `cell_mm` wide (about a neighbourhood's radius).
    pub fn new(graph: &SampleGraph, cell_mm: f64) -> SampleGrid {
        let mut cells: FxHashMap<(i64, i64), Vec<u32>> = FxHashMap::default();
        let cell_mm = cell_mm.max(1e-9);
        for (s, sample) in graph.samples.iter().enumerate() {
            cells.entry(cell_of(sample.position_mm, cell_mm)).or_default().push(s as u32);
        }
        SampleGrid { cell_mm, cells }
    }

    /// The samples of `graph` (the one the grid was made from) within
    /// `radius_mm` of `centre`, nearest first.
    pub fn within(&self, graph: &SampleGraph, centre: DVec2, radius_mm: f64) -> Vec<u32> {
        let reach = (radius_mm / self.cell_mm).ceil() as i64;
        let (cx, cy) = cell_of(centre, self.cell_mm);
        let mut found: Vec<(f64, u32)> = Vec::new();
        for dx in -reach..=reach {
            for dy in -reach..=reach {
                for &s in self.cells.get(&(cx + dx, cy + dy)).map_or(&[][..], |v| &v[..]) {
                    let d = graph.samples[s as usize].position_mm.distance(centre);
                    if d <= radius_mm {
                        found.push((d, s));
                    }
                }
            }
        }
        found.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        found.into_iter().map(|(_, s)| s).collect()
    }
}

fn cell_of(p: DVec2, cell_mm: f64) -> (i64, i64) {
    ((p.x / cell_mm).floor() as i64, (p.y / cell_mm).floor() as i64)
}

/// The edges of sample `s` as vectors to its neighbours, mm.
fn edge_vectors(graph: &SampleGraph, s: usize) -> Vec<DVec2> {
    let p = graph.samples[s].position_mm;
    graph.neighbours[s].iter().map(|&n| graph.samples[n as usize].position_mm - p).collect()
}

/// How differently samples `a` of `graph_a` and `b` of `graph_b` are
/// connected (equation 5): their edge vectors matched one to one to
/// minimize the sum of differences (Kuhn–Munkres), that sum, plus
/// `beta_mm` for each edge one has more than the other. A sample without
/// edges (newly added to an output) differs from nothing: 0.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, SampleGraph, edge_difference};
/// let line = SampleGraph::new(&[CurvePath { points_mm: vec![DVec2::ZERO, DVec2::new(4.0, 0.0)], closed: false }], 1.0).unwrap();
/// // An inner sample (two edges) against an end (one edge): one edge matched exactly, one extra.
/// assert!((edge_difference(&line, 2, &line, 0, 1.0) - 1.0).abs() < 1e-9);
/// ```
pub fn edge_difference(graph_a: &SampleGraph, a: usize, graph_b: &SampleGraph, b: usize, beta_mm: f64) -> f64 {
    let (ea, eb) = (edge_vectors(graph_a, a), edge_vectors(graph_b, b));
    if ea.is_empty() {
        return 0.0;
    }
    let (rows, columns) = if ea.len() <= eb.len() { (&ea, &eb) } else { (&eb, &ea) };
    let extra = beta_mm * (columns.len() - rows.len()) as f64;
    if rows.is_empty() {
        return extra;
    }
    // Nanometres, as integers for the solver; maximizing the negated sum.
    let weights =
        Matrix::from_fn(rows.len(), columns.len(), |(r, c)| -((rows[r].distance(columns[c]) * 1e6).round() as i64));
    let (_, assignment) = kuhn_munkres(&weights);
    let matched: f64 = assignment.iter().enumerate().map(|(r, &c)| rows[r].distance(columns[c])).sum();
    matched + extra
}

/// What a neighbourhood comparison needs besides the two patterns.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Similarity {
    /// Sample spacing at this level, mm: the paper's β, and the scale of
    /// the cost of leaving a sample unmatched.
    pub delta_mm: f64,
}

impl Similarity {
    /// Comparisons at sample spacing `delta_mm`.
    pub fn new(delta_mm: f64) -> Similarity {
        Similarity { delta_mm }
    }
}

/// The cost of leaving output sample `s` unmatched: `min(2, 1.2 + 0.4 |E(s)|) δ`,
/// so that a well-connected sample is kept matched more readily.
pub fn unmatched_cost(graph: &SampleGraph, s: usize, delta_mm: f64) -> f64 {
    (1.2 + 0.4 * graph.neighbours[s].len() as f64).min(2.0) * delta_mm
}

/// How unlike the neighbourhood `members_o` of output sample `s_o` is to
/// the neighbourhood `members_i` of input sample `s_i` (equation 7), and
/// how their samples match. Offsets are taken from each centre, so the
/// two patterns may lie anywhere.
pub fn neighbourhood_distance(
    output: &SampleGraph,
    s_o: usize,
    members_o: &[u32],
    input: &SampleGraph,
    s_i: usize,
    members_i: &[u32],
    similarity: &Similarity,
) -> Matching {
    let (centre_o, centre_i) = (output.samples[s_o].position_mm, input.samples[s_i].position_mm);
    let cost = |o: usize, i: usize| {
        let (so, si) = (members_o[o] as usize, members_i[i] as usize);
        let offset_o = output.samples[so].position_mm - centre_o;
        let offset_i = input.samples[si].position_mm - centre_i;
        offset_o.distance(offset_i) + EDGE_WEIGHT * edge_difference(output, so, input, si, similarity.delta_mm)
    };
    let unmatched: Vec<f64> =
        members_o.iter().map(|&s| unmatched_cost(output, s as usize, similarity.delta_mm)).collect();
    robust_match(members_o.len(), members_i.len(), &cost, &unmatched)
}
