//! [`CurvePath`]: one stroked path of a curve exemplar, flattened.

use glam::DVec2;

/// A path as a polyline, mm, `y` up.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CurvePath {
    /// The points in order.
    pub points_mm: Vec<DVec2>,
    /// Whether the path closes back to its first point.
    pub closed: bool,
}

impl CurvePath {
    /// Distance from `p` to the path, mm.
    pub fn distance_to(&self, p: DVec2) -> f64 {
        crate::geom::polyline_distance(&self.points_mm, self.closed, p)
    }

    /// The first and last points of an open path of two or more points;
    /// `None` for a loop, which has no ends.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::region_fill::CurvePath;
    /// let line = CurvePath { points_mm: vec![DVec2::ZERO, DVec2::X, DVec2::ONE], closed: false };
    /// assert_eq!(line.free_ends(), Some([DVec2::ZERO, DVec2::ONE]));
    /// assert_eq!(CurvePath { closed: true, ..line }.free_ends(), None);
    /// ```
    pub fn free_ends(&self) -> Option<[DVec2; 2]> {
        match (self.points_mm.first(), self.points_mm.last()) {
            (Some(&a), Some(&b)) if !self.closed && self.points_mm.len() >= 2 => Some([a, b]),
            _ => None,
        }
    }

    /// Straight pieces: one fewer than the points, or as many for a loop.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::region_fill::CurvePath;
    /// let square = vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    /// assert_eq!(CurvePath { points_mm: square.clone(), closed: true }.segment_count(), 4);
    /// assert_eq!(CurvePath { points_mm: square, closed: false }.segment_count(), 3);
    /// ```
    pub fn segment_count(&self) -> usize {
        match (self.points_mm.len(), self.closed) {
            (0 | 1, _) => 0,
            (n, true) => n,
            (n, false) => n - 1,
        }
    }

    /// The point a share `t` along segment `i`.
    pub fn segment_point(&self, i: usize, t: f64) -> DVec2 {
        let n = self.points_mm.len();
        let (a, b) = (self.points_mm[i % n], self.points_mm[(i + 1) % n]);
        a + (b - a) * t
    }

    /// Length of segment `i`, mm.
    pub fn segment_length(&self, i: usize) -> f64 {
        self.segment_point(i, 0.0).distance(self.segment_point(i, 1.0))
    }

    /// Arc length at the start of each segment, and the total last.
    pub fn cumulative_lengths(&self) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.segment_count() + 1);
        let mut s = 0.0;
        out.push(0.0);
        for i in 0..self.segment_count() {
            s += self.segment_length(i);
            out.push(s);
        }
        out
    }

    /// Length, mm.
    pub fn length_mm(&self) -> f64 {
        (0..self.segment_count()).map(|i| self.segment_length(i)).sum()
    }
}
