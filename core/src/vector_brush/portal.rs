//! Portals: where a cut line crosses the inside of a shape.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::geom::Region;

/// One interval of a cut line inside the material, with the boundary
/// tangents at its two endpoints.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Portal {
    /// `v` of the upper endpoint.
    pub top: f64,
    /// `v` of the lower endpoint.
    pub bottom: f64,
    /// Unit boundary tangent at the upper endpoint, pointing towards `+u`.
    pub top_tangent: DVec2,
    /// Unit boundary tangent at the lower endpoint, pointing towards `+u`.
    pub bottom_tangent: DVec2,
}

impl Portal {
    /// Length of the portal along `v`.
    pub fn width(&self) -> f64 {
        self.top - self.bottom
    }

    /// Middle of the portal along `v`.
    pub fn middle(&self) -> f64 {
        0.5 * (self.top + self.bottom)
    }
}

/// The portals where the vertical line `u = cut` crosses `region`, top to bottom.
///
/// `cut` must not pass through a vertex (see [`crate::cut_positions`], which
/// moves cuts off vertices); the region must be clean, so that crossings
/// alternate between entering and leaving the material.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::vector_brush::portals_at;
/// let outer = vec![DVec2::new(0.0, -2.0), DVec2::new(4.0, -2.0), DVec2::new(4.0, 2.0), DVec2::new(0.0, 2.0)];
/// let hole = vec![DVec2::new(1.0, -1.0), DVec2::new(1.0, 1.0), DVec2::new(3.0, 1.0), DVec2::new(3.0, -1.0)];
/// let region = Region::new(vec![Polygon { outer, holes: vec![hole] }]);
/// let portals = portals_at(&region, 2.0);
/// assert_eq!(portals.len(), 2);
/// assert_eq!((portals[0].top, portals[0].bottom), (2.0, 1.0));
/// ```
pub fn portals_at(region: &Region, cut: f64) -> Vec<Portal> {
    let mut crossings: Vec<(f64, DVec2)> = Vec::new();
    for ring in region.rings() {
        let n = ring.len();
        for i in 0..n {
            let a = ring[i];
            let b = ring[(i + 1) % n];
            if (a.x < cut) != (b.x < cut) && a.x != b.x {
                let t = (cut - a.x) / (b.x - a.x);
                let v = a.y + t * (b.y - a.y);
                let mut tangent = (b - a).normalize_or_zero();
                if tangent.x < 0.0 {
                    tangent = -tangent;
                }
                crossings.push((v, tangent));
            }
        }
    }
    crossings.sort_by(|a, b| b.0.total_cmp(&a.0));
    crossings
        .chunks_exact(2)
        .map(|pair| Portal { top: pair[0].0, bottom: pair[1].0, top_tangent: pair[0].1, bottom_tangent: pair[1].1 })
        .collect()
}
