//! The centre lines of a shape drawn as filled bands (a fret, a rule, a
//! ring): its chordal axis.
//!
//! Ornaments drawn for print fill their lines as bands rather than stroke
//! them. Read as outlines, a band 1 mm wide is two curves 1 mm apart, which
//! a sampling coarser than that cannot tell apart. The chordal axis
//! (Prasad's chordal axis transform) recovers the line the band was drawn
//! along: triangulate the shape with its outline as constraints, and join
//! the midpoints of the chords (the edges across the shape) through each
//! triangle. A triangle with three chords is a junction.

use std::collections::HashMap;

use glam::DVec2;
use spade::handles::{DirectedEdgeHandle, FaceHandle as SpadeFace, InnerTag};
use spade::{CdtEdge, ConstrainedDelaunayTriangulation, Point2, Triangulation};

use super::{Polygon, faces_inside};

/// Most points an outline may be resampled to: a bound on time and memory
/// whatever the shape and step.
pub const MAX_CENTRE_LINE_POINTS: usize = 400_000;

/// A spur shorter than this many times the width of the junction it leaves
/// is a corner of the outline, not a branch of the band.
const SPUR_WIDTHS: f64 = 1.0;

/// Two lines meeting at a junction of four arms cross there when each
/// turns by less than 40° through it (the cosine of 40°).
const STRAIGHT_THROUGH_COS: f64 = 0.766;

/// The centre lines of a shape, and how wide its bands are.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CentreLines {
    /// The lines, each with whether it closes on itself, mm.
    pub paths: Vec<(Vec<DVec2>, bool)>,
    /// Width across the band and the length of centre line it spans, for
    /// each triangle between two chords, mm.
    widths_mm: Vec<(f64, f64)>,
}

impl CentreLines {
    /// The width of band that `fraction` of the centre lines' length lies
    /// within, mm (so `width_at(0.8)` is how wide a band is along most of
    /// its length, corners aside). Infinite when there are no bands.
    pub fn width_at(&self, fraction: f64) -> f64 {
        let mut widths = self.widths_mm.clone();
        widths.sort_by(|a, b| a.0.total_cmp(&b.0));
        let total: f64 = widths.iter().map(|w| w.1).sum();
        let mut run = 0.0;
        for (width, length) in widths {
            run += length;
            if run >= fraction * total {
                return width;
            }
        }
        f64::INFINITY
    }
}

/// The chordal axis of `polygon`, with its outline resampled every
/// `step_mm` first (the finer the step, the more closely the lines follow
/// the band's middle), or `None` if the outline cannot be triangulated.
/// Spurs running into a corner of the outline are removed, and the lines
/// smoothed lightly; ends and junctions stay where the axis put them.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, centre_lines};
/// // A ring 2 mm wide about a circle of radius 10 mm.
/// let circle = |r: f64| (0..90).map(|k| DVec2::from_angle(k as f64 * std::f64::consts::TAU / 90.0) * r).collect::<Vec<_>>();
/// let ring = Polygon { outer: circle(11.0), holes: vec![circle(9.0).into_iter().rev().collect()] };
/// let lines = centre_lines(&ring, 0.5).unwrap();
/// assert_eq!(lines.paths.len(), 1);
/// assert!(lines.paths[0].1, "the ring's centre line closes");
/// assert!(lines.paths[0].0.iter().all(|p| (p.length() - 10.0).abs() < 0.1));
/// assert!((lines.width_at(0.8) - 2.0).abs() < 0.3);
/// ```
pub fn centre_lines(polygon: &Polygon, step_mm: f64) -> Option<CentreLines> {
    let cdt = triangulate(polygon, step_mm)?;
    let inside = faces_inside(&cdt);
    let chords_of = |face| chords_of(face, &inside);
    let capped = cap_chords(&cdt, &inside);
    let mut graph = Graph::default();
    let mut chord_nodes: HashMap<usize, usize> = HashMap::new();
    let mut widths_mm = Vec::new();
    for face in cdt.inner_faces().filter(|f| filled(*f, &inside)) {
        let mut chords = Vec::with_capacity(3);
        for edge in chords_of(face) {
            if capped.contains(&edge.as_undirected().fix().index()) {
                continue;
            }
            let [a, b] = edge.positions().map(|p| DVec2::new(p.x, p.y));
            let node = *chord_nodes
                .entry(edge.as_undirected().fix().index())
                .or_insert_with(|| graph.add((a + b) * 0.5, a.distance(b)));
            chords.push(node);
        }
        match chords[..] {
            [p, q] => {
                graph.link(p, q);
                let width = 0.5 * (graph.width[p] + graph.width[q]);
                widths_mm.push((width, graph.at[p].distance(graph.at[q])));
            }
            [p, q, r] => {
                let [a, b, c] = face.positions().map(|p| DVec2::new(p.x, p.y));
                let widest = graph.width[p].max(graph.width[q]).max(graph.width[r]);
                let junction = graph.add((a + b + c) / 3.0, widest);
                for chord in [p, q, r] {
                    graph.link(junction, chord);
                }
            }
            _ => {}
        }
    }
    graph.prune_spurs();
    graph.merge_near_junctions();
    graph.prune_spurs();
    graph.cross_through();
    let paths = graph.trace().into_iter().map(|(points, closed)| (smoothed(points, closed), closed)).collect();
    Some(CentreLines { paths, widths_mm })
}

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;
type FaceHandle<'a> = SpadeFace<'a, InnerTag, Point2<f64>, (), CdtEdge<()>, ()>;
type EdgeHandle<'a> = DirectedEdgeHandle<'a, Point2<f64>, (), CdtEdge<()>, ()>;

/// The chords inside the caps of the shape, found as Prasad prunes the
/// chordal axis: from each end triangle (one chord), triangles are merged
/// inwards while every vertex merged lies within the circle on the chord
/// reached. A round or pointed end thus fits within the circle on its
/// base, and its line ends there, at the middle, rather than wandering
/// through a fan of triangles into one side. A bump on a band's side fits
/// too, up to the triangle where it meets the band, and leaves no branch.
fn cap_chords(cdt: &Cdt, inside: &[Option<bool>]) -> std::collections::HashSet<usize> {
    let chords_of = |face| chords_of(face, inside);
    let point = |p: Point2<f64>| DVec2::new(p.x, p.y);
    let mut capped = std::collections::HashSet::new();
    for end in cdt.inner_faces().filter(|f| filled(*f, inside)) {
        let chords = chords_of(end);
        let [mut chord] = chords[..] else { continue };
        let mut merged: Vec<DVec2> = end.positions().map(point).to_vec();
        loop {
            let [a, b] = chord.positions().map(point);
            let (centre, radius) = ((a + b) * 0.5, 0.5 * a.distance(b) * (1.0 + 1e-6));
            if merged.iter().any(|p| p.distance(centre) > radius) {
                break;
            }
            capped.insert(chord.as_undirected().fix().index());
            let Some(next) = chord.rev().face().as_inner() else { break };
            let onward: Vec<EdgeHandle<'_>> =
                chords_of(next).into_iter().filter(|e| e.as_undirected() != chord.as_undirected()).collect();
            let [further] = onward[..] else { break };
            merged.extend(next.positions().map(point));
            chord = further;
        }
    }
    capped
}

/// Whether `face` lies inside the shape, by [`faces_inside`]'s flood.
fn filled(face: FaceHandle<'_>, inside: &[Option<bool>]) -> bool {
    inside[face.fix().index()] == Some(true)
}

/// The edges of a filled face that cross to another filled face.
fn chords_of<'a>(face: FaceHandle<'a>, inside: &[Option<bool>]) -> Vec<EdgeHandle<'a>> {
    face.adjacent_edges()
        .into_iter()
        .filter(|e| {
            !e.as_undirected().is_constraint_edge() && e.rev().face().as_inner().is_some_and(|f| filled(f, inside))
        })
        .collect()
}

/// The constrained Delaunay triangulation of `polygon`'s rings resampled
/// every `step_mm`.
fn triangulate(polygon: &Polygon, step_mm: f64) -> Option<Cdt> {
    if !(step_mm.is_finite() && step_mm > 0.0) {
        return None;
    }
    let pieces_of = |a: DVec2, b: DVec2| ((a.distance(b) / step_mm).ceil() as usize).max(1);
    let total: usize =
        polygon.rings().flat_map(|r| (0..r.len()).map(move |k| pieces_of(r[k], r[(k + 1) % r.len()]))).sum();
    if total > MAX_CENTRE_LINE_POINTS {
        return None;
    }
    let mut ids: HashMap<(u64, u64), usize> = HashMap::new();
    let mut points: Vec<Point2<f64>> = Vec::with_capacity(total);
    let mut edges: Vec<[usize; 2]> = Vec::with_capacity(total);
    for ring in polygon.rings().filter(|r| r.len() >= 3) {
        let mut ring_ids: Vec<usize> = Vec::new();
        for k in 0..ring.len() {
            let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
            let pieces = pieces_of(a, b);
            for j in 0..pieces {
                let p = a.lerp(b, j as f64 / pieces as f64);
                let next = points.len();
                let id = *ids.entry((p.x.to_bits(), p.y.to_bits())).or_insert(next);
                if id == next {
                    points.push(Point2::new(p.x, p.y));
                }
                if ring_ids.last() != Some(&id) {
                    ring_ids.push(id);
                }
            }
        }
        while ring_ids.len() > 1 && ring_ids.first() == ring_ids.last() {
            ring_ids.pop();
        }
        if ring_ids.len() >= 3 {
            edges.extend((0..ring_ids.len()).map(|k| [ring_ids[k], ring_ids[(k + 1) % ring_ids.len()]]));
        }
    }
    let mut conflicts = 0;
    let cdt =
        ConstrainedDelaunayTriangulation::<Point2<f64>>::try_bulk_load_cdt(points, edges, |_| conflicts += 1).ok()?;
    (conflicts == 0).then_some(cdt)
}

/// The chordal axis as a graph: chord midpoints and junctions.
#[derive(Default)]
struct Graph {
    at: Vec<DVec2>,
    /// The chord's length, or a junction's widest chord.
    width: Vec<f64>,
    links: Vec<Vec<usize>>,
    alive: Vec<bool>,
}

impl Graph {
    fn add(&mut self, at: DVec2, width: f64) -> usize {
        self.at.push(at);
        self.width.push(width);
        self.links.push(Vec::new());
        self.alive.push(true);
        self.at.len() - 1
    }

    fn link(&mut self, a: usize, b: usize) {
        self.links[a].push(b);
        self.links[b].push(a);
    }

    fn neighbours(&self, node: usize) -> impl Iterator<Item = usize> + '_ {
        self.links[node].iter().copied().filter(|&n| self.alive[n])
    }

    fn degree(&self, node: usize) -> usize {
        self.neighbours(node).count()
    }

    /// From `from` through `first`, along nodes of degree 2, to the next
    /// node of another degree (or back to `from`): the nodes passed and the
    /// length.
    fn walk(&self, from: usize, first: usize) -> (Vec<usize>, f64) {
        let (mut previous, mut node) = (from, first);
        let mut nodes = vec![from];
        let mut length = self.at[from].distance(self.at[first]);
        while node != from && self.degree(node) == 2 {
            let Some(next) = self.neighbours(node).find(|&n| n != previous) else { break };
            nodes.push(node);
            length += self.at[node].distance(self.at[next]);
            (previous, node) = (node, next);
        }
        nodes.push(node);
        (nodes, length)
    }

    /// Joins junctions that a line shorter than they are wide links into
    /// one, at their middle: where two bands cross, the triangulation
    /// splits the crossing into two triangles with three chords each, and
    /// the short link between them is not a line of the drawing.
    fn merge_near_junctions(&mut self) {
        for junction in 0..self.at.len() {
            if !self.alive[junction] || self.degree(junction) < 3 {
                continue;
            }
            for first in self.neighbours(junction).collect::<Vec<_>>() {
                if !self.alive[junction] || !self.alive[first] {
                    continue;
                }
                let (nodes, length) = self.walk(junction, first);
                let other = *nodes.last().expect("a walk has an end");
                let wide = self.width[junction].max(self.width[other]);
                if other == junction || self.degree(other) < 3 || length >= SPUR_WIDTHS * wide {
                    continue;
                }
                for &n in &nodes[1..nodes.len() - 1] {
                    self.alive[n] = false;
                }
                let moved = std::mem::take(&mut self.links[other]);
                for n in moved.into_iter().filter(|&n| self.alive[n] && n != junction) {
                    for back in &mut self.links[n] {
                        if *back == other {
                            *back = junction;
                        }
                    }
                    self.links[junction].push(n);
                }
                self.alive[other] = false;
                self.at[junction] = 0.5 * (self.at[junction] + self.at[other]);
                self.width[junction] = wide;
            }
        }
    }

    /// Where four arms meet as two lines running straight through each
    /// other (a flourish crossing itself, drawn as one filled shape), the
    /// junction becomes a crossing: each line's arms are linked across it,
    /// so that the two lines cross there as the drawing's did, rather than
    /// four lines ending at one point.
    fn cross_through(&mut self) {
        for junction in 0..self.at.len() {
            if !self.alive[junction] || self.degree(junction) != 4 {
                continue;
            }
            let arms: Vec<usize> = self.neighbours(junction).collect();
            let heading: Vec<DVec2> = arms.iter().map(|&a| self.heading(junction, a)).collect();
            // The pairing whose lines bend least; each must run nearly straight.
            let pairings = [[(0, 1), (2, 3)], [(0, 2), (1, 3)], [(0, 3), (1, 2)]];
            let bend = |(a, b): (usize, usize)| heading[a].dot(heading[b]);
            let best = pairings
                .iter()
                .min_by(|p, q| (bend(p[0]) + bend(p[1])).total_cmp(&(bend(q[0]) + bend(q[1]))))
                .expect("three pairings");
            if best.iter().any(|&pair| bend(pair) > -STRAIGHT_THROUGH_COS) {
                continue;
            }
            self.alive[junction] = false;
            for &(a, b) in best {
                self.link(arms[a], arms[b]);
            }
        }
    }

    /// The direction from `from` along the arm through its neighbour
    /// `first`, taken about one width of `from` away (or where the arm
    /// ends), so that the zigzag of the first chords does not decide it.
    fn heading(&self, from: usize, first: usize) -> DVec2 {
        let (mut previous, mut node) = (from, first);
        while self.at[node].distance(self.at[from]) < self.width[from] && self.degree(node) == 2 {
            let Some(next) = self.neighbours(node).find(|&n| n != previous) else { break };
            (previous, node) = (node, next);
        }
        (self.at[node] - self.at[from]).normalize_or_zero()
    }

    /// Removes, until none is left, every branch from a free end to a
    /// junction shorter than the junction is wide.
    fn prune_spurs(&mut self) {
        loop {
            let mut changed = false;
            for end in 0..self.at.len() {
                if !self.alive[end] || self.degree(end) != 1 {
                    continue;
                }
                let Some(first) = self.neighbours(end).next() else { continue };
                let (nodes, length) = self.walk(end, first);
                let junction = *nodes.last().expect("a walk has an end");
                if self.degree(junction) >= 3 && length < SPUR_WIDTHS * self.width[junction] {
                    for &n in &nodes[..nodes.len() - 1] {
                        self.alive[n] = false;
                    }
                    changed = true;
                }
            }
            if !changed {
                return;
            }
        }
    }

    /// The lines between ends and junctions, then the loops left.
    fn trace(&self) -> Vec<(Vec<DVec2>, bool)> {
        let mut used: std::collections::HashSet<(usize, usize)> = Default::default();
        let key = |a: usize, b: usize| (a.min(b), a.max(b));
        let mut paths = Vec::new();
        let follow = |from: usize, first: usize, used: &mut std::collections::HashSet<(usize, usize)>| {
            let (nodes, _) = self.walk(from, first);
            for pair in nodes.windows(2) {
                used.insert(key(pair[0], pair[1]));
            }
            let closed = nodes.first() == nodes.last() && self.degree(from) == 2;
            let mut points: Vec<DVec2> = nodes.iter().map(|&n| self.at[n]).collect();
            if closed {
                points.pop();
            }
            (points, closed)
        };
        for degree_two in [false, true] {
            for node in (0..self.at.len()).filter(|&n| self.alive[n]) {
                if (self.degree(node) == 2) != degree_two {
                    continue;
                }
                for next in self.neighbours(node).collect::<Vec<_>>() {
                    if !used.contains(&key(node, next)) {
                        let (points, closed) = follow(node, next, &mut used);
                        if points.len() >= 2 {
                            paths.push((points, closed));
                        }
                    }
                }
            }
        }
        paths
    }
}

/// `points` after two passes of a (¼, ½, ¼) average, which takes out the
/// zigzag of midpoints of chords leaning alternately; the ends of an open
/// line stay.
fn smoothed(mut points: Vec<DVec2>, closed: bool) -> Vec<DVec2> {
    let n = points.len();
    if n < 3 {
        return points;
    }
    for _ in 0..2 {
        let before = points.clone();
        let range = if closed { 0..n } else { 1..n - 1 };
        for k in range {
            let (a, b) = (before[(k + n - 1) % n], before[(k + 1) % n]);
            points[k] = 0.25 * a + 0.5 * before[k] + 0.25 * b;
        }
    }
    points
}
