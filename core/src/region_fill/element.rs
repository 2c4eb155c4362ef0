//! Discrete elements (sections 4.1 and 4.4.1 of the curve-texture paper):
//! the small filled shapes of an exemplar (a dot, a leaf, a dash), learned
//! whole. Shapes alike up to a translation are one kind; each element is
//! one sample at its centre that matches only samples of its kind, and the
//! fill draws the kind's shape there, undistorted.

use glam::DVec2;

use crate::geom::{Polygon, Rect};

/// A filled shape is a discrete element when its bounding box's diagonal
/// is at most this many sample spacings: about the width of a
/// neighbourhood at the default radius (3.1 spacings), so that the
/// matching around its centre sees what lies beside it.
pub const ELEMENT_MAX_SPACINGS: f64 = 6.0;

/// Two shapes are one kind when, laid on each other by their centres, no
/// point of either outline lies farther than this share of the larger's
/// diagonal from the other's: the same dot drawn twice, not a dot and a
/// ring or a leaf turned another way.
pub const SAME_KIND_SHARE: f64 = 0.05;

/// A shape a person drew (or accepted and then edited) is taken for a kind
/// when it is this alike ([`SAME_KIND_SHARE`]'s measure): looser, since its
/// outline went through the canvas's smoothing.
pub const DRAWN_KIND_SHARE: f64 = 0.10;

/// An element of a pattern: its kind, and where its centre lies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlacedElement {
    /// Index into [`Elements::kinds`].
    pub kind: u32,
    /// The centre (the shape's centroid), mm.
    pub centre_mm: DVec2,
}

/// The discrete elements of a pattern.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Elements {
    /// Each kind's shape, mm, about its centroid.
    pub kinds: Vec<Polygon>,
    /// The elements.
    pub placed: Vec<PlacedElement>,
}

impl Elements {
    /// Adds `polygon` (mm) as an element, of a kind already known when
    /// one has the same shape ([`SAME_KIND_SHARE`]), or of a new kind.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::geom::Polygon;
    /// use tracery_core::region_fill::Elements;
    /// let square = |at: DVec2, side: f64| Polygon {
    ///     outer: vec![at, at + DVec2::X * side, at + DVec2::ONE * side, at + DVec2::Y * side],
    ///     holes: vec![],
    /// };
    /// let mut elements = Elements::default();
    /// elements.add(&square(DVec2::ZERO, 2.0));
    /// elements.add(&square(DVec2::new(10.0, 5.0), 2.0));
    /// elements.add(&square(DVec2::new(20.0, 0.0), 3.0));
    /// assert_eq!(elements.kinds.len(), 2, "two squares alike, one larger");
    /// assert_eq!(elements.placed[1].centre_mm, DVec2::new(11.0, 6.0));
    /// assert_eq!(elements.polygons()[1], square(DVec2::new(10.0, 5.0), 2.0));
    /// ```
    pub fn add(&mut self, polygon: &Polygon) {
        let centre_mm = centroid(polygon);
        let shape = polygon.map_points(|p| p - centre_mm);
        let kind = match self.kinds.iter().position(|k| unlikeness(k, &shape, SAME_KIND_SHARE).is_some()) {
            Some(k) => k,
            None => {
                self.kinds.push(shape);
                self.kinds.len() - 1
            }
        };
        self.placed.push(PlacedElement { kind: kind as u32, centre_mm });
    }

    /// `polygon` (mm) as an element of the kind most like it, within
    /// [`DRAWN_KIND_SHARE`]; `None` when no kind is that alike.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::geom::Polygon;
    /// use tracery_core::region_fill::Elements;
    /// let square = |at: DVec2, side: f64| Polygon {
    ///     outer: vec![at, at + DVec2::X * side, at + DVec2::ONE * side, at + DVec2::Y * side],
    ///     holes: vec![],
    /// };
    /// let mut elements = Elements::default();
    /// elements.add(&square(DVec2::ZERO, 2.0));
    /// elements.add(&square(DVec2::ZERO, 4.0));
    /// let like = elements.like(&square(DVec2::new(10.0, 0.0), 3.9)).unwrap();
    /// assert_eq!(like.kind, 1);
    /// assert!(like.centre_mm.distance(DVec2::new(11.95, 1.95)) < 1e-9);
    /// assert!(elements.like(&square(DVec2::ZERO, 3.0)).is_none());
    /// ```
    pub fn like(&self, polygon: &Polygon) -> Option<PlacedElement> {
        let centre_mm = centroid(polygon);
        let shape = polygon.map_points(|p| p - centre_mm);
        let (kind, _) = (self.kinds.iter().enumerate())
            .filter_map(|(k, kind)| Some((k, unlikeness(kind, &shape, DRAWN_KIND_SHARE)?)))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        Some(PlacedElement { kind: kind as u32, centre_mm })
    }

    /// Whether there are no elements.
    pub fn is_empty(&self) -> bool {
        self.placed.is_empty()
    }

    /// Each element's shape where it lies, mm.
    pub fn polygons(&self) -> Vec<Polygon> {
        self.placed.iter().map(|e| self.shape_at(e)).collect()
    }

    /// The shape of element `e`, mm.
    pub fn shape_at(&self, e: &PlacedElement) -> Polygon {
        self.kinds[e.kind as usize].map_points(|p| p + e.centre_mm)
    }

    /// The same elements drawn `factor` times larger, about the origin.
    pub fn scaled(&self, factor: f64) -> Elements {
        Elements {
            kinds: self.kinds.iter().map(|k| k.map_points(|p| p * factor)).collect(),
            placed: self.placed.iter().map(|e| PlacedElement { centre_mm: e.centre_mm * factor, ..*e }).collect(),
        }
    }

    /// The same kinds placed at `placed` instead.
    pub fn with_placed(&self, placed: Vec<PlacedElement>) -> Elements {
        Elements { kinds: self.kinds.clone(), placed }
    }
}

/// Whether a filled shape is small enough to be learned whole at sample
/// spacing `delta_mm` ([`ELEMENT_MAX_SPACINGS`]).
pub fn is_element_sized(polygon: &Polygon, delta_mm: f64) -> bool {
    Rect::from_points(polygon.outer.iter().copied())
        .is_some_and(|b| b.size().length() <= ELEMENT_MAX_SPACINGS * delta_mm)
}

/// The centroid of a polygon's area, holes taken out; the mean of its
/// outer points when it has no area.
pub fn centroid(polygon: &Polygon) -> DVec2 {
    let (mut weighted, mut area) = (DVec2::ZERO, 0.0);
    for ring in polygon.rings() {
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let cross = a.perp_dot(b);
            weighted += (a + b) * cross;
            area += cross;
        }
    }
    // Holes run the other way, so their terms subtract themselves.
    if area.abs() > 1e-12 {
        weighted / (3.0 * area)
    } else {
        polygon.outer.iter().copied().sum::<DVec2>() / polygon.outer.len().max(1) as f64
    }
}

/// The size of a shape's bounding box.
fn size(p: &Polygon) -> DVec2 {
    Rect::from_points(p.outer.iter().copied()).map_or(DVec2::ZERO, |r| r.size())
}

/// How far the point of `from`'s outlines farthest from `to`'s lies from them.
fn farthest(from: &Polygon, to: &Polygon) -> f64 {
    from.rings().flatten().map(|&p| to.outline_distance(p)).fold(0.0, f64::max)
}

/// How unlike two shapes, each about its centroid, are: the farthest a
/// point of either's outlines lies from the other's, as a share of the
/// larger's diagonal; `None` when that is over `share`.
fn unlikeness(a: &Polygon, b: &Polygon, share: f64) -> Option<f64> {
    let (size_a, size_b) = (size(a), size(b));
    let diagonal = size_a.length().max(size_b.length());
    let tolerance = share * diagonal;
    // Cheap refusals first: an exemplar may hold hundreds of shapes.
    if a.holes.len() != b.holes.len()
        || (size_a - size_b).abs().max_element() > 2.0 * tolerance
        || (a.area() - b.area()).abs() > 2.0 * tolerance * diagonal
    {
        return None;
    }
    let apart = farthest(a, b).max(farthest(b, a));
    (apart <= tolerance).then(|| apart / diagonal)
}
