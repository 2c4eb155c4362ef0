//! Polygons with holes and sets of them ([`Region`]).

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::Rect;

/// A simple polygon with holes.
///
/// Rings are stored without repeating the first point. The outer ring runs
/// counter-clockwise (positive signed area, with `v` pointing up) and holes run
/// clockwise, the convention of [`i_overlay`]'s output.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Polygon {
    /// The outer boundary, counter-clockwise.
    pub outer: Vec<DVec2>,
    /// Holes, each clockwise, strictly inside `outer`.
    pub holes: Vec<Vec<DVec2>>,
}

/// A set of polygons with holes that do not overlap: a planar region.
///
/// Each [`Polygon`] of a region produced by a boolean operation is one
/// connected component.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Region {
    /// The polygons, one per connected component.
    pub polygons: Vec<Polygon>,
}

/// Signed area of a ring: positive when counter-clockwise.
///
/// ```
/// use glam::DVec2;
/// let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
/// assert_eq!(tracery_core::geom::signed_area(&square), 1.0);
/// ```
pub fn signed_area(ring: &[DVec2]) -> f64 {
    let n = ring.len();
    if n < 3 {
        return 0.0;
    }
    let mut twice = 0.0;
    for i in 0..n {
        let a = ring[i];
        let b = ring[(i + 1) % n];
        twice += a.perp_dot(b);
    }
    twice * 0.5
}

/// Length of a closed ring, its closing edge included.
///
/// ```
/// use glam::DVec2;
/// let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
/// assert_eq!(tracery_core::geom::ring_perimeter(&square), 4.0);
/// ```
pub fn ring_perimeter(ring: &[DVec2]) -> f64 {
    let n = ring.len();
    (0..n).map(|i| ring[i].distance(ring[(i + 1) % n])).sum()
}

/// Whether `p` lies inside `ring` (even-odd crossing test).
pub fn ring_contains(ring: &[DVec2], p: DVec2) -> bool {
    let mut inside = false;
    let n = ring.len();
    let mut j = n.wrapping_sub(1);
    for i in 0..n {
        let a = ring[i];
        let b = ring[j];
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
        j = i;
    }
    inside
}

impl Polygon {
    /// Area of the polygon (outer minus holes).
    pub fn area(&self) -> f64 {
        signed_area(&self.outer).abs() - self.holes.iter().map(|h| signed_area(h).abs()).sum::<f64>()
    }

    /// Whether `p` lies in the filled part of the polygon.
    pub fn contains(&self, p: DVec2) -> bool {
        ring_contains(&self.outer, p) && !self.holes.iter().any(|h| ring_contains(h, p))
    }

    /// All rings: the outer first, then the holes.
    pub fn rings(&self) -> impl Iterator<Item = &Vec<DVec2>> {
        std::iter::once(&self.outer).chain(self.holes.iter())
    }

    /// Distance from `p` to the nearest of the polygon's rings (inside or
    /// out); infinite for a polygon with no points.
    ///
    /// ```
    /// use glam::DVec2;
    /// use tracery_core::geom::Polygon;
    /// let square = Polygon { outer: vec![DVec2::ZERO, DVec2::X * 4.0, DVec2::splat(4.0), DVec2::Y * 4.0], holes: vec![] };
    /// assert_eq!(square.outline_distance(DVec2::new(1.0, 2.0)), 1.0);
    /// assert_eq!(square.outline_distance(DVec2::new(7.0, 2.0)), 3.0);
    /// ```
    pub fn outline_distance(&self, p: DVec2) -> f64 {
        self.rings().map(|ring| super::polyline_distance(ring, true, p)).fold(f64::INFINITY, f64::min)
    }

    /// Applies `f` to every point.
    pub fn map_points(&self, mut f: impl FnMut(DVec2) -> DVec2) -> Polygon {
        Polygon {
            outer: self.outer.iter().map(|&p| f(p)).collect(),
            holes: self.holes.iter().map(|h| h.iter().map(|&p| f(p)).collect()).collect(),
        }
    }
}

impl Region {
    /// A region made of the given polygons, taken as they are.
    pub fn new(polygons: Vec<Polygon>) -> Self {
        Region { polygons }
    }

    /// The rectangle `rect` as a region (counter-clockwise from its lower left).
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::geom::{Rect, Region};
    /// let r = Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::new(4.0, 3.0)));
    /// assert!((r.area() - 12.0).abs() < 1e-12);
    /// ```
    pub fn rectangle(rect: &Rect) -> Region {
        Region { polygons: vec![Polygon { outer: rect.corners().to_vec(), holes: Vec::new() }] }
    }

    /// Whether the region has no polygon.
    pub fn is_empty(&self) -> bool {
        self.polygons.is_empty()
    }

    /// Total filled area.
    pub fn area(&self) -> f64 {
        self.polygons.iter().map(Polygon::area).sum()
    }

    /// Number of polygons (components, for a region from a boolean operation).
    pub fn component_count(&self) -> usize {
        self.polygons.len()
    }

    /// Number of holes over all polygons.
    pub fn hole_count(&self) -> usize {
        self.polygons.iter().map(|p| p.holes.len()).sum()
    }

    /// Number of vertices over all rings.
    pub fn vertex_count(&self) -> usize {
        self.rings().map(Vec::len).sum()
    }

    /// All rings of all polygons.
    pub fn rings(&self) -> impl Iterator<Item = &Vec<DVec2>> {
        self.polygons.iter().flat_map(Polygon::rings)
    }

    /// How far the region reaches from the axis `y = 0` (in band space: from
    /// the curve), 0 for an empty region.
    pub fn reach_from_axis(&self) -> f64 {
        self.rings().flatten().map(|p| p.y.abs()).fold(0.0, f64::max)
    }

    /// The bounding box, or `None` for an empty region.
    pub fn bounds(&self) -> Option<Rect> {
        Rect::from_points(self.rings().flatten().copied())
    }

    /// Whether `p` lies in the filled part of the region.
    pub fn contains(&self, p: DVec2) -> bool {
        self.polygons.iter().any(|poly| poly.contains(p))
    }

    /// Applies `f` to every point.
    pub fn map_points(&self, mut f: impl FnMut(DVec2) -> DVec2) -> Region {
        Region { polygons: self.polygons.iter().map(|p| p.map_points(&mut f)).collect() }
    }

    /// The region moved by `offset`.
    pub fn translated(&self, offset: DVec2) -> Region {
        self.map_points(|p| p + offset)
    }
}
