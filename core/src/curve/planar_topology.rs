//! The topology of a pattern laid along a curve, counted from its geometry
//! alone, with a loop's central openings told apart from holes in the lace.

use glam::DVec2;

use super::Curve;
use crate::geom::{PatternTopology, Rect, Region, Topology, count_topology, ring_contains};

/// Counts the topology of a planar pattern from its geometry. On a loop,
/// holes that contain a point well inside the loop (away from the band) are
/// its central openings, not holes in the lace.
pub fn planar_topology(region: &Region, curve: &Curve) -> PatternTopology {
    let Topology { components, holes } = count_topology(region);
    let mut loop_openings = 0;
    if let Some(probe) = inner_probe(region, curve).filter(|_| curve.is_closed()) {
        loop_openings = region.polygons.iter().flat_map(|p| p.holes.iter()).filter(|h| ring_contains(h, probe)).count();
    }
    PatternTopology { components, holes: holes - loop_openings, loop_openings, jump_rings: 0 }
}

/// A point inside the loop and outside the pattern, as far from the curve as possible.
fn inner_probe(region: &Region, curve: &Curve) -> Option<DVec2> {
    let bounds = Rect::from_points(curve.points().iter().copied())?;
    let n = 48;
    // The farthest candidates first; the pattern is tested only until one
    // lies outside it, since testing a point against it is the costly part.
    let mut candidates: Vec<(f64, DVec2)> = (0..=n)
        .flat_map(|i| (0..=n).map(move |j| DVec2::new(i as f64 / n as f64, j as f64 / n as f64)))
        .map(|t| bounds.min + bounds.size() * t)
        .filter(|&p| curve.winding(p) != 0)
        .map(|p| (curve.distance(p), p))
        .collect();
    candidates.sort_by(|a, b| b.0.total_cmp(&a.0));
    candidates.into_iter().map(|(_, p)| p).find(|&p| !region.contains(p))
}
