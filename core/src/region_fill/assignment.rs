//! The assignment step (section 4.3.4 of the curve-texture paper): every
//! matched pair of neighbourhoods votes on where output samples lie, which
//! exist, and which are joined; the votes are then settled.

use glam::DVec2;
use rustc_hash::FxHashMap;
use smallvec::SmallVec;

use super::{Matching, SampleGraph};

/// One matched pair of neighbourhoods: output sample `centre_o`'s members,
/// input sample `centre_i`'s members, and how they matched.
#[derive(Clone, Debug)]
pub struct MatchedPair {
    /// The output centre.
    pub centre_o: u32,
    /// The output neighbourhood's samples.
    pub members_o: Vec<u32>,
    /// The input centre.
    pub centre_i: u32,
    /// The input neighbourhood's samples.
    pub members_i: Vec<u32>,
    /// Which input member each output member matched.
    pub matching: Matching,
}

/// Sweeps of the position solve: each moves every sample to the mean of
/// where its votes put it.
const POSITION_SWEEPS: usize = 20;

/// Positions (equation 14): each matched pair says that output members
/// should lie from their centre as the matched input members lie from
/// theirs. Solved in the least-squares sense by Jacobi sweeps from the
/// current positions; a sample outside `inside` is pulled back to its
/// nearest point of the domain by `project`. Samples `0..pinned` (drawn by
/// the person) keep their places and only cast votes.
pub fn assign_positions(
    output: &mut SampleGraph,
    input: &SampleGraph,
    pairs: &[MatchedPair],
    pinned: usize,
    project: &dyn Fn(DVec2) -> DVec2,
) {
    // Each vote: (a, b, d) says p(b) - p(a) should be d.
    let mut votes: Vec<(u32, u32, DVec2)> = Vec::new();
    for pair in pairs {
        let centre_i = input.samples[pair.centre_i as usize].position_mm;
        for (k, matched) in pair.matching.input_of.iter().enumerate() {
            let (Some(i), member) = (matched, pair.members_o[k]) else { continue };
            if member == pair.centre_o {
                continue;
            }
            let d = input.samples[pair.members_i[*i] as usize].position_mm - centre_i;
            votes.push((pair.centre_o, member, d));
        }
    }
    let n = output.samples.len();
    for _ in 0..POSITION_SWEEPS {
        let mut sum = vec![DVec2::ZERO; n];
        let mut count = vec![0.0; n];
        for &(a, b, d) in &votes {
            let (pa, pb) = (output.samples[a as usize].position_mm, output.samples[b as usize].position_mm);
            sum[b as usize] += pa + d;
            count[b as usize] += 1.0;
            sum[a as usize] += pb - d;
            count[a as usize] += 1.0;
        }
        for s in pinned..n {
            if count[s] > 0.0 {
                // Half toward the votes' mean: Jacobi sweeps with damping converge on such graphs.
                let target = sum[s] / count[s];
                let p = &mut output.samples[s].position_mm;
                *p = project(0.5 * (*p + target));
            }
        }
    }
}

/// Existence (equation 15): the share of the neighbourhoods holding a
/// sample in which it was matched. The synthesis removes samples below
/// its threshold by [`SampleGraph::retain`].
pub fn existence_votes(samples: usize, pairs: &[MatchedPair]) -> Vec<f64> {
    let (mut held, mut matched) = (vec![0.0; samples], vec![0.0; samples]);
    for pair in pairs {
        for (k, &member) in pair.members_o.iter().enumerate() {
            held[member as usize] += 1.0;
            if pair.matching.input_of[k].is_some() {
                matched[member as usize] += 1.0;
            }
        }
    }
    (0..samples).map(|s| if held[s] > 0.0 { matched[s] / held[s] } else { 1.0 }).collect()
}

/// Edges (equations 16 to 21): each pair votes for an output edge where
/// two members matched two input samples that are joined; an edge's
/// expected confidence is its votes over the pairs holding both ends, and
/// a sample's expected edge count the mean of its matches'. Edges are then
/// taken greedily, most confident first, when taking one brings the
/// confidences and the counts closer (equation 21). Edges between samples
/// `0..pinned` (drawn by the person) are kept as they are, and no other
/// edge joins two of them.
pub fn assign_edges(output: &mut SampleGraph, input: &SampleGraph, pairs: &[MatchedPair], pinned: usize) {
    let n = output.samples.len();
    let drawn: Vec<(u32, u32)> = output.edges_among(pinned);
    let mut votes: FxHashMap<(u32, u32), f64> = FxHashMap::default();
    let (mut degree_sum, mut degree_count) = (vec![0.0; n], vec![0.0; n]);
    for pair in pairs {
        let mut output_of_input: FxHashMap<u32, u32> = FxHashMap::default();
        for (k, matched) in pair.matching.input_of.iter().enumerate() {
            if let Some(i) = matched {
                let (so, si) = (pair.members_o[k], pair.members_i[*i]);
                output_of_input.insert(si, so);
                degree_sum[so as usize] += input.neighbours[si as usize].len() as f64;
                degree_count[so as usize] += 1.0;
            }
        }
        for (&si, &so) in &output_of_input {
            for &sj in &input.neighbours[si as usize] {
                if let Some(&to) = output_of_input.get(&sj)
                    && so < to
                {
                    *votes.entry((so, to)).or_default() += 1.0;
                }
            }
        }
    }
    // How many pairs hold both ends of each voted edge.
    let mut both_held: FxHashMap<(u32, u32), f64> = FxHashMap::default();
    for pair in pairs {
        for (a, &x) in pair.members_o.iter().enumerate() {
            for &y in &pair.members_o[a + 1..] {
                let key = if x < y { (x, y) } else { (y, x) };
                if votes.contains_key(&key) {
                    *both_held.entry(key).or_default() += 1.0;
                }
            }
        }
    }
    let expected_degree: Vec<f64> =
        (0..n).map(|s| if degree_count[s] > 0.0 { degree_sum[s] / degree_count[s] } else { 0.0 }).collect();
    let mut candidates: Vec<((u32, u32), f64)> =
        votes.iter().map(|(&key, &v)| (key, v / both_held.get(&key).copied().unwrap_or(v).max(v))).collect();
    candidates.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
    let mut degree = vec![0usize; n];
    for &(a, b) in &drawn {
        degree[a as usize] += 1;
        degree[b as usize] += 1;
    }
    let mut chosen = drawn;
    for ((a, b), confidence) in candidates {
        if (a as usize) < pinned && (b as usize) < pinned {
            continue;
        }
        let (da, db) = (degree[a as usize] as f64, degree[b as usize] as f64);
        let (ea, eb) = (expected_degree[a as usize], expected_degree[b as usize]);
        let without = confidence + (da - ea).abs() + (db - eb).abs();
        let with = (1.0 - confidence) + (da + 1.0 - ea).abs() + (db + 1.0 - eb).abs();
        if with < without {
            degree[a as usize] += 1;
            degree[b as usize] += 1;
            chosen.push((a, b));
        }
    }
    output.neighbours = vec![SmallVec::new(); n];
    for sample in &mut output.samples {
        sample.orientations.clear();
    }
    for (a, b) in chosen {
        output.connect(a, b);
    }
}

/// Where samples are missing (the paper's Algorithm 1): in each pair, an
/// input member that no output member matched says the output lacks a
/// sample at the same place from its centre. Such candidates are gathered
/// into clusters half a spacing wide; a cluster becomes a sample where it
/// was proposed by more than half of the output neighbourhoods that would
/// hold it, `inside` the domain and not on top of a sample already there.
/// Each comes with its kind (`None` on a path, or an element's kind), and
/// candidates of different kinds are never one cluster.
pub fn missing_samples(
    output: &SampleGraph,
    input: &SampleGraph,
    pairs: &[MatchedPair],
    delta_mm: f64,
    radius_mm: f64,
    inside: &dyn Fn(DVec2) -> bool,
) -> Vec<(DVec2, Option<u32>)> {
    let mut candidates: Vec<(DVec2, Option<u32>)> = Vec::new();
    for pair in pairs {
        let mut used = vec![false; pair.members_i.len()];
        for i in pair.matching.input_of.iter().flatten() {
            used[*i] = true;
        }
        let centre_i = input.samples[pair.centre_i as usize].position_mm;
        let centre_o = output.samples[pair.centre_o as usize].position_mm;
        for (k, &member) in pair.members_i.iter().enumerate() {
            if !used[k] {
                let sample = &input.samples[member as usize];
                candidates.push((sample.position_mm - centre_i + centre_o, sample.element));
            }
        }
    }
    // Greedy clustering: each candidate joins the nearest cluster whose
    // centre is within half a spacing, or starts one.
    let mut clusters: Vec<(DVec2, f64, Option<u32>)> = Vec::new();
    let cell = 0.5 * delta_mm;
    let key = |p: DVec2| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: FxHashMap<(i64, i64), Vec<usize>> = FxHashMap::default();
    for (c, kind) in candidates {
        let (cx, cy) = key(c);
        let mut best: Option<(usize, f64)> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                for &k in grid.get(&(cx + dx, cy + dy)).map_or(&[][..], |v| &v[..]) {
                    let d = (clusters[k].0 / clusters[k].1).distance(c);
                    if clusters[k].2 == kind && d < cell && best.is_none_or(|(_, bd)| d < bd) {
                        best = Some((k, d));
                    }
                }
            }
        }
        match best {
            Some((k, _)) => {
                clusters[k].0 += c;
                clusters[k].1 += 1.0;
            }
            None => {
                grid.entry((cx, cy)).or_default().push(clusters.len());
                clusters.push((c, 1.0, kind));
            }
        }
    }
    let existing = super::SampleGrid::new(output, radius_mm);
    clusters
        .into_iter()
        .filter_map(|(sum, count, kind)| {
            let at = sum / count;
            let holding = existing.within(output, at, radius_mm).len() as f64;
            let crowded = !existing.within(output, at, 0.5 * delta_mm).is_empty();
            (inside(at) && !crowded && holding > 0.0 && count / holding > 0.5).then_some((at, kind))
        })
        .collect()
}
