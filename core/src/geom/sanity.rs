//! [`Region::sanity_check`]: the invariants every stage's region must keep.
//! Tests call it after every stage, as spade's `cdt_sanity_check` is called.

use glam::DVec2;

use super::{Region, signed_area};

/// Rings whose signed area is within this of zero are flagged as degenerate, mm² or units².
pub const MIN_RING_AREA: f64 = 1e-12;

/// What is wrong with a region.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RegionDefect {
    /// A ring has fewer than three points.
    #[error("polygon {polygon}, ring {ring}: {points} point(s), a ring needs three")]
    TooFewPoints {
        /// Polygon index.
        polygon: usize,
        /// Ring index: 0 the outer ring, then the holes.
        ring: usize,
        /// Points found.
        points: usize,
    },
    /// A coordinate is not a finite number.
    #[error("polygon {polygon}, ring {ring}: a coordinate is not a finite number")]
    NotFinite {
        /// Polygon index.
        polygon: usize,
        /// Ring index.
        ring: usize,
    },
    /// The first point is repeated at the end, or two consecutive points are equal.
    #[error("polygon {polygon}, ring {ring}: point {point} repeats its predecessor (rings close implicitly)")]
    RepeatedPoint {
        /// Polygon index.
        polygon: usize,
        /// Ring index.
        ring: usize,
        /// The repeated point.
        point: usize,
    },
    /// An outer ring runs clockwise or a hole counter-clockwise (or encloses no area).
    #[error("polygon {polygon}, ring {ring}: wrong orientation (signed area {area})")]
    Orientation {
        /// Polygon index.
        polygon: usize,
        /// Ring index.
        ring: usize,
        /// Its signed area.
        area: f64,
    },
    /// A hole lies outside its polygon's outer ring.
    #[error("polygon {polygon}: hole {hole} is not inside the outer ring")]
    HoleOutside {
        /// Polygon index.
        polygon: usize,
        /// Hole index.
        hole: usize,
    },
    /// Two edges cross (or overlap along a line).
    #[error("edges cross near ({x:.6}, {y:.6})")]
    Crossing {
        /// Where, x.
        x: f64,
        /// Where, y.
        y: f64,
    },
}

struct Edge {
    a: DVec2,
    b: DVec2,
    ring: usize,
    index: usize,
    ring_len: usize,
}

fn orient(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    (b - a).perp_dot(c - a)
}

/// Whether two edges meet anywhere but at shared end points: a proper
/// crossing, or a collinear overlap of positive length.
fn edges_conflict(e: &Edge, f: &Edge) -> bool {
    let (o1, o2) = (orient(e.a, e.b, f.a), orient(e.a, e.b, f.b));
    let (o3, o4) = (orient(f.a, f.b, e.a), orient(f.a, f.b, e.b));
    if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
        return true;
    }
    if o1 == 0.0 && o2 == 0.0 {
        // Collinear: project on the longer axis and look for an overlap of positive length.
        let d = e.b - e.a;
        let axis = if d.x.abs() >= d.y.abs() { DVec2::X } else { DVec2::Y };
        let (e0, e1) = minmax(e.a.dot(axis), e.b.dot(axis));
        let (f0, f1) = minmax(f.a.dot(axis), f.b.dot(axis));
        return e1.min(f1) > e0.max(f0);
    }
    false
}

fn minmax(a: f64, b: f64) -> (f64, f64) {
    if a <= b { (a, b) } else { (b, a) }
}

impl Region {
    /// Checks the region's invariants: every ring has at least three finite,
    /// distinct consecutive points (closed implicitly), outer rings run
    /// counter-clockwise and holes clockwise, holes lie inside their outer
    /// ring, and no two edges cross or overlap anywhere (rings may touch at a
    /// vertex, as boolean operations leave them).
    ///
    /// ```
    /// use glam::DVec2;
    /// use tracery_core::geom::{Polygon, Region};
    /// let square = vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    /// let good = Region::new(vec![Polygon { outer: square.clone(), holes: vec![] }]);
    /// assert!(good.sanity_check().is_ok());
    /// let bow_tie = vec![DVec2::ZERO, DVec2::ONE, DVec2::X, DVec2::Y];
    /// let bad = Region::new(vec![Polygon { outer: bow_tie, holes: vec![] }]);
    /// assert!(bad.sanity_check().is_err());
    /// ```
    pub fn sanity_check(&self) -> Result<(), RegionDefect> {
        let mut edges = Vec::new();
        let mut ring_id = 0;
        for (p, polygon) in self.polygons.iter().enumerate() {
            for (r, ring) in polygon.rings().enumerate() {
                if ring.len() < 3 {
                    return Err(RegionDefect::TooFewPoints { polygon: p, ring: r, points: ring.len() });
                }
                if ring.iter().any(|q| !q.is_finite()) {
                    return Err(RegionDefect::NotFinite { polygon: p, ring: r });
                }
                if let Some(i) = (0..ring.len()).find(|&i| ring[i] == ring[(i + 1) % ring.len()]) {
                    return Err(RegionDefect::RepeatedPoint { polygon: p, ring: r, point: (i + 1) % ring.len() });
                }
                let area = signed_area(ring);
                let outer = r == 0;
                if (outer && area <= MIN_RING_AREA) || (!outer && area >= -MIN_RING_AREA) {
                    return Err(RegionDefect::Orientation { polygon: p, ring: r, area });
                }
                for i in 0..ring.len() {
                    let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
                    edges.push(Edge { a, b, ring: ring_id, index: i, ring_len: ring.len() });
                }
                ring_id += 1;
            }
            for (h, hole) in polygon.holes.iter().enumerate() {
                // A hole may touch the outer ring at a vertex; test a point
                // well inside the hole's first edge instead of a vertex.
                let probe = hole[0].lerp(hole[1], 0.5);
                if !super::ring_contains(&polygon.outer, probe) {
                    return Err(RegionDefect::HoleOutside { polygon: p, hole: h });
                }
            }
        }
        // Sweep over x: only edges whose x-ranges overlap can meet.
        edges.sort_by(|e, f| e.a.x.min(e.b.x).total_cmp(&f.a.x.min(f.b.x)));
        let mut active: Vec<usize> = Vec::new();
        for i in 0..edges.len() {
            let e = &edges[i];
            let left = e.a.x.min(e.b.x);
            active.retain(|&j| edges[j].a.x.max(edges[j].b.x) >= left);
            for &j in &active {
                let f = &edges[j];
                let adjacent = e.ring == f.ring
                    && ((e.index + 1) % e.ring_len == f.index || (f.index + 1) % f.ring_len == e.index);
                if !adjacent && edges_conflict(e, f) {
                    let at = e.a.lerp(e.b, 0.5);
                    return Err(RegionDefect::Crossing { x: at.x, y: at.y });
                }
            }
            active.push(i);
        }
        Ok(())
    }
}
