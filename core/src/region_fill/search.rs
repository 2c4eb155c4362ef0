//! The search step (section 4.3.3 of the curve-texture paper): for every
//! output sample, the input sample whose neighbourhood is most alike, found
//! approximately by PatchMatch over a graph of nearest output samples.

use glam::DVec2;

use super::{EdgeVectors, NeighbourhoodPair, SampleGraph, SampleGrid, Similarity, edge_vectors};
use rayon::prelude::*;

use crate::random::{SplitMix64, mix};

/// Stretches of the visiting order searched at once (see [`search`]).
const SEARCH_STRETCHES: usize = 4;

/// How the search runs.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct SearchSettings {
    /// Neighbourhood radius, mm.
    pub radius_mm: f64,
    /// Sample spacing at this level, mm.
    pub delta_mm: f64,
    /// Passes of propagation and random search.
    pub iterations: usize,
    /// Output samples each one takes candidates from (the paper's k).
    pub nearest: usize,
    /// The random search's first window, as a share of the input's size;
    /// it halves down to [`SearchSettings::min_window_share`].
    pub max_window_share: f64,
    /// The random search's last window, as a share of the input's size.
    pub min_window_share: f64,
    /// Seed of the random choices.
    pub seed: u64,
    /// The cost of leaving a discrete element's sample unmatched, mm
    /// ([`Similarity::element_unmatched_mm`]).
    pub element_unmatched_mm: f64,
}

impl SearchSettings {
    /// The paper's settings (k = 8; windows 150 down to 25 on inputs
    /// about 300 wide) for neighbourhoods of `radius_mm` at spacing `delta_mm`.
    pub fn new(radius_mm: f64, delta_mm: f64) -> SearchSettings {
        SearchSettings {
            radius_mm,
            delta_mm,
            iterations: 5,
            nearest: 8,
            max_window_share: 0.5,
            min_window_share: 0.08,
            seed: 1,
            element_unmatched_mm: Similarity::new(delta_mm).element_unmatched_mm,
        }
    }
}

/// The input samples of each kind (paths, or each kind of element), for
/// starting an output sample's search at a random sample it may match.
pub(super) struct KindIndex {
    by_kind: rustc_hash::FxHashMap<Option<u32>, Vec<u32>>,
    /// Samples in all.
    samples: usize,
}

impl KindIndex {
    pub(super) fn new(input: &SampleGraph) -> KindIndex {
        let mut by_kind: rustc_hash::FxHashMap<Option<u32>, Vec<u32>> = Default::default();
        for (s, sample) in input.samples.iter().enumerate() {
            by_kind.entry(sample.element).or_default().push(s as u32);
        }
        KindIndex { by_kind, samples: input.samples.len() }
    }

    /// The input samples of kind `kind`, if there are any.
    pub(super) fn of(&self, kind: Option<u32>) -> Option<&[u32]> {
        self.by_kind.get(&kind).map(Vec::as_slice)
    }

    /// A random input sample of kind `kind`; any sample if there is none.
    pub(super) fn random(&self, kind: Option<u32>, rng: &mut SplitMix64) -> u32 {
        let all = self.samples.max(1);
        match self.of(kind) {
            Some(of_kind) => of_kind[(rng.next_unit() * of_kind.len() as f64) as usize % of_kind.len()],
            None => (rng.next_unit() * all as f64) as u32 % all as u32,
        }
    }
}

/// The nearest-neighbour field: for each output sample, its input sample
/// and the cost of their neighbourhoods' match.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NearestField {
    /// The input sample of each output sample.
    pub input_of: Vec<u32>,
    /// The neighbourhood distance of each pair.
    pub cost: Vec<f64>,
}

impl NearestField {
    /// Keeps the entries of the output samples `keep` says (as
    /// [`SampleGraph::retain`] keeps the samples).
    pub fn retain(&mut self, keep: &[bool]) {
        self.input_of = kept(&self.input_of, keep);
        self.cost = kept(&self.cost, keep);
    }
}

/// The `values` whose entry in `keep` is true.
fn kept<T: Copy>(values: &[T], keep: &[bool]) -> Vec<T> {
    values.iter().zip(keep).filter(|(_, k)| **k).map(|(v, _)| *v).collect()
}

/// Every sample's neighbourhood in a graph, and the grid that found them:
/// found once for the search and the assignment that follows it (and for
/// an exemplar, once for every step of a level).
#[derive(Clone, Debug)]
pub struct Neighbourhoods {
    /// The graph's samples on a grid, for finding samples near a point.
    pub grid: SampleGrid,
    /// Each sample's neighbourhood: the samples within the radius, nearest first.
    pub members: Vec<Vec<u32>>,
    /// Each sample's edges as vectors ([`edge_vectors`]).
    pub edges: Vec<EdgeVectors>,
}

impl Neighbourhoods {
    /// The neighbourhoods of radius `radius_mm` of every sample of `graph`.
    pub fn new(graph: &SampleGraph, radius_mm: f64) -> Neighbourhoods {
        let grid = SampleGrid::new(graph, radius_mm);
        let members = graph.samples.iter().map(|s| grid.within(graph, s.position_mm, radius_mm)).collect();
        Neighbourhoods { grid, members, edges: edge_vectors(graph) }
    }
}

/// PatchMatch: starting from `start` (the previous step's field) or at
/// random, each pass visits the output samples breadth first over their
/// nearest-sample graph (forward, then backward), and tries for each the
/// input sample its neighbours' matches suggest (propagation) and ones
/// near its own match in shrinking windows (random search), keeping the
/// cheapest by [`neighbourhood_distance`]. Both graphs' neighbourhoods
/// must be of `settings.radius_mm`.
pub fn search(
    (output, output_near): (&SampleGraph, &Neighbourhoods),
    (input, input_near): (&SampleGraph, &Neighbourhoods),
    start: Option<&NearestField>,
    settings: &SearchSettings,
) -> NearestField {
    let n_out = output.samples.len();
    if n_out == 0 || input.samples.is_empty() {
        return NearestField::default();
    }
    let similarity = Similarity::new(settings.delta_mm).with_element_unmatched(settings.element_unmatched_mm);
    let (low, high) = input
        .samples
        .iter()
        .fold((DVec2::MAX, DVec2::MIN), |(lo, hi), s| (lo.min(s.position_mm), hi.max(s.position_mm)));
    let input_size_mm = (high - low).max_element().max(settings.delta_mm);
    // The input sample of kind `kind` nearest a point, if any lies within reach.
    let nearest_input = |p: DVec2, reach_mm: f64, kind: Option<u32>| {
        input_near.grid.nearest_where(input, p, reach_mm, &|s| input.samples[s as usize].element == kind)
    };
    let of_kind = KindIndex::new(input);
    let nearest: Vec<Vec<u32>> = (0..n_out)
        .map(|s| {
            let reach = 2.0 * settings.radius_mm;
            let found = output_near.grid.within(output, output.samples[s].position_mm, reach);
            found.into_iter().filter(|&n| n as usize != s).take(settings.nearest).collect()
        })
        .collect();
    let order = breadth_first(&nearest);
    let mut stream = SplitMix64::new(settings.seed);
    // The cost of matching output sample `o` to input sample `i`, or
    // infinity once it is sure to be at least `bound`.
    let cost_below = |o: usize, i: u32, bound: f64| {
        let i = i as usize;
        let pair = NeighbourhoodPair {
            output,
            output_edges: &output_near.edges,
            input_edges: &input_near.edges,
            s_o: o,
            members_o: &output_near.members[o],
            input,
            s_i: i,
            members_i: &input_near.members[i],
        };
        pair.distance_below(&similarity, bound).map_or(f64::INFINITY, |m| m.cost)
    };
    let cost_of = |o: usize, i: u32| cost_below(o, i, f64::INFINITY);
    let mut field = match start {
        // The previous step's matches, scored again: the samples have moved since.
        Some(f) if f.input_of.len() == n_out => {
            let cost = f.input_of.par_iter().enumerate().map(|(o, &i)| cost_of(o, i)).collect();
            NearestField { input_of: f.input_of.clone(), cost }
        }
        _ => {
            // At random, among the inputs of each output sample's kind.
            let input_of: Vec<u32> = (0..n_out)
                .map(|o| match of_kind.of(output.samples[o].element) {
                    Some(like) => like[stream.below(like.len() as u64) as usize],
                    None => stream.below(input.samples.len() as u64) as u32,
                })
                .collect();
            let cost = input_of.par_iter().enumerate().map(|(o, &i)| cost_of(o, i)).collect();
            NearestField { input_of, cost }
        }
    };
    // Propagation, then random search, for output sample `o`.
    // `tried` holds the inputs already scored for `o` in this search: the
    // output does not move during a search, so a candidate that lost once
    // loses again against a match that can only have got cheaper.
    let visit_sample = |o: usize, field: &mut NearestField, tried: &mut Vec<u32>, stream: &mut SplitMix64| {
        let here = output.samples[o].position_mm;
        let kind = output.samples[o].element;
        let mut try_candidate = |field: &mut NearestField, i: u32| {
            if i == field.input_of[o] || tried.contains(&i) {
                return;
            }
            tried.push(i);
            let c = cost_below(o, i, field.cost[o]);
            if c < field.cost[o] {
                field.input_of[o] = i;
                field.cost[o] = c;
            }
        };
        // Propagation: where a neighbour's match says this sample's should be.
        for &n in &nearest[o] {
            let matched = input.samples[field.input_of[n as usize] as usize].position_mm;
            let guess = matched + (here - output.samples[n as usize].position_mm);
            if let Some(i) = nearest_input(guess, settings.delta_mm, kind) {
                try_candidate(field, i);
            }
        }
        // Random search round the current match, in shrinking windows.
        let mut window = settings.max_window_share * input_size_mm;
        while window >= settings.min_window_share * input_size_mm {
            let around = input.samples[field.input_of[o] as usize].position_mm;
            let signed = |s: &mut SplitMix64| 2.0 * s.next_unit() - 1.0;
            let guess = around + DVec2::new(signed(stream), signed(stream)) * window;
            if let Some(i) = nearest_input(guess, window, kind) {
                try_candidate(field, i);
            }
            window *= 0.5;
        }
    };
    let mut tried: Vec<Vec<u32>> = field.input_of.iter().map(|&i| vec![i]).collect();
    for pass in 0..settings.iterations {
        // The visiting order in stretches, each searched by its own thread
        // against the field as the pass found it (and its own updates):
        // stretches of a breadth-first order are patches of the output, so
        // matches still propagate within each. A fixed number of stretches
        // keeps the result the same on any number of cores.
        let mut visit: Vec<u32> = order.clone();
        if pass % 2 == 1 {
            visit.reverse();
        }
        let stretch = visit.len().div_ceil(SEARCH_STRETCHES).max(1);
        let (snapshot, tried_before) = (&field, &tried);
        let updates: Vec<Vec<Visited>> = visit
            .par_chunks(stretch)
            .enumerate()
            .map(|(k, chunk)| {
                let mut local = snapshot.clone();
                let mut stream = SplitMix64::new(mix(settings.seed ^ mix(((pass as u64) << 32) | k as u64)));
                chunk
                    .iter()
                    .map(|&o| {
                        let o = o as usize;
                        let mut tried_o = tried_before[o].clone();
                        visit_sample(o, &mut local, &mut tried_o, &mut stream);
                        (o, local.input_of[o], local.cost[o], tried_o)
                    })
                    .collect()
            })
            .collect();
        for (o, i, c, tried_o) in updates.into_iter().flatten() {
            field.input_of[o] = i;
            field.cost[o] = c;
            tried[o] = tried_o;
        }
    }
    field
}

/// What visiting one output sample found: the sample, its match and that
/// match's cost, and the inputs tried for it so far.
type Visited = (usize, u32, f64, Vec<u32>);

/// Every sample once, breadth first over `nearest` from the first sample
/// of each connected part.
fn breadth_first(nearest: &[Vec<u32>]) -> Vec<u32> {
    let mut seen = vec![false; nearest.len()];
    let mut order = Vec::with_capacity(nearest.len());
    for start in 0..nearest.len() {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut queue = std::collections::VecDeque::from([start as u32]);
        while let Some(s) = queue.pop_front() {
            order.push(s);
            for &n in &nearest[s as usize] {
                if !seen[n as usize] {
                    seen[n as usize] = true;
                    queue.push_back(n);
                }
            }
        }
    }
    order
}
