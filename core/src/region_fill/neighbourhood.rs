//! Neighbourhoods and their similarity (section 4.2 of the curve-texture
//! paper): the samples within a radius of a sample, compared with another
//! pattern's by robust matching, where each pair costs the difference of
//! their offsets from the centres plus the difference of their edges.

use glam::DVec2;
use pathfinding::kuhn_munkres::kuhn_munkres;
use pathfinding::matrix::Matrix;
use rustc_hash::FxHashMap;
use smallvec::SmallVec;

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

    /// The first of [`SampleGrid::within`], found ring of cells by ring
    /// outward, without gathering and sorting the rest: the search asks
    /// this for windows up to half the exemplar wide.
    pub fn nearest(&self, graph: &SampleGraph, centre: DVec2, radius_mm: f64) -> Option<u32> {
        self.nearest_where(graph, centre, radius_mm, &|_| true)
    }

    /// As [`SampleGrid::nearest`], among the samples `wanted` accepts.
    pub fn nearest_where(
        &self,
        graph: &SampleGraph,
        centre: DVec2,
        radius_mm: f64,
        wanted: &dyn Fn(u32) -> bool,
    ) -> Option<u32> {
        let reach = (radius_mm / self.cell_mm).ceil() as i64;
        let (cx, cy) = cell_of(centre, self.cell_mm);
        let mut best: Option<(f64, u32)> = None;
        for ring in 0..=reach {
            // Points in ring `ring` lie more than `ring - 1` cells from the
            // centre, which may sit anywhere in its own cell.
            if best.is_some_and(|(d, _)| d <= (ring - 1) as f64 * self.cell_mm) {
                break;
            }
            for dx in -ring..=ring {
                for dy in -ring..=ring {
                    if dx.abs() != ring && dy.abs() != ring {
                        continue;
                    }
                    for &s in self.cells.get(&(cx + dx, cy + dy)).map_or(&[][..], |v| &v[..]) {
                        let d = graph.samples[s as usize].position_mm.distance(centre);
                        if d <= radius_mm && best.is_none_or(|b| (d, s) < b) && wanted(s) {
                            best = Some((d, s));
                        }
                    }
                }
            }
        }
        best.map(|(_, s)| s)
    }
}

fn cell_of(p: DVec2, cell_mm: f64) -> (i64, i64) {
    ((p.x / cell_mm).floor() as i64, (p.y / cell_mm).floor() as i64)
}

/// Edges a sample has at most before [`edge_difference`] leaves the
/// exhaustive matching for Kuhn–Munkres.
const EXHAUSTIVE_EDGES: usize = 4;

/// A sample's edges as vectors to its neighbours, mm.
pub type EdgeVectors = SmallVec<[DVec2; 4]>;

/// The edges of sample `s` as vectors to its neighbours, mm.
fn sample_edges(graph: &SampleGraph, s: usize) -> EdgeVectors {
    let p = graph.samples[s].position_mm;
    graph.neighbours[s].iter().map(|&n| graph.samples[n as usize].position_mm - p).collect()
}

/// Every sample's edges as vectors to its neighbours, mm: found once per
/// graph and step, since the search compares each sample's edges many times.
pub fn edge_vectors(graph: &SampleGraph) -> Vec<EdgeVectors> {
    (0..graph.samples.len()).map(|s| sample_edges(graph, s)).collect()
}

/// The least sum of `|rows[r] − columns[c]|` over one-to-one matchings of
/// every row, trying them all: samples have few edges (two along a path,
/// three or four at a junction), and this is called for every pair of
/// samples the search compares.
fn least_matching_sum(rows: &[DVec2], columns: &[DVec2], used: &mut [bool; 8]) -> f64 {
    // The usual cases, without the recursion: an end, or a path sample
    // against a path sample.
    match (rows, columns) {
        ([a], _) if !used.iter().any(|&u| u) => {
            return columns.iter().map(|c| a.distance(*c)).fold(f64::INFINITY, f64::min);
        }
        ([a, b], [c, d]) => return (a.distance(*c) + b.distance(*d)).min(a.distance(*d) + b.distance(*c)),
        _ => {}
    }
    let Some((first, rest)) = rows.split_first() else {
        return 0.0;
    };
    let mut best = f64::INFINITY;
    for c in 0..columns.len() {
        if used[c] {
            continue;
        }
        let here = first.distance(columns[c]);
        if here >= best {
            continue;
        }
        used[c] = true;
        best = best.min(here + least_matching_sum(rest, columns, used));
        used[c] = false;
    }
    best
}

/// How differently samples `a` of `graph_a` and `b` of `graph_b` are
/// connected (equation 5): their edge vectors matched one to one to
/// minimize the sum of differences, that sum, plus `beta_mm` for each edge
/// one has more than the other. A sample without edges (newly added to an
/// output) differs from nothing: 0. Up to four edges a side every matching
/// is tried; more go to Kuhn–Munkres.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, SampleGraph, edge_difference};
/// let line = SampleGraph::new(&[CurvePath { points_mm: vec![DVec2::ZERO, DVec2::new(4.0, 0.0)], closed: false }], 1.0).unwrap();
/// // An inner sample (two edges) against an end (one edge): one edge matched exactly, one extra.
/// assert!((edge_difference(&line, 2, &line, 0, 1.0) - 1.0).abs() < 1e-9);
/// ```
pub fn edge_difference(graph_a: &SampleGraph, a: usize, graph_b: &SampleGraph, b: usize, beta_mm: f64) -> f64 {
    edges_difference(&sample_edges(graph_a, a), &sample_edges(graph_b, b), beta_mm)
}

/// [`edge_difference`] of two samples' edge vectors.
fn edges_difference(ea: &[DVec2], eb: &[DVec2], beta_mm: f64) -> f64 {
    if ea.is_empty() {
        return 0.0;
    }
    let (rows, columns) = if ea.len() <= eb.len() { (&ea, &eb) } else { (&eb, &ea) };
    let extra = beta_mm * (columns.len() - rows.len()) as f64;
    if rows.is_empty() {
        return extra;
    }
    if columns.len() <= EXHAUSTIVE_EDGES {
        return least_matching_sum(rows, columns, &mut [false; 8]) + extra;
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
    /// The cost of leaving a discrete element's sample unmatched, mm.
    pub element_unmatched_mm: f64,
}

impl Similarity {
    /// Comparisons at sample spacing `delta_mm`; an element left unmatched
    /// costs as much as a path sample without edges.
    pub fn new(delta_mm: f64) -> Similarity {
        Similarity { delta_mm, element_unmatched_mm: 1.2 * delta_mm }
    }

    /// The same, with an element left unmatched costing `cost_mm`.
    pub fn with_element_unmatched(self, cost_mm: f64) -> Similarity {
        Similarity { element_unmatched_mm: cost_mm, ..self }
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
    let (output_edges, input_edges) = (edge_vectors(output), edge_vectors(input));
    let pair = NeighbourhoodPair {
        output,
        output_edges: &output_edges,
        s_o,
        members_o,
        input,
        input_edges: &input_edges,
        s_i,
        members_i,
    };
    pair.distance_below(similarity, f64::INFINITY).unwrap_or(Matching { input_of: Vec::new(), cost: f64::INFINITY })
}

/// Two neighbourhoods to compare: output sample `s_o` with its members,
/// and input sample `s_i` with its.
#[derive(Clone, Copy, Debug)]
pub struct NeighbourhoodPair<'a> {
    /// The output graph.
    pub output: &'a SampleGraph,
    /// Its samples' edges ([`edge_vectors`]).
    pub output_edges: &'a [EdgeVectors],
    /// The output neighbourhood's centre.
    pub s_o: usize,
    /// The output neighbourhood's samples.
    pub members_o: &'a [u32],
    /// The input graph.
    pub input: &'a SampleGraph,
    /// Its samples' edges ([`edge_vectors`]).
    pub input_edges: &'a [EdgeVectors],
    /// The input neighbourhood's centre.
    pub s_i: usize,
    /// The input neighbourhood's samples.
    pub members_i: &'a [u32],
}

impl NeighbourhoodPair<'_> {
    /// [`neighbourhood_distance`], or `None` as soon as it is sure to be at
    /// least `bound`: each output sample costs at least its cheapest pair or
    /// its unmatched cost, whichever is less, and the offsets alone are
    /// checked against that before the edges are compared. The search
    /// rejects most candidates this way without solving the assignment.
    pub fn distance_below(&self, similarity: &Similarity, bound: f64) -> Option<Matching> {
        let (output, input) = (self.output, self.input);
        let (n, m) = (self.members_o.len(), self.members_i.len());
        // Only samples of one kind match (section 4.2.3): paths with paths,
        // and an element with elements of its kind.
        if output.samples[self.s_o].element != input.samples[self.s_i].element {
            return None;
        }
        let (centre_o, centre_i) = (output.samples[self.s_o].position_mm, input.samples[self.s_i].position_mm);
        let offsets_i: SmallVec<[DVec2; 64]> =
            self.members_i.iter().map(|&s| input.samples[s as usize].position_mm - centre_i).collect();
        let unmatched: SmallVec<[f64; 64]> = self
            .members_o
            .iter()
            .map(|&s| match output.samples[s as usize].element {
                Some(_) => similarity.element_unmatched_mm,
                None => unmatched_cost(output, s as usize, similarity.delta_mm),
            })
            .collect();
        let mut costs: SmallVec<[f64; 1024]> = smallvec::smallvec![0.0; n * m];
        let mut lower = 0.0;
        let mut row_least: SmallVec<[f64; 64]> = SmallVec::with_capacity(n);
        for (o, &so) in self.members_o.iter().enumerate() {
            let offset_o = output.samples[so as usize].position_mm - centre_o;
            let row = &mut costs[o * m..(o + 1) * m];
            let mut least = unmatched[o];
            let kind = output.samples[so as usize].element;
            for ((c, offset_i), &si) in row.iter_mut().zip(&offsets_i).zip(self.members_i) {
                *c = if input.samples[si as usize].element == kind {
                    offset_o.distance(*offset_i)
                } else {
                    f64::INFINITY
                };
                least = least.min(*c);
            }
            row_least.push(least);
            lower += least;
        }
        if lower >= bound {
            return None;
        }
        // Row by row, each row's offsets-only least gives way to its least
        // with edges; the bound is checked after each.
        for (o, &so) in self.members_o.iter().enumerate() {
            let row = &mut costs[o * m..(o + 1) * m];
            let mut least = unmatched[o];
            for (c, &si) in row.iter_mut().zip(self.members_i) {
                // A pair dearer than leaving the output sample unmatched is
                // never better than that (there is an unmatched place for
                // every row), so it is forbidden without comparing its edges.
                if *c < unmatched[o] {
                    *c += EDGE_WEIGHT
                        * edges_difference(
                            &self.output_edges[so as usize],
                            &self.input_edges[si as usize],
                            similarity.delta_mm,
                        );
                }
                if *c >= unmatched[o] {
                    *c = f64::INFINITY;
                }
                least = least.min(*c);
            }
            lower += least - row_least[o];
            if lower >= bound {
                return None;
            }
        }
        // Inputs no output sample may match are left out of the assignment.
        let useful: SmallVec<[usize; 64]> = (0..m).filter(|&i| (0..n).any(|o| costs[o * m + i].is_finite())).collect();
        let matching = robust_match(n, useful.len(), &|o, k| costs[o * m + useful[k]], &unmatched);
        Some(Matching {
            input_of: matching.input_of.into_iter().map(|k| k.map(|k| useful[k])).collect(),
            cost: matching.cost,
        })
    }
}
