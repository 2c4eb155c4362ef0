//! Orientation assignment (section 4.3.4 of the curve-texture paper) and
//! the tangents it leaves for reconstruction (section 4.4.2).
//!
//! Each output edge's orientation at each end is voted by the input edges
//! it was matched with: where two members of a matched pair of
//! neighbourhoods are joined in the output and their input matches are
//! joined in the exemplar, the exemplar's tangent there, less its chord,
//! is a vote for how far the output's tangent turns from its own chord.
//! The paper instead matches each sample's orientations to its matches'
//! by a second Hungarian assignment and votes the number of entries too;
//! tying an orientation to its edge needs neither, since the edges'
//! correspondence is already settled, and keeps one orientation per edge
//! in the output as the exemplar has. Votes are relative to the chord
//! because the output's samples do not lie where the exemplar's did: a
//! bend learned as "turns 10° left of the chord" bends alike wherever the
//! chord now points.

use std::f64::consts::PI;

use glam::DVec2;
use rustc_hash::FxHashMap;
use smallvec::SmallVec;

use super::SampleGraph;
use super::assignment::MatchedPair;
use super::fragments::{Place, key};
use super::sample_graph::angle_of;

/// Two orientations at a sample within this angle of opposite run
/// through it: the paper's `8π/9 .. 10π/9`.
pub const THROUGH_TOLERANCE: f64 = PI / 9.0;

/// Sets each output edge's orientations from the votes of `pairs` (see the
/// module notes); an edge with no votes keeps its chord.
pub fn assign_orientations(output: &mut SampleGraph, input: &SampleGraph, pairs: &[MatchedPair]) {
    let mut votes: Vec<SmallVec<[DVec2; 4]>> =
        output.neighbours.iter().map(|around| SmallVec::from_elem(DVec2::ZERO, around.len())).collect();
    let chord = |g: &SampleGraph, a: u32, b: u32| g.samples[b as usize].position_mm - g.samples[a as usize].position_mm;
    for pair in pairs {
        let input_of: FxHashMap<u32, u32> = pair
            .matching
            .input_of
            .iter()
            .enumerate()
            .filter_map(|(k, m)| m.map(|i| (pair.members_o[k], pair.members_i[i])))
            .collect();
        for (&so, &si) in &input_of {
            for (e, &no) in output.neighbours[so as usize].iter().enumerate() {
                let Some(&ni) = input_of.get(&no) else { continue };
                let Some(tangent) = input.orientation_toward(si, ni) else { continue };
                let turn = chord(input, si, ni).angle_to(DVec2::from_angle(tangent));
                votes[so as usize][e] += DVec2::from_angle(turn);
            }
        }
    }
    for (s, around) in output.neighbours.iter().enumerate() {
        for (e, &n) in around.iter().enumerate() {
            let c = chord(output, s as u32, n);
            let v = votes[s][e];
            let turn = if v.length_squared() > 0.0 { v.y.atan2(v.x) } else { 0.0 };
            output.samples[s].orientations[e] = (angle_of(c) + turn).rem_euclid(std::f64::consts::TAU);
        }
    }
}

/// The orientations of a synthesized graph, found by the positions of the
/// samples (to the nanometre, as fragment removal finds paths' ends), for reconstruction after its paths have been cleaned up.
#[derive(Clone, Debug, Default)]
pub struct EdgeTangents {
    /// Each sample's neighbours, with the direction leaving toward each.
    at: FxHashMap<Place, SmallVec<[(Place, DVec2); 4]>>,
}

impl EdgeTangents {
    /// The orientations of `graph`'s edges, each sample moved by `offset_mm`.
    pub fn of(graph: &SampleGraph, offset_mm: DVec2) -> EdgeTangents {
        let mut at: FxHashMap<_, SmallVec<_>> = FxHashMap::default();
        for (s, around) in graph.neighbours.iter().enumerate() {
            let from = key(graph.samples[s].position_mm + offset_mm);
            let list: &mut SmallVec<_> = at.entry(from).or_default();
            for (e, &n) in around.iter().enumerate() {
                let to = key(graph.samples[n as usize].position_mm + offset_mm);
                list.push((to, DVec2::from_angle(graph.samples[s].orientations[e])));
            }
        }
        EdgeTangents { at }
    }

    /// The unit direction of the path leaving `from` toward `to`, if they
    /// are a sample and its neighbour.
    fn toward(&self, from: DVec2, to: DVec2) -> Option<DVec2> {
        let to = key(to);
        self.at.get(&key(from))?.iter().find(|(n, _)| *n == to).map(|(_, d)| *d)
    }

    /// The direction a smooth curve should leave `at` toward `next`: the
    /// edge's orientation, or where the path comes in from `previous` (or,
    /// at a path's end on a junction, from whichever other branch there is
    /// most nearly opposite) running through it within
    /// [`THROUGH_TOLERANCE`], the mean of the two. `None` where the
    /// synthesis left no orientation (a point added after it).
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::region_fill::{EdgeTangents, SampleGraph};
    /// // A T: the bar runs through its middle sample; the stem meets it square.
    /// let mut g = SampleGraph::default();
    /// let (l, m, r, s) = (g.add_sample(-DVec2::X), g.add_sample(DVec2::ZERO), g.add_sample(DVec2::X), g.add_sample(DVec2::NEG_Y));
    /// g.connect(l, m);
    /// g.connect(m, r);
    /// g.connect(m, s);
    /// let t = EdgeTangents::of(&g, DVec2::ZERO);
    /// // The bar's half leaving the junction alone continues its other half.
    /// assert!(t.leaving(None, DVec2::ZERO, DVec2::X).unwrap().abs_diff_eq(DVec2::X, 1e-12));
    /// // The stem has no partner: it leaves along its own edge.
    /// assert!(t.leaving(None, DVec2::ZERO, DVec2::NEG_Y).unwrap().abs_diff_eq(DVec2::NEG_Y, 1e-12));
    /// // Coming in along the stem, the bar is a corner.
    /// assert!(t.leaving(Some(DVec2::NEG_Y), DVec2::ZERO, DVec2::X).unwrap().abs_diff_eq(DVec2::X, 1e-12));
    /// ```
    pub fn leaving(&self, previous: Option<DVec2>, at: DVec2, next: DVec2) -> Option<DVec2> {
        let out = self.toward(at, next)?;
        let through = |d: DVec2| out.dot(-d) >= THROUGH_TOLERANCE.cos();
        let back = match previous {
            Some(p) => self.toward(at, p).filter(|&d| through(d)),
            None => {
                let next = key(next);
                self.at
                    .get(&key(at))?
                    .iter()
                    .filter(|(n, d)| *n != next && through(*d))
                    .map(|(_, d)| *d)
                    .min_by(|a, b| out.dot(*a).total_cmp(&out.dot(*b)))
            }
        };
        Some(back.map_or(out, |b| (out - b).normalize_or(out)))
    }
}
