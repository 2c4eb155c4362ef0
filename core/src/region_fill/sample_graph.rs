//! [`SampleGraph`]: a curve pattern as point samples joined by edges (section
//! 4.1 of the curve-texture paper): samples where paths meet or cross, at
//! path ends, and every `δ` along paths, each with the tangent directions of
//! the paths through it.

use glam::DVec2;
use smallvec::SmallVec;

use super::{CORNER_TURN, CurvePath};
use crate::curve::Curve;
use crate::disjoint_sets::DisjointSets;
use crate::geom::closest_on_segment;

/// What a sample is, by the number of its edges.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SampleKind {
    /// The end of a path (one edge).
    End,
    /// A sample along a path (two edges, opposite directions).
    Path,
    /// Where three or more path branches meet (a crossing has four).
    Junction,
}

/// One sample of a pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct Sample {
    /// Position, mm.
    pub position_mm: DVec2,
    /// The direction of each path branch leaving the sample, radians in
    /// `[0, 2π)`: one per edge in an exemplar.
    pub orientations: SmallVec<[f64; 4]>,
    /// Confidence that the sample exists, `0..=1` (1 in an exemplar).
    pub existence: f64,
    /// The kind of discrete element this sample stands for, at its centre
    /// (the paper's id `q`); `None` for a sample of a path. Samples match
    /// only samples of the same kind.
    pub element: Option<u32>,
}

/// A pattern's samples and the edges between them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SampleGraph {
    /// The samples.
    pub samples: Vec<Sample>,
    /// Each sample's neighbours along the paths.
    pub neighbours: Vec<SmallVec<[u32; 4]>>,
}

/// The share of a sample spacing over which a path's tangent is read at a
/// sample (and over which a turn counts as a corner).
pub const TANGENT_REACH_SPACINGS: f64 = 0.25;

/// The angle of `v` in `[0, 2π)`.
pub(super) fn angle_of(v: DVec2) -> f64 {
    v.y.atan2(v.x).rem_euclid(std::f64::consts::TAU)
}

/// Points closer than this are one point when paths are cut where they
/// meet, mm: a path drawn to end on another is taken to join it.
pub const JOIN_TOLERANCE_MM: f64 = 0.05;

/// Why a pattern could not be sampled.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SampleError {
    /// The spacing is not a positive length.
    #[error("the sample spacing must be a positive number of millimetres, not {0}")]
    Spacing(f64),
    /// Too many segments to find where they cross in reasonable time.
    #[error("the curve exemplar has {segments} straight pieces; at most {limit} are sampled: simplify it")]
    TooLarge {
        /// Segments found.
        segments: usize,
        /// The most allowed.
        limit: usize,
    },
}

/// Most segments whose crossings are searched (pairwise, pruned by boxes).
pub const MAX_SEGMENTS: usize = 20_000;

/// A cut of a path: where, as the index of its segment and the share along
/// it, and which junction point it belongs to.
#[derive(Clone, Copy, Debug)]
struct Cut {
    segment: usize,
    t: f64,
    point: usize,
}

impl SampleGraph {
    /// Samples `paths` every `delta_mm` at most along each stretch between
    /// cuts (ends, crossings, and ends that touch another path).
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::region_fill::{CurvePath, SampleGraph, SampleKind};
    /// // Two lines crossing in a plus sign.
    /// let line = |a: DVec2, b: DVec2| CurvePath { points_mm: vec![a, b], closed: false };
    /// let plus = [line(DVec2::new(-5.0, 0.0), DVec2::new(5.0, 0.0)), line(DVec2::new(0.0, -5.0), DVec2::new(0.0, 5.0))];
    /// let graph = SampleGraph::new(&plus, 1.0).unwrap();
    /// let junctions = (0..graph.samples.len()).filter(|&s| graph.kind(s) == SampleKind::Junction).count();
    /// assert_eq!(junctions, 1);
    /// assert_eq!(graph.samples.len(), 21);
    /// ```
    pub fn new(paths: &[CurvePath], delta_mm: f64) -> Result<SampleGraph, SampleError> {
        let reach = TANGENT_REACH_SPACINGS * delta_mm;
        SampleGraph::sampled(paths, delta_mm, &|path: &CurvePath| super::corner_vertices(path, reach, CORNER_TURN))
    }

    /// As [`SampleGraph::new`], without cutting paths at their corners: for
    /// a synthesized pattern sampled again at the next level, whose sharp
    /// turns are mostly the coarse level's chords rather than corners
    /// drawn. (Cutting there too, by the turn or by the coarse level's
    /// orientations, changed the synthesis of the built-ins without
    /// corners and left the scales and spirals with gaps; see
    /// `docs/region-fill.md`.)
    pub fn new_without_corners(paths: &[CurvePath], delta_mm: f64) -> Result<SampleGraph, SampleError> {
        SampleGraph::sampled(paths, delta_mm, &|_: &CurvePath| Vec::new())
    }

    /// Samples `paths`, cutting each at the vertices `corners` finds.
    fn sampled(
        paths: &[CurvePath],
        delta_mm: f64,
        corners: &dyn Fn(&CurvePath) -> Vec<usize>,
    ) -> Result<SampleGraph, SampleError> {
        if !(delta_mm.is_finite() && delta_mm > 0.0) {
            return Err(SampleError::Spacing(delta_mm));
        }
        let paths: Vec<&CurvePath> = paths.iter().filter(|p| p.points_mm.len() >= 2).collect();
        let segments: usize = paths.iter().map(|p| p.segment_count()).sum();
        if segments > MAX_SEGMENTS {
            return Err(SampleError::TooLarge { segments, limit: MAX_SEGMENTS });
        }
        let (cuts, points) = find_cuts(&paths, corners);
        let mut graph = SampleGraph::default();
        // Junction points become samples first, shared by every path through them.
        let mut point_sample = vec![u32::MAX; points.len()];
        for (path_index, path) in paths.iter().enumerate() {
            let mut path_cuts: Vec<Cut> = cuts[path_index].clone();
            path_cuts
                .sort_by(|a, b| (a.segment, a.t).partial_cmp(&(b.segment, b.t)).unwrap_or(std::cmp::Ordering::Equal));
            path_cuts.dedup_by(|a, b| a.point == b.point && a.segment == b.segment);
            graph.sample_path(path, &path_cuts, &points, &mut point_sample, delta_mm);
        }
        Ok(graph)
    }

    /// How many edges sample `s` has, as a kind.
    pub fn kind(&self, s: usize) -> SampleKind {
        match self.neighbours[s].len() {
            0 | 1 => SampleKind::End,
            2 => SampleKind::Path,
            _ => SampleKind::Junction,
        }
    }

    /// The edges, each once, as pairs of sample indices (smaller first).
    pub fn edges(&self) -> Vec<[u32; 2]> {
        let mut out = Vec::new();
        for (s, around) in self.neighbours.iter().enumerate() {
            out.extend(around.iter().filter(|&&n| n as usize > s).map(|&n| [s as u32, n]));
        }
        out
    }

    /// The graph as paths: a path from each end or junction along plain
    /// samples (two edges) to the next end or junction, and a closed path
    /// for each loop of plain samples. Every edge is in exactly one path.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::region_fill::{CurvePath, SampleGraph};
    /// let line = |a: DVec2, b: DVec2| CurvePath { points_mm: vec![a, b], closed: false };
    /// let plus = SampleGraph::new(&[line(DVec2::new(-5.0, 0.0), DVec2::new(5.0, 0.0)), line(DVec2::new(0.0, -5.0), DVec2::new(0.0, 5.0))], 1.0).unwrap();
    /// assert_eq!(plus.to_paths().len(), 4);
    /// ```
    pub fn to_paths(&self) -> Vec<CurvePath> {
        let mut used: rustc_hash::FxHashSet<(u32, u32)> = Default::default();
        let key = |a: u32, b: u32| (a.min(b), a.max(b));
        let mut paths = Vec::new();
        let plain = |s: u32| self.neighbours[s as usize].len() == 2;
        let walk = |start: u32, first: u32, used: &mut rustc_hash::FxHashSet<(u32, u32)>| {
            let mut points = vec![self.samples[start as usize].position_mm];
            let (mut previous, mut current) = (start, first);
            used.insert(key(previous, current));
            loop {
                points.push(self.samples[current as usize].position_mm);
                if !plain(current) || current == start {
                    break;
                }
                let Some(&next) = self.neighbours[current as usize].iter().find(|&&n| !used.contains(&key(current, n)))
                else {
                    break;
                };
                used.insert(key(current, next));
                previous = current;
                current = next;
            }
            let _ = previous;
            let closed = current == start && points.len() > 3;
            if closed {
                points.pop();
            }
            CurvePath { points_mm: points, closed }
        };
        for s in 0..self.samples.len() as u32 {
            if plain(s) {
                continue;
            }
            for &t in &self.neighbours[s as usize].clone() {
                if !used.contains(&key(s, t)) {
                    paths.push(walk(s, t, &mut used));
                }
            }
        }
        for s in 0..self.samples.len() as u32 {
            if let Some(&t) = self.neighbours[s as usize].iter().find(|&&t| !used.contains(&key(s, t))) {
                paths.push(walk(s, t, &mut used));
            }
        }
        paths
    }

    /// Adds a sample at `position_mm` with no edges; returns its index.
    pub fn add_sample(&mut self, position_mm: DVec2) -> u32 {
        self.add_of_kind(position_mm, None)
    }

    /// Adds a sample standing for a discrete element of kind `kind`, centred
    /// at `centre_mm`; it never has edges. Returns its index.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::region_fill::SampleGraph;
    /// let mut g = SampleGraph::default();
    /// let dot = g.add_element(DVec2::new(3.0, 4.0), 0);
    /// assert_eq!(g.samples[dot as usize].element, Some(0));
    /// assert!(g.to_paths().is_empty(), "an element is no path");
    /// ```
    pub fn add_element(&mut self, centre_mm: DVec2, kind: u32) -> u32 {
        self.add_of_kind(centre_mm, Some(kind))
    }

    /// Adds a sample of a path (`element` `None`) or an element's centre.
    pub fn add_of_kind(&mut self, position_mm: DVec2, element: Option<u32>) -> u32 {
        self.samples.push(Sample { position_mm, orientations: SmallVec::new(), existence: 1.0, element });
        self.neighbours.push(SmallVec::new());
        (self.samples.len() - 1) as u32
    }

    /// The elements' centres and kinds, in sample order.
    pub fn elements(&self) -> Vec<(DVec2, u32)> {
        self.samples.iter().filter_map(|s| s.element.map(|k| (s.position_mm, k))).collect()
    }

    /// Joins `a` and `b`, recording at each the direction toward the other.
    pub fn connect(&mut self, a: u32, b: u32) {
        let d = self.samples[b as usize].position_mm - self.samples[a as usize].position_mm;
        self.connect_oriented(a, b, angle_of(d), angle_of(-d));
    }

    /// Joins `a` and `b`, the path leaving `a` toward `b` at angle `at_a`
    /// and leaving `b` toward `a` at `at_b` (radians): the tangents of a
    /// curved path rather than the chord between its samples.
    pub fn connect_oriented(&mut self, a: u32, b: u32, at_a: f64, at_b: f64) {
        // An element is whole in itself: no path runs through its centre.
        let element = |s: u32| self.samples[s as usize].element.is_some();
        if a == b || self.neighbours[a as usize].contains(&b) || element(a) || element(b) {
            return;
        }
        self.samples[a as usize].orientations.push(at_a.rem_euclid(std::f64::consts::TAU));
        self.samples[b as usize].orientations.push(at_b.rem_euclid(std::f64::consts::TAU));
        self.neighbours[a as usize].push(b);
        self.neighbours[b as usize].push(a);
    }

    /// The direction of the path leaving `s` along its edge to `n`,
    /// radians; `None` when they are not joined.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::region_fill::SampleGraph;
    /// let mut g = SampleGraph::default();
    /// let (a, b) = (g.add_sample(DVec2::ZERO), g.add_sample(DVec2::Y));
    /// g.connect(a, b);
    /// assert!((g.orientation_toward(a, b).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    /// assert_eq!(g.orientation_toward(a, a), None);
    /// ```
    pub fn orientation_toward(&self, s: u32, n: u32) -> Option<f64> {
        let k = self.neighbours[s as usize].iter().position(|&x| x == n)?;
        self.samples[s as usize].orientations.get(k).copied()
    }

    /// Every edge once (smaller index first), with its orientation at each end.
    fn oriented_edges(&self) -> Vec<(u32, u32, f64, f64)> {
        let mut out = Vec::new();
        for (s, around) in self.neighbours.iter().enumerate() {
            for (k, &n) in around.iter().enumerate() {
                if (n as usize) > s {
                    let at_n = self.orientation_toward(n, s as u32).unwrap_or(0.0);
                    out.push((s as u32, n, self.samples[s].orientations[k], at_n));
                }
            }
        }
        out
    }

    /// The edges between two of the samples `0..count`, each once.
    pub fn edges_among(&self, count: usize) -> Vec<(u32, u32)> {
        let mut edges = Vec::new();
        for (a, around) in self.neighbours.iter().enumerate().take(count) {
            edges.extend(around.iter().filter(|&&b| (b as usize) < count && a < b as usize).map(|&b| (a as u32, b)));
        }
        edges
    }

    /// Removes the edges between two of the samples `0..count`.
    pub fn disconnect_among(&mut self, count: usize) {
        self.disconnect_where(|a, b| (a as usize) < count && (b as usize) < count);
    }

    /// Removes the edges `(a, b)` (`a < b`) that `remove` picks, keeping
    /// the others' orientations.
    pub fn disconnect_where(&mut self, remove: impl Fn(u32, u32) -> bool) {
        let edges = self.oriented_edges();
        self.neighbours = vec![SmallVec::new(); self.samples.len()];
        for sample in &mut self.samples {
            sample.orientations.clear();
        }
        for (a, b, at_a, at_b) in edges {
            if !remove(a, b) {
                self.connect_oriented(a, b, at_a, at_b);
            }
        }
    }

    /// The same graph with the samples `first` marks moved to the front,
    /// each side in its order; also how many were marked.
    pub fn pinned_first(&self, first: &[bool]) -> (SampleGraph, usize) {
        let order: Vec<usize> = (0..self.samples.len())
            .filter(|&s| first[s])
            .chain((0..self.samples.len()).filter(|&s| !first[s]))
            .collect();
        let mut new_index = vec![0u32; self.samples.len()];
        for (k, &s) in order.iter().enumerate() {
            new_index[s] = k as u32;
        }
        let mut graph = SampleGraph::default();
        for &s in &order {
            graph.add_of_kind(self.samples[s].position_mm, self.samples[s].element);
        }
        for (a, b, at_a, at_b) in self.oriented_edges() {
            graph.connect_oriented(new_index[a as usize], new_index[b as usize], at_a, at_b);
        }
        (graph, first.iter().filter(|&&f| f).count())
    }

    /// Keeps the samples `keep` says, with the edges between them.
    pub fn retain(&mut self, keep: &[bool]) {
        let mut new_index = vec![u32::MAX; self.samples.len()];
        let mut next = 0;
        for (s, &k) in keep.iter().enumerate() {
            if k {
                new_index[s] = next;
                next += 1;
            }
        }
        let edges = self.oriented_edges();
        self.neighbours.clear();
        let old_samples = std::mem::take(&mut self.samples);
        for (s, sample) in old_samples.into_iter().enumerate() {
            if keep[s] {
                self.samples.push(Sample { orientations: SmallVec::new(), ..sample });
                self.neighbours.push(SmallVec::new());
            }
        }
        for (s, n, at_s, at_n) in edges {
            let (a, b) = (new_index[s as usize], new_index[n as usize]);
            if a != u32::MAX && b != u32::MAX {
                self.connect_oriented(a, b, at_s, at_n);
            }
        }
    }

    /// The sample of junction point `point`, made on first use.
    fn point_sample(&mut self, point: usize, points: &[DVec2], point_sample: &mut [u32]) -> u32 {
        if point_sample[point] == u32::MAX {
            point_sample[point] = self.add_sample(points[point]);
        }
        point_sample[point]
    }

    /// Samples one path between its cuts (sorted along it).
    fn sample_path(
        &mut self,
        path: &CurvePath,
        cuts: &[Cut],
        points: &[DVec2],
        point_sample: &mut [u32],
        delta_mm: f64,
    ) {
        // Points at arc lengths come from the curve (a path of no length adds nothing).
        let Ok(curve) = Curve::from_polyline(&path.points_mm, path.closed) else { return };
        // Stretches between consecutive cuts; a closed path wraps from its last cut to its first.
        let mut stops: Vec<(f64, u32)> = Vec::new();
        let lengths = path.cumulative_lengths();
        for cut in cuts {
            let s = lengths[cut.segment] + cut.t * path.segment_length(cut.segment);
            let sample = self.point_sample(cut.point, points, point_sample);
            stops.push((s, sample));
        }
        let total = *lengths.last().unwrap_or(&0.0);
        if path.closed && stops.is_empty() {
            // A loop touching nothing: one stretch all around from its start.
            let first = self.add_sample(path.points_mm[0]);
            self.sample_stretch(&curve, 0.0, total, first, first, delta_mm);
            return;
        }
        if path.closed {
            let (s0, first) = stops[0];
            stops.push((s0 + total, first));
        }
        for pair in stops.windows(2) {
            let ((from, a), (to, b)) = (pair[0], pair[1]);
            // Cuts a hair apart at one point (an end near its own path's
            // first segments, as at a spiral's tight centre) leave no loop.
            let loop_back = a == b && to - from <= 4.0 * JOIN_TOLERANCE_MM;
            if !loop_back && (to - from > 1e-12 || a != b) {
                self.sample_stretch(&curve, from, to, a, b, delta_mm);
            }
        }
    }

    /// Samples the stretch of `curve` from arc length `from` to `to` (past
    /// the total for a loop) between samples `a` and `b`.
    fn sample_stretch(&mut self, curve: &Curve, from: f64, to: f64, a: u32, b: u32, delta_mm: f64) {
        let intervals = ((to - from) / delta_mm).ceil().max(1.0) as usize;
        // A loop through one point needs at least three samples to be a loop.
        let intervals = if a == b { intervals.max(3) } else { intervals };
        let step = (to - from) / intervals as f64;
        // Within a stretch the path runs smoothly through each sample: its
        // tangent is read across it, the same both ways. At the stretch's
        // ends (a junction, a corner, an end) it is read on the stretch's
        // side only, over a quarter spacing, so a corner stays a corner;
        // a loop touching nothing has no such end.
        let reach = (TANGENT_REACH_SPACINGS * delta_mm).min(0.5 * step);
        let smooth_ends = a == b && to - from >= curve.length() && curve.is_closed();
        let forward_at = |s: f64, end: bool| {
            let (back, ahead) = (if end { curve.point(s) } else { curve.point(s - reach) }, curve.point(s + reach));
            angle_of(ahead - back)
        };
        let backward_at = |s: f64, end: bool| {
            let (back, ahead) = (curve.point(s - reach), if end { curve.point(s) } else { curve.point(s + reach) });
            angle_of(back - ahead)
        };
        let (mut previous, mut at) = (a, from);
        for k in 1..=intervals {
            let s = if k == intervals { to } else { from + (to - from) * k as f64 / intervals as f64 };
            let next = if k == intervals { b } else { self.add_sample(curve.point(s)) };
            let (start_is_end, stop_is_end) = (k == 1 && !smooth_ends, k == intervals && !smooth_ends);
            self.connect_oriented(previous, next, forward_at(at, start_is_end), backward_at(s, stop_is_end));
            (previous, at) = (next, s);
        }
    }
}

/// Where paths must be cut: their ends, where they cross, and where an end
/// touches another path; all such points merged within
/// [`JOIN_TOLERANCE_MM`]. Returns the cuts per path and the points.
fn find_cuts(paths: &[&CurvePath], corners: &dyn Fn(&CurvePath) -> Vec<usize>) -> (Vec<Vec<Cut>>, Vec<DVec2>) {
    let mut raw: Vec<(usize, Cut, DVec2)> = Vec::new();
    for (p, path) in paths.iter().enumerate() {
        if !path.closed {
            let last = path.segment_count() - 1;
            raw.push((p, Cut { segment: 0, t: 0.0, point: 0 }, path.points_mm[0]));
            raw.push((p, Cut { segment: last, t: 1.0, point: 0 }, *path.points_mm.last().unwrap_or(&DVec2::ZERO)));
        }
    }
    let segments: Vec<(usize, usize, DVec2, DVec2)> = paths
        .iter()
        .enumerate()
        .flat_map(|(p, path)| {
            (0..path.segment_count()).map(move |i| (p, i, path.segment_point(i, 0.0), path.segment_point(i, 1.0)))
        })
        .collect();
    // Crossings, pairwise with a box test; neighbouring segments of one path meet at their shared vertex, not a crossing.
    for (i, &(pa, ia, a0, a1)) in segments.iter().enumerate() {
        for &(pb, ib, b0, b1) in &segments[i + 1..] {
            if pa == pb && (ib == ia + 1 || (paths[pa].closed && ia == 0 && ib == paths[pa].segment_count() - 1)) {
                continue;
            }
            if a0.max(a1).cmplt(b0.min(b1) - JOIN_TOLERANCE_MM).any()
                || b0.max(b1).cmplt(a0.min(a1) - JOIN_TOLERANCE_MM).any()
            {
                continue;
            }
            if let Some((t, u)) = crossing(a0, a1, b0, b1) {
                let at = a0 + (a1 - a0) * t;
                raw.push((pa, Cut { segment: ia, t, point: 0 }, at));
                raw.push((pb, Cut { segment: ib, t: u, point: 0 }, at));
            }
        }
    }
    // An end touching another path (a T-junction) cuts that path where it touches.
    let ends: Vec<DVec2> = raw.iter().map(|r| r.2).collect();
    for end in ends {
        for &(p, i, a, b) in &segments {
            let (t, at) = closest_on_segment(end, a, b);
            if at.distance(end) <= JOIN_TOLERANCE_MM {
                raw.push((p, Cut { segment: i, t, point: 0 }, at));
            }
        }
    }
    // Corners are cut too, so a sample keeps each (after the T-junctions:
    // a corner is no end to touch another path).
    for (p, path) in paths.iter().enumerate() {
        for j in corners(path) {
            raw.push((p, Cut { segment: j, t: 0.0, point: 0 }, path.points_mm[j]));
        }
    }
    // Merge points within the tolerance (pairwise on a grid of cells the tolerance wide).
    let mut sets = DisjointSets::new(raw.len());
    let cell = |p: DVec2| ((p.x / JOIN_TOLERANCE_MM).floor() as i64, (p.y / JOIN_TOLERANCE_MM).floor() as i64);
    let mut grid: rustc_hash::FxHashMap<(i64, i64), Vec<usize>> = Default::default();
    for (k, r) in raw.iter().enumerate() {
        grid.entry(cell(r.2)).or_default().push(k);
    }
    for (k, r) in raw.iter().enumerate() {
        let (cx, cy) = cell(r.2);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for &other in grid.get(&(cx + dx, cy + dy)).map_or(&[][..], |v| &v[..]) {
                    if raw[other].2.distance(r.2) <= JOIN_TOLERANCE_MM {
                        sets.join(k, other);
                    }
                }
            }
        }
    }
    let mut point_of_root = rustc_hash::FxHashMap::default();
    let mut points = Vec::new();
    let mut cuts = vec![Vec::new(); paths.len()];
    for (k, (p, mut cut, at)) in raw.into_iter().enumerate() {
        let root = sets.find(k);
        cut.point = *point_of_root.entry(root).or_insert_with(|| {
            points.push(at);
            points.len() - 1
        });
        cuts[p].push(cut);
    }
    (cuts, points)
}

/// Where segments `a0a1` and `b0b1` cross, as the shares along each, if
/// they cross properly (not merely touching at an end, which the T-junction
/// pass handles, nor running parallel).
fn crossing(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> Option<(f64, f64)> {
    let (da, db) = (a1 - a0, b1 - b0);
    let denom = da.perp_dot(db);
    if denom.abs() <= 1e-12 * da.length() * db.length() {
        return None;
    }
    let t = (b0 - a0).perp_dot(db) / denom;
    let u = (b0 - a0).perp_dot(da) / denom;
    let inside = |x: f64| x > 1e-9 && x < 1.0 - 1e-9;
    (inside(t) && inside(u)).then_some((t, u))
}
