//! A region's outline edges in a uniform grid: the largest empty disc
//! tangent at an outline point (the local width), and the edges near a
//! seam for the bridges.

use glam::DVec2;

use crate::geom::{Region, closest_on_segment};

pub(super) struct Edge {
    pub(super) a: DVec2,
    pub(super) b: DVec2,
    ring: usize,
    /// Index of `a` in its ring.
    k: usize,
    /// Arc length along the ring at `a`, mm.
    arc_a: f64,
}

/// Most buckets in one grid: past that they grow, so that a large region
/// never takes more than a few megabytes of offsets.
const MAX_BUCKETS: f64 = 2_097_152.0;

/// One edge as listed in a bucket: its ends beside its index, so that a
/// query reads a bucket's edges in one run of memory.
#[derive(Clone, Copy)]
struct Listed {
    a: DVec2,
    b: DVec2,
    edge: u32,
}

/// The outline's edges, each listed in every bucket its box overlaps, the
/// buckets a dense grid over the region's box stored as one array
/// (compressed rows: `starts[k]..starts[k + 1]` are bucket `k`'s edges).
pub(super) struct EdgeGrid<'a> {
    rings: Vec<&'a [DVec2]>,
    pub(super) edges: Vec<Edge>,
    ring_lengths: Vec<f64>,
    cell_mm: f64,
    /// Index of the first column and row: buckets lie on the lattice of
    /// multiples of `bucket_mm`, wherever the region is.
    origin: (i64, i64),
    bucket_mm: f64,
    columns: i64,
    rows: i64,
    starts: Vec<u32>,
    listed: Vec<Listed>,
}

impl<'a> EdgeGrid<'a> {
    /// The edges of `region`, in buckets `cell_mm` wide (wider only where
    /// the region would need more than [`MAX_BUCKETS`]).
    pub(super) fn new(region: &'a Region, cell_mm: f64) -> Self {
        let rings: Vec<&[DVec2]> = region.rings().map(|r| r.as_slice()).collect();
        let mut edges = Vec::new();
        let mut ring_lengths = Vec::new();
        for (ring_index, ring) in rings.iter().enumerate() {
            let mut arc = 0.0;
            for k in 0..ring.len() {
                let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                edges.push(Edge { a, b, ring: ring_index, k, arc_a: arc });
                arc += a.distance(b);
            }
            ring_lengths.push(arc);
        }
        let (low, high) =
            edges.iter().fold((DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)), |(lo, hi), e| {
                (lo.min(e.a).min(e.b), hi.max(e.a).max(e.b))
            });
        let (low, size) = if edges.is_empty() { (DVec2::ZERO, DVec2::ZERO) } else { (low, high - low) };
        let mut bucket_mm = cell_mm.max(f64::MIN_POSITIVE);
        let area_buckets = (size.x / bucket_mm + 2.0) * (size.y / bucket_mm + 2.0);
        if area_buckets > MAX_BUCKETS {
            bucket_mm *= (area_buckets / MAX_BUCKETS).sqrt();
        }
        let lattice = |v: f64| (v / bucket_mm).floor() as i64;
        let origin = (lattice(low.x), lattice(low.y));
        let columns = lattice(low.x + size.x) - origin.0 + 1;
        let rows = lattice(low.y + size.y) - origin.1 + 1;
        let mut grid = EdgeGrid {
            rings,
            edges,
            ring_lengths,
            cell_mm,
            origin,
            bucket_mm,
            columns,
            rows,
            starts: Vec::new(),
            listed: Vec::new(),
        };
        // Counted first, then filled: one allocation for all the lists.
        let bucket_count = (columns * rows) as usize;
        let mut counts = vec![0u32; bucket_count + 1];
        for e in &grid.edges {
            let (lo, hi) = (grid.bucket_of(e.a.min(e.b)), grid.bucket_of(e.a.max(e.b)));
            for y in lo.1..=hi.1 {
                for x in lo.0..=hi.0 {
                    counts[(y * columns + x) as usize + 1] += 1;
                }
            }
        }
        for k in 0..bucket_count {
            counts[k + 1] += counts[k];
        }
        let mut next = counts.clone();
        let mut listed = vec![Listed { a: DVec2::ZERO, b: DVec2::ZERO, edge: 0 }; counts[bucket_count] as usize];
        for (i, e) in grid.edges.iter().enumerate() {
            let (lo, hi) = (grid.bucket_of(e.a.min(e.b)), grid.bucket_of(e.a.max(e.b)));
            for y in lo.1..=hi.1 {
                for x in lo.0..=hi.0 {
                    let slot = &mut next[(y * columns + x) as usize];
                    listed[*slot as usize] = Listed { a: e.a, b: e.b, edge: i as u32 };
                    *slot += 1;
                }
            }
        }
        grid.starts = counts;
        grid.listed = listed;
        grid
    }

    /// The reach the grid was made for, mm.
    pub(super) fn cell_mm(&self) -> f64 {
        self.cell_mm
    }

    /// The bucket holding `p`, clamped to the grid.
    fn bucket_of(&self, p: DVec2) -> (i64, i64) {
        let q = (p / self.bucket_mm).floor();
        // NaN goes to 0 with `as`, and the clamp holds everything else.
        ((q.x as i64 - self.origin.0).clamp(0, self.columns - 1), (q.y as i64 - self.origin.1).clamp(0, self.rows - 1))
    }

    /// Edges listed in the buckets that overlap the box `lo`–`hi` (some twice).
    fn listed_in(&self, lo: DVec2, hi: DVec2) -> impl Iterator<Item = &Listed> + '_ {
        let (lo, hi) = (self.bucket_of(lo), self.bucket_of(hi));
        (lo.1..=hi.1).flat_map(move |y| {
            let row = y * self.columns;
            let (first, last) = ((row + lo.0) as usize, (row + hi.0) as usize);
            self.listed[self.starts[first] as usize..self.starts[last + 1] as usize].iter()
        })
    }

    /// Edges whose buckets overlap the box around `a`–`b`, each once.
    pub(super) fn near(&self, a: DVec2, b: DVec2) -> Vec<usize> {
        let mut out: Vec<usize> = self.listed_in(a.min(b), a.max(b)).map(|l| l.edge as usize).collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// The vertex before edge `e`, its two ends and the vertex after it.
    pub(super) fn with_neighbours(&self, e: usize) -> (DVec2, DVec2, DVec2, DVec2) {
        let (ring, k) = (self.rings[self.edges[e].ring], self.edges[e].k);
        let n = ring.len();
        (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n], ring[(k + 2) % n])
    }

    /// The largest disc tangent to the outline at `p` (its centre at
    /// `p + normal · r`, `normal` of unit length) that holds no point of the
    /// outline, ignoring edge `skip` (the one `p` lies on), when it is
    /// smaller than `max_radius`: `(r, edge, point)`, the outline point on
    /// its boundary that stops it. `None` when the disc of `max_radius` is
    /// empty.
    ///
    /// A point `q` lies inside the disc of radius `r` exactly when
    /// `r > |q − p|² / (2 normal·(q − p))`, so the disc is the smallest of
    /// those radii over the outline; along each edge the ratio's minimum is
    /// found in closed form. The shrinking-ball iteration converges to the
    /// same disc, several queries later.
    pub(super) fn largest_empty_disc(
        &self,
        p: DVec2,
        normal: DVec2,
        max_radius: f64,
        skip: usize,
    ) -> Option<(f64, usize, DVec2)> {
        let (largest, reach) = (p + normal * max_radius, DVec2::splat(max_radius));
        // A point on the largest disc's own boundary is not inside it.
        let limit = max_radius * (1.0 - 1e-9);
        let mut best: Option<(f64, usize, DVec2)> = None;
        for l in self.listed_in(largest - reach, largest + reach) {
            if l.edge as usize == skip {
                continue;
            }
            // An edge wholly behind the tangent line stops no disc.
            if normal.dot(l.a - p) <= TANGENT_SLACK_MM && normal.dot(l.b - p) <= TANGENT_SLACK_MM {
                continue;
            }
            // Only edges that reach into the best disc so far can stop it
            // sooner (the discs tangent at `p` are nested).
            let bound = best.map_or(limit, |b| b.0);
            let centre = p + normal * bound;
            if closest_on_segment(centre, l.a, l.b).1.distance_squared(centre) >= bound * bound {
                continue;
            }
            if let Some((radius, q)) = smallest_tangent_disc(p, normal, l.a, l.b)
                && radius < bound
            {
                best = Some((radius, l.edge as usize, q));
            }
        }
        best
    }

    /// Distance along the ring between two outline points (the shorter way),
    /// or infinity when they are on different rings.
    pub(super) fn arc_between(&self, e1: usize, p1: DVec2, e2: usize, p2: DVec2) -> f64 {
        let (a, b) = (&self.edges[e1], &self.edges[e2]);
        if a.ring != b.ring {
            return f64::INFINITY;
        }
        let s1 = a.arc_a + a.a.distance(p1);
        let s2 = b.arc_a + b.a.distance(p2);
        let d = (s1 - s2).abs();
        d.min(self.ring_lengths[a.ring] - d)
    }
}

/// Points closer to the tangent line than this (in mm, along the normal)
/// stop no disc: a disc through them would be unboundedly large.
const TANGENT_SLACK_MM: f64 = 1e-12;

/// The smallest radius `r(q) = |q − p|² / (2 normal·(q − p))` over the
/// points `q` of the segment `a`–`b` in front of the tangent line at `p`,
/// with the point that has it; `None` when no point is in front.
///
/// With `q = a + t (b − a)`, `r` is a ratio of a quadratic to a linear
/// function of `t`, whose derivative vanishes where
/// `Aβ t² + 2Aα t + 2Bα − βC = 0` (`A = e·e`, `B = d·e`, `C = d·d`,
/// `α = n·d`, `β = n·e`, `d = a − p`, `e = b − a`); the minimum is there
/// or at an end of the part of the segment in front of the line.
fn smallest_tangent_disc(p: DVec2, normal: DVec2, a: DVec2, b: DVec2) -> Option<(f64, DVec2)> {
    let (d, e) = (a - p, b - a);
    let (big_a, big_b, big_c) = (e.dot(e), d.dot(e), d.dot(d));
    let (alpha, beta) = (normal.dot(d), normal.dot(e));
    // The part of [0, 1] where α + β t > slack.
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    if beta.abs() <= f64::EPSILON * (alpha.abs() + 1.0) {
        if alpha <= TANGENT_SLACK_MM {
            return None;
        }
    } else {
        let crossing = (TANGENT_SLACK_MM - alpha) / beta;
        if beta > 0.0 {
            lo = lo.max(crossing);
        } else {
            hi = hi.min(crossing);
        }
        if lo > hi {
            return None;
        }
    }
    let radius_at = |t: f64| {
        let height = alpha + beta * t;
        (height > TANGENT_SLACK_MM).then(|| ((big_a * t + 2.0 * big_b) * t + big_c) / (2.0 * height))
    };
    let mut best: Option<(f64, f64)> = None;
    let mut consider = |t: f64| {
        if !(lo..=hi).contains(&t) {
            return;
        }
        if let Some(r) = radius_at(t)
            && best.is_none_or(|(br, _)| r < br)
        {
            best = Some((r, t));
        }
    };
    consider(lo);
    consider(hi);
    let (q2, q1, q0) = (big_a * beta, 2.0 * big_a * alpha, 2.0 * big_b * alpha - beta * big_c);
    // Roots without cancellation: `q = −(q1 + sign(q1)·√Δ)/2` gives
    // `q/q2` and `q0/q`, well conditioned even when `q2` is tiny (an edge
    // almost parallel to the tangent line), where the textbook formula
    // loses the root that matters.
    let discriminant = q1 * q1 - 4.0 * q2 * q0;
    if discriminant >= 0.0 {
        let half = -0.5 * (q1 + q1.signum() * discriminant.sqrt());
        if q2 != 0.0 {
            consider(half / q2);
        }
        if half != 0.0 {
            consider(q0 / half);
        }
    }
    best.map(|(r, t)| (r, a + e * t))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Polygon;

    /// The shrinking ball as first written: query the nearest outline point
    /// inside the disc (over every edge, no grid), shrink the disc to pass
    /// through it, and repeat until the disc is empty.
    fn shrinking_ball(edges: &[Edge], p: DVec2, normal: DVec2, max_radius: f64, skip: usize) -> Option<f64> {
        let mut radius = max_radius;
        let mut found = None;
        for _ in 0..200 {
            let c = p + normal * radius;
            let inside = radius * (1.0 - 1e-9);
            let nearest = (0..edges.len())
                .filter(|&i| i != skip)
                .map(|i| closest_on_segment(c, edges[i].a, edges[i].b).1)
                .filter(|q| q.distance_squared(c) < inside * inside)
                .min_by(|a, b| a.distance_squared(c).total_cmp(&b.distance_squared(c)));
            let Some(q) = nearest else { break };
            let towards = normal.dot(q - p);
            if towards <= 1e-12 {
                break;
            }
            let shrunk = (q - p).length_squared() / (2.0 * towards);
            if shrunk >= radius {
                break;
            }
            radius = shrunk;
            found = Some(radius);
        }
        found
    }

    /// A wavy ring with a second ring close beside it: necks, bays and
    /// edges at every angle to the samples' normals.
    fn wavy_region() -> Region {
        let ring = |centre: DVec2, radius: f64, waves: f64, count: usize| -> Vec<DVec2> {
            (0..count)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / count as f64;
                    centre + DVec2::from_angle(t) * radius * (1.0 + 0.2 * (waves * t).sin())
                })
                .collect()
        };
        Region::new(vec![
            Polygon { outer: ring(DVec2::ZERO, 1.0, 5.0, 173), holes: vec![] },
            Polygon { outer: ring(DVec2::new(2.3, 0.1), 1.0, 3.0, 97), holes: vec![] },
        ])
    }

    #[test]
    fn the_closed_form_disc_is_the_one_the_shrinking_ball_reaches() {
        let region = wavy_region();
        let grid = EdgeGrid::new(&region, 0.4);
        let mut compared = 0;
        for (i, e) in grid.edges.iter().enumerate() {
            let along = (e.b - e.a).normalize();
            for side in [along.perp(), -along.perp()] {
                for t in [0.3, 0.5, 0.8] {
                    let p = e.a.lerp(e.b, t);
                    let fast = grid.largest_empty_disc(p, side, 0.4, i).map(|f| f.0);
                    let slow = shrinking_ball(&grid.edges, p, side, 0.4, i);
                    match (fast, slow) {
                        (Some(f), Some(s)) => {
                            // The iteration stops a hair above the true
                            // minimum, never below it.
                            assert!(f <= s * (1.0 + 1e-7) && f >= s * (1.0 - 1e-6), "{f} against {s} at {p}");
                            compared += 1;
                        }
                        (None, None) => {}
                        other => panic!("{other:?} at {p}"),
                    }
                }
            }
        }
        // Both sides of the neck and the bays stop discs.
        assert!(compared > 200, "{compared}");
    }

    #[test]
    fn an_edge_nearly_parallel_to_the_tangent_stops_the_disc_at_its_foot() {
        // A sample 0.02 below an edge that slopes by one part in 10¹⁶:
        // the disc stops at the point straight above, radius 0.01.
        let (p, normal) = (DVec2::new(0.04, -0.02), DVec2::Y);
        let (a, b) = (DVec2::new(-0.5, 0.0), DVec2::new(0.5, 1e-16));
        let (radius, q) = smallest_tangent_disc(p, normal, a, b).unwrap();
        assert!((radius - 0.01).abs() < 1e-12, "{radius}");
        assert!((q.x - 0.04).abs() < 1e-9, "{q}");
        // Wholly behind the tangent line: nothing.
        assert!(smallest_tangent_disc(p, normal, a - DVec2::Y, b - DVec2::Y).is_none());
    }
}
