//! Rings that touch at a single point, moved a hair apart.
//!
//! Where two parts meet at a corner, or two holes meet tip to tip, one
//! point is shared by several rings (or twice by one). Whether such a point
//! joins what meets there depends on rounding: a polygon union may keep the
//! parts apart in one coordinate system and merge them once the same points
//! are mapped into another. Separating the copies settles it once, the same
//! way everywhere: parts that only touch are apart, and material between
//! holes that only touch holds. This is also the rule the topology
//! descriptors plan with.

use glam::DVec2;

use super::{Polygon, Region};

/// Vertex `v` of a ring (material on the left of `prev → v → next`) moved by
/// `step`, or less on short edges, into the convex side of its corner: into
/// the material where the material's corner is convex or straight, out of
/// it where it is reflex. Its new edges stay inside its own wedge, so they
/// cross nothing. `round` is applied to the result (the output's precision).
fn into_own_wedge(prev: DVec2, v: DVec2, next: DVec2, step: f64, round: &impl Fn(DVec2) -> DVec2) -> Option<DVec2> {
    let (to_prev, to_next) = (prev - v, next - v);
    let turn = (v - prev).perp_dot(next - v);
    let bisector = (to_prev.normalize_or_zero() + to_next.normalize_or_zero()).normalize_or_zero();
    // On a straight run either side is a half-plane: the material's is on the left.
    let inward = if turn == 0.0 || bisector == DVec2::ZERO { (v - prev).perp().normalize_or_zero() } else { bisector };
    if inward == DVec2::ZERO {
        return None;
    }
    let step = step.min(0.25 * to_prev.length().min(to_next.length()));
    let moved = round(v + inward * step);
    (moved != v).then_some(moved)
}

/// A ring vertex: its position's bits, its ring and its index in the ring.
type VertexAt = ((u64, u64), u32, u32);

/// Moves every point that several ring vertices share (after `round`) apart
/// by about `step`, all copies but one.
///
/// Copies whose material corner is convex (or straight) move into their
/// material first, since material wedges never overlap: parts that touch
/// come apart, an opening pinched shut opens. Where copies with reflex
/// corners still share the point (two holes tip to tip), all but one move
/// back into their openings, and the material between them holds.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::separate_touching_rings;
/// // Two squares touching corner to corner.
/// let square = |x: f64, y: f64| vec![DVec2::new(x, y), DVec2::new(x + 1.0, y), DVec2::new(x + 1.0, y + 1.0), DVec2::new(x, y + 1.0)];
/// let mut rings = vec![square(0.0, 0.0), square(1.0, 1.0)];
/// separate_touching_rings(&mut rings, 1e-3, |p| p);
/// assert_ne!(rings[0][2], rings[1][0]);
/// assert!(rings[0][2].distance(rings[1][0]) > 1e-3);
/// ```
pub fn separate_touching_rings(rings: &mut [Vec<DVec2>], step: f64, round: impl Fn(DVec2) -> DVec2) {
    // Every vertex by position, then by ring and index: shared points are
    // runs of equal keys, each run in ring order. Sorting a flat list is
    // several times faster than a map of lists on a dense pattern (90 k
    // vertices), and this runs on every pattern twice.
    let mut copies: Vec<VertexAt> = Vec::with_capacity(rings.iter().map(Vec::len).sum());
    for (r, ring) in rings.iter().enumerate() {
        copies.extend(ring.iter().enumerate().map(|(k, p)| ((p.x.to_bits(), p.y.to_bits()), r as u32, k as u32)));
    }
    copies.sort_unstable();
    let groups: Vec<&[VertexAt]> = copies.chunk_by(|a, b| a.0 == b.0).filter(|run| run.len() > 1).collect();
    if groups.is_empty() {
        return;
    }
    let originals: Vec<Vec<DVec2>> = rings.to_vec();
    let corner = |(r, k): (usize, usize)| {
        let ring = &originals[r];
        let n = ring.len();
        (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n])
    };
    for shared in groups {
        let mut staying = Vec::new();
        for copy in shared.iter().map(|&(_, r, k)| (r as usize, k as usize)) {
            let (prev, v, next) = corner(copy);
            match into_own_wedge(prev, v, next, step, &round).filter(|_| (v - prev).perp_dot(next - v) >= 0.0) {
                Some(moved) => rings[copy.0][copy.1] = moved,
                None => staying.push(copy),
            }
        }
        for &copy in staying.iter().skip(1) {
            let (prev, v, next) = corner(copy);
            if let Some(moved) = into_own_wedge(prev, v, next, step, &round) {
                rings[copy.0][copy.1] = moved;
            }
        }
    }
}

/// Fraction of `step` within which a vertex counts as lying on an edge
/// ([`super::insert_edge_contacts`]): far below any feature, far above
/// the rounding of the maps that put it there.
const CONTACT_TOLERANCE: f64 = 1e-3;

/// [`separate_touching`], with a vertex that touches another ring's edge
/// (not one of its vertices) counted as a touching point too: it is put
/// into that edge first ([`super::insert_edge_contacts`]). Slower: every
/// vertex is looked for on the edges near it.
pub fn separate_contacts(region: &Region, step: f64) -> Region {
    let mut rings: Vec<Vec<DVec2>> = region.rings().cloned().collect();
    super::insert_edge_contacts(&mut rings, CONTACT_TOLERANCE * step);
    separated(region, rings, step)
}

/// The region with its touching points moved about `step` apart
/// ([`separate_touching_rings`]), in the region's own units.
pub fn separate_touching(region: &Region, step: f64) -> Region {
    let rings: Vec<Vec<DVec2>> = region.rings().cloned().collect();
    separated(region, rings, step)
}

/// `region` with its rings replaced by `rings` (in [`Region::rings`] order)
/// separated where they touch.
fn separated(region: &Region, mut rings: Vec<Vec<DVec2>>, step: f64) -> Region {
    separate_touching_rings(&mut rings, step, |p| p);
    let mut rings = rings.into_iter();
    let polygons = region
        .polygons
        .iter()
        .map(|p| Polygon {
            outer: rings.next().unwrap_or_default(),
            holes: p.holes.iter().map(|_| rings.next().unwrap_or_default()).collect(),
        })
        .collect();
    Region::new(polygons)
}
