//! Axis-aligned rectangles.

use glam::DVec2;
use serde::{Deserialize, Serialize};

/// An axis-aligned rectangle, `min` to `max` inclusive.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Rect {
    /// Lower-left corner (smallest `u` and `v`).
    pub min: DVec2,
    /// Upper-right corner.
    pub max: DVec2,
}

impl Rect {
    /// The rectangle spanning two corners, in any order.
    pub fn new(a: DVec2, b: DVec2) -> Self {
        Rect { min: a.min(b), max: a.max(b) }
    }

    /// The bounding box of `points`, or `None` when there are none.
    ///
    /// ```
    /// use glam::DVec2;
    /// use tracery_core::geom::Rect;
    /// let r = Rect::from_points([DVec2::new(1.0, 2.0), DVec2::new(-1.0, 5.0)]).unwrap();
    /// assert_eq!(r.size(), DVec2::new(2.0, 3.0));
    /// ```
    pub fn from_points(points: impl IntoIterator<Item = DVec2>) -> Option<Self> {
        let mut it = points.into_iter();
        let first = it.next()?;
        let (min, max) = it.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p)));
        Some(Rect { min, max })
    }

    /// Width and height.
    pub fn size(&self) -> DVec2 {
        self.max - self.min
    }

    /// Width (extent along `u`).
    pub fn width(&self) -> f64 {
        self.max.x - self.min.x
    }

    /// Height (extent along `v`).
    pub fn height(&self) -> f64 {
        self.max.y - self.min.y
    }

    /// The centre point.
    pub fn center(&self) -> DVec2 {
        (self.min + self.max) * 0.5
    }

    /// The smallest rectangle holding both.
    pub fn union(&self, other: &Rect) -> Rect {
        Rect { min: self.min.min(other.min), max: self.max.max(other.max) }
    }

    /// Whether the two rectangles share a point (touching counts).
    ///
    /// ```
    /// use glam::DVec2;
    /// use tracery_core::geom::Rect;
    /// let unit = Rect::new(DVec2::ZERO, DVec2::ONE);
    /// assert!(unit.overlaps(&Rect::new(DVec2::ONE, DVec2::splat(2.0))));
    /// assert!(!unit.overlaps(&Rect::new(DVec2::new(1.5, 0.0), DVec2::splat(2.0))));
    /// ```
    pub fn overlaps(&self, other: &Rect) -> bool {
        self.max.cmpge(other.min).all() && other.max.cmpge(self.min).all()
    }

    /// Whether `p` lies in the rectangle (its edges count).
    ///
    /// ```
    /// use glam::DVec2;
    /// use tracery_core::geom::Rect;
    /// let unit = Rect::new(DVec2::ZERO, DVec2::ONE);
    /// assert!(unit.contains(DVec2::ONE) && !unit.contains(DVec2::new(0.5, 1.5)));
    /// ```
    pub fn contains(&self, p: DVec2) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// The rectangle grown by `margin` on every side.
    pub fn inflate(&self, margin: f64) -> Rect {
        Rect { min: self.min - DVec2::splat(margin), max: self.max + DVec2::splat(margin) }
    }

    /// The four corners, counter-clockwise from `min`.
    pub fn corners(&self) -> [DVec2; 4] {
        [self.min, DVec2::new(self.max.x, self.min.y), self.max, DVec2::new(self.min.x, self.max.y)]
    }
}
