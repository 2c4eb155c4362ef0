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
    PatternTopology { components, holes: holes - loop_openings, loop_openings }
}

/// A point inside the loop and outside the pattern, as far from the curve as possible.
fn inner_probe(region: &Region, curve: &Curve) -> Option<DVec2> {
    let bounds = Rect::from_points(curve.points().iter().copied())?;
    let n = 48;
    let mut best: Option<(f64, DVec2)> = None;
    for i in 0..=n {
        for j in 0..=n {
            let p = bounds.min + bounds.size() * DVec2::new(i as f64 / n as f64, j as f64 / n as f64);
            if curve.winding(p) == 0 || region.contains(p) {
                continue;
            }
            let d = curve.distance(p);
            if best.is_none_or(|(b, _)| d > b) {
                best = Some((d, p));
            }
        }
    }
    best.map(|(_, p)| p)
}
