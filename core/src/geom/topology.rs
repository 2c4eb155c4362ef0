//! Counting the topology of geometry, independently of the solver.

use serde::{Deserialize, Serialize};

use super::{Region, union};

/// Numbers of connected components and holes of a planar region.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Topology {
    /// Connected components.
    pub components: usize,
    /// Holes: bounded parts of the complement (the region's first Betti number).
    pub holes: usize,
}

/// Counts components and holes of `region` from its geometry alone.
///
/// The region is first merged with a polygon union, so polygons that overlap
/// or share an edge count once; then components are the outer rings and holes
/// the inner rings. This is the check that the solver's topology descriptors
/// are tested against.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{count_topology, Polygon, Region};
/// let square = |x: f64| Polygon {
///     outer: vec![DVec2::new(x, 0.0), DVec2::new(x + 1.0, 0.0), DVec2::new(x + 1.0, 1.0), DVec2::new(x, 1.0)],
///     holes: vec![],
/// };
/// // Two squares sharing an edge are one component.
/// let t = count_topology(&Region::new(vec![square(0.0), square(1.0)]));
/// assert_eq!((t.components, t.holes), (1, 0));
/// ```
pub fn count_topology(region: &Region) -> Topology {
    let merged = union(&[region]);
    Topology { components: merged.component_count(), holes: merged.hole_count() }
}

/// Topology of a planar pattern, counted from its polygons alone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct PatternTopology {
    /// Connected components.
    pub components: usize,
    /// Holes in the lace: planar holes less the central openings of a loop.
    pub holes: usize,
    /// Central openings: holes that the loop itself goes around (0 on open curves).
    pub loop_openings: usize,
    /// Holes of jump rings added for hanging the piece.
    #[serde(default)]
    pub jump_rings: usize,
}

impl From<Topology> for PatternTopology {
    /// A planar pattern's counts: no loop openings nor jump rings.
    fn from(t: Topology) -> Self {
        PatternTopology { components: t.components, holes: t.holes, ..Default::default() }
    }
}
