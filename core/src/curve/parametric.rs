//! Curves that patterns follow: arc-length parameterized polylines with normals.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::geom::closest_on_segment;

/// A smooth curve as a dense polyline, parameterized by arc length.
///
/// `u` runs along the curve from 0 to [`Curve::length`]; the band's `v`
/// axis is the left normal (counter-clockwise from the tangent).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Curve {
    points: Vec<DVec2>,
    /// Arc length at each point.
    arc: Vec<f64>,
    /// Unit tangent at each point, smoothed over a few segments.
    tangents: Vec<DVec2>,
    closed: bool,
}

/// Pairs of Taubin passes that [`Curve::from_stroke`] smooths a stroke
/// with: wiggles shorter than about ten samples fade, longer shapes stay.
const STROKE_SMOOTHING_PASSES: usize = 4;

/// Taubin's shrinking step.
const TAUBIN_SHRINK: f64 = 0.5;

/// Taubin's inflating step: a little stronger than the shrinking one, so
/// that long shapes keep their size.
const TAUBIN_INFLATE: f64 = -0.53;

/// How many segments [`Curve::locate_near`] steps from its hint before it
/// searches instead.
const NEAR_STEPS: usize = 4;

/// [`Curve::map`] for points that come in order along the curve (an
/// outline's, say): each starts from the segment of the one before, which
/// spares a search over the whole curve for most. Same points to the last
/// bit.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::curve::Curve;
/// let curve = Curve::circle(10.0).unwrap();
/// let cursor = curve.cursor();
/// for k in 0..100 {
///     let (u, v) = (k as f64 * 0.7, 0.5);
///     assert_eq!(cursor.map(u, v), curve.map(u, v));
/// }
/// ```
#[derive(Debug)]
pub struct CurveCursor<'a> {
    curve: &'a Curve,
    segment: std::cell::Cell<Option<usize>>,
}

impl CurveCursor<'_> {
    /// The point at `(u, v)` of band space, as [`Curve::map`] gives it.
    pub fn map(&self, u: f64, v: f64) -> DVec2 {
        let at = self.curve.locate_near(u, self.segment.get());
        self.segment.set(Some(at.0));
        self.curve.map_at(at, v)
    }
}

/// Why a curve could not be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CurveError {
    /// Fewer than two distinct points, or no length.
    #[error("the curve needs at least two distinct points")]
    TooShort,
    /// A coordinate is not a finite number.
    #[error("the curve has a coordinate that is not a number")]
    NotFinite,
    /// A drawing reaching farther than [`crate::setting::WORLD_EXTENT_MM`] from its origin.
    #[error("the drawing reaches {0:e} mm from its origin, more than 10000 mm (ten metres): check its units and size")]
    TooFar(f64),
    /// A drawing the curve was to be taken from is not an SVG document.
    #[error("this is not an SVG file ({0})")]
    NotSvg(String),
    /// The drawing has no path to follow.
    #[error("the SVG has no path to follow")]
    NoPath,
}

impl Curve {
    /// A curve through `points` as given (no smoothing); a closed curve joins
    /// the last point back to the first.
    pub fn from_polyline(points: &[DVec2], closed: bool) -> Result<Curve, CurveError> {
        if points.iter().any(|p| !p.is_finite()) {
            return Err(CurveError::NotFinite);
        }
        let mut pts: Vec<DVec2> = Vec::with_capacity(points.len() + 1);
        for &p in points {
            if pts.last().is_none_or(|q: &DVec2| q.distance(p) > 1e-9) {
                pts.push(p);
            }
        }
        if closed && pts.len() > 2 && pts[0].distance(*pts.last().unwrap()) <= 1e-9 {
            pts.pop();
        }
        if pts.len() < 2 {
            return Err(CurveError::TooShort);
        }
        if closed {
            pts.push(pts[0]);
        }
        let mut arc = Vec::with_capacity(pts.len());
        let mut acc = 0.0;
        arc.push(0.0);
        for w in pts.windows(2) {
            acc += w[0].distance(w[1]);
            arc.push(acc);
        }
        if acc <= 0.0 {
            return Err(CurveError::TooShort);
        }
        let mut curve = Curve { points: pts, arc, tangents: Vec::new(), closed };
        curve.tangents = curve.smoothed_tangents();
        Ok(curve)
    }

    /// Tangents at the points, each the direction of the chord across a
    /// window of four mean segments. A polyline's own tangent turns only at
    /// its vertices, and unevenly after resampling; an offset of the curve by
    /// `v` folds wherever the tangent turns faster than `1/v`, so the band
    /// needs a frame whose turning is spread evenly.
    fn smoothed_tangents(&self) -> Vec<DVec2> {
        let n = self.points.len();
        let window = 2.0 * self.length() / (n - 1) as f64;
        self.arc
            .iter()
            .enumerate()
            .map(|(k, &a)| {
                let chord = self.point(a + window) - self.point(a - window);
                chord.try_normalize().unwrap_or_else(|| {
                    let (i, j) = if k + 1 < n { (k, k + 1) } else { (k - 1, k) };
                    (self.points[j] - self.points[i]).normalize_or(DVec2::X)
                })
            })
            .collect()
    }

    /// A curve from a person's stroke: smoothed (Chaikin corner cutting) and
    /// resampled every `spacing` units, so jitter of the hand does not show.
    ///
    /// ```
    /// use glam::DVec2;
    /// use tracery_core::curve::Curve;
    /// let stroke: Vec<DVec2> = (0..50).map(|i| DVec2::new(i as f64, if i % 2 == 0 { 0.0 } else { 0.3 })).collect();
    /// let curve = Curve::from_stroke(&stroke, false, 1.0).unwrap();
    /// assert!((curve.length() - 49.0).abs() < 2.0);
    /// ```
    pub fn from_stroke(points: &[DVec2], closed: bool, spacing: f64) -> Result<Curve, CurveError> {
        let mut pts: Vec<DVec2> = Curve::from_polyline(points, closed)?.resampled(spacing).points;
        if closed {
            pts.pop();
        }
        for _ in 0..3 {
            pts = chaikin(&pts, closed);
        }
        // The hand's tremor and the pointer's pixel steps, every half
        // millimetre or so, outlast corner cutting: they wiggle the curve
        // on a radius of a millimetre or two, tighter than a band turns.
        // Taubin's smoothing takes out wiggles a few samples long without
        // shrinking what is longer (a loop, a drawn corner's legs).
        let mut pts = Curve::from_polyline(&pts, closed)?.resampled(spacing).points;
        if closed {
            pts.pop();
        }
        for _ in 0..STROKE_SMOOTHING_PASSES {
            pts = relaxed(&pts, closed, TAUBIN_SHRINK);
            pts = relaxed(&pts, closed, TAUBIN_INFLATE);
        }
        Ok(Curve::from_polyline(&pts, closed)?.resampled(spacing))
    }

    /// The same curve run the other way: its left side becomes its right,
    /// so a band along it shows the other face of its pattern.
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// let circle = Curve::circle(10.0).unwrap();
    /// assert!(circle.signed_area() > 0.0 && circle.reversed().signed_area() < 0.0);
    /// assert_eq!(circle.reversed().reversed(), circle);
    /// ```
    pub fn reversed(&self) -> Curve {
        let mut points = self.points.clone();
        if self.closed {
            points.pop();
            // A loop keeps its start point.
            points[1..].reverse();
        } else {
            points.reverse();
        }
        Curve::from_polyline(&points, self.closed).unwrap_or_else(|_| self.clone())
    }

    /// The area the curve winds round, positive where it runs
    /// counter-clockwise (x right, y up); 0 for an open curve.
    pub fn signed_area(&self) -> f64 {
        if !self.closed {
            return 0.0;
        }
        0.5 * self.points.windows(2).map(|w| w[0].perp_dot(w[1])).sum::<f64>()
    }

    /// A straight line of `length` along `+x`, from the origin.
    pub fn line(length: f64) -> Result<Curve, CurveError> {
        Curve::from_polyline(&[DVec2::ZERO, DVec2::new(length, 0.0)], false)
    }

    /// A circle of `radius` around the origin, counter-clockwise.
    pub fn circle(radius: f64) -> Result<Curve, CurveError> {
        let n = 720;
        let pts: Vec<DVec2> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                DVec2::new(radius * a.cos(), radius * a.sin())
            })
            .collect();
        Curve::from_polyline(&pts, true)
    }

    /// A heart `width` wide around the origin, counter-clockwise, with its
    /// point at the bottom and its dip at the top (both sharp).
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// let heart = Curve::heart(60.0).unwrap();
    /// assert!(heart.is_closed() && heart.length() > 150.0);
    /// ```
    pub fn heart(width: f64) -> Result<Curve, CurveError> {
        let n = 720;
        let scale = width / 32.0;
        let pts: Vec<DVec2> = (0..n)
            .map(|i| {
                let t = -std::f64::consts::TAU * i as f64 / n as f64;
                let x = 16.0 * t.sin().powi(3);
                let y = 13.0 * t.cos() - 5.0 * (2.0 * t).cos() - 2.0 * (3.0 * t).cos() - (4.0 * t).cos();
                DVec2::new(x, y) * scale
            })
            .collect();
        Curve::from_polyline(&pts, true)
    }

    /// A smooth S curve of arc length `length`: one period of a sine whose
    /// amplitude is an eighth of its span.
    pub fn wave(length: f64) -> Result<Curve, CurveError> {
        let n = 600;
        let unit: Vec<DVec2> = (0..=n)
            .map(|i| {
                let t = i as f64 / n as f64;
                DVec2::new(t, (std::f64::consts::TAU * t).sin() / 8.0)
            })
            .collect();
        let unit_length: f64 = unit.windows(2).map(|w| w[0].distance(w[1])).sum();
        let pts: Vec<DVec2> = unit.iter().map(|p| *p * (length / unit_length)).collect();
        Curve::from_polyline(&pts, false)
    }

    /// A closed polygon through `corners`, counter-clockwise, with sharp corners.
    fn frame(corners: Vec<DVec2>) -> Result<Curve, CurveError> {
        Curve::from_polyline(&corners, true)
    }

    /// A regular polygon with `sides` sides (at least 3) inscribed in a circle
    /// of `radius` around the origin, one side at the bottom: a square or
    /// hexagonal picture frame.
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// let square = Curve::regular_polygon(4, 10.0).unwrap();
    /// assert!((square.length() - 4.0 * 10.0 * 2f64.sqrt()).abs() < 1e-9);
    /// ```
    pub fn regular_polygon(sides: usize, radius: f64) -> Result<Curve, CurveError> {
        if sides < 3 {
            return Err(CurveError::TooShort);
        }
        let start = -std::f64::consts::FRAC_PI_2 - std::f64::consts::PI / sides as f64;
        Curve::frame(
            (0..sides)
                .map(|i| {
                    let a = start + std::f64::consts::TAU * i as f64 / sides as f64;
                    DVec2::new(radius * a.cos(), radius * a.sin())
                })
                .collect(),
        )
    }

    /// A star with `points` tips on a circle of `radius`, its inner corners at
    /// half the radius.
    pub fn star(points: usize, radius: f64) -> Result<Curve, CurveError> {
        if points < 3 {
            return Err(CurveError::TooShort);
        }
        Curve::frame(
            (0..2 * points)
                .map(|i| {
                    let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * i as f64 / points as f64;
                    let r = if i % 2 == 0 { radius } else { 0.5 * radius };
                    DVec2::new(r * a.cos(), r * a.sin())
                })
                .collect(),
        )
    }

    /// The same curve with points every `spacing` units of arc length.
    pub fn resampled(&self, spacing: f64) -> Curve {
        let count = ((self.length() / spacing.max(1e-9)).ceil() as usize).clamp(2, 200_000);
        let mut pts: Vec<DVec2> = (0..=count).map(|k| self.point(self.length() * k as f64 / count as f64)).collect();
        if self.closed {
            pts.pop();
        }
        Curve::from_polyline(&pts, self.closed).unwrap_or_else(|_| self.clone())
    }

    /// Total arc length.
    pub fn length(&self) -> f64 {
        *self.arc.last().unwrap_or(&0.0)
    }

    /// Whether the curve is a loop.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The polyline points (on a loop, the first point is repeated at the end).
    pub fn points(&self) -> &[DVec2] {
        &self.points
    }

    /// Segment index and fraction for arc length `u` (wrapped on loops, clamped otherwise).
    fn locate(&self, u: f64) -> (usize, f64) {
        self.locate_near(u, None)
    }

    /// [`Self::locate`], trying segment `near` and the few after and before
    /// it first: the answer is the same, found without a search when
    /// successive calls ask about nearby arc lengths.
    fn locate_near(&self, u: f64, near: Option<usize>) -> (usize, f64) {
        let length = self.length();
        let u = if self.closed { u.rem_euclid(length) } else { u.clamp(0.0, length) };
        // The last segment whose start is at or before `u` (the first or the
        // last segment for `u` outside).
        let last = self.arc.len() - 2;
        let fits = |k: usize| (k == 0 || self.arc[k] <= u) && (k == last || self.arc[k + 1] > u);
        let walked = near.and_then(|k| {
            let mut k = k.min(last);
            for _ in 0..NEAR_STEPS {
                if fits(k) {
                    return Some(k);
                }
                k = if self.arc[k] <= u { k + 1 } else { k - 1 };
            }
            None
        });
        let k = walked.unwrap_or_else(|| self.arc.partition_point(|&a| a <= u).clamp(1, self.arc.len() - 1) - 1);
        let span = self.arc[k + 1] - self.arc[k];
        (k, if span > 0.0 { (u - self.arc[k]) / span } else { 0.0 })
    }

    /// The point at arc length `u`.
    pub fn point(&self, u: f64) -> DVec2 {
        let (k, t) = self.locate(u);
        self.points[k].lerp(self.points[k + 1], t)
    }

    /// The unit tangent at arc length `u`, interpolated between the smoothed
    /// tangents of the points so that it turns continuously and evenly.
    pub fn tangent(&self, u: f64) -> DVec2 {
        self.tangent_at(self.locate(u))
    }

    /// The tangent at segment `k`, fraction `t` ([`Self::locate`]).
    fn tangent_at(&self, (k, t): (usize, f64)) -> DVec2 {
        if self.tangents.is_empty() {
            return (self.points[k + 1] - self.points[k]).normalize_or(DVec2::X);
        }
        self.tangents[k].lerp(self.tangents[k + 1], t).normalize_or(self.tangents[k])
    }

    /// Where an open curve starts and ends: each end's point and the direction
    /// pointing away from the curve (empty on loops).
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// let ends = Curve::line(10.0).unwrap().path_ends();
    /// assert_eq!(ends[1][0].x, 10.0);
    /// assert_eq!(ends[0][1].x, -1.0);
    /// assert!(Curve::circle(5.0).unwrap().path_ends().is_empty());
    /// ```
    pub fn path_ends(&self) -> Vec<[DVec2; 2]> {
        if self.closed {
            return Vec::new();
        }
        let end = self.length();
        vec![[self.point(0.0), -self.tangent(0.0)], [self.point(end), self.tangent(end)]]
    }

    /// The unit left normal at arc length `u`.
    pub fn normal(&self, u: f64) -> DVec2 {
        self.tangent(u).perp()
    }

    /// Signed curvature at arc length `u` (positive when turning left), from
    /// the turning of the tangent over `window` units of arc.
    pub fn curvature(&self, u: f64, window: f64) -> f64 {
        let h = 0.5 * window.max(1e-9);
        let (a, b) = if self.closed { (u - h, u + h) } else { ((u - h).max(0.0), (u + h).min(self.length())) };
        if b - a <= 0.0 {
            return 0.0;
        }
        let ta = self.tangent(a);
        let tb = self.tangent(b);
        ta.perp_dot(tb).atan2(ta.dot(tb)) / (b - a)
    }

    /// The point at `(u, v)` of band space: `u` along the curve, `v` along the left normal.
    pub fn map(&self, u: f64, v: f64) -> DVec2 {
        self.map_at(self.locate(u), v)
    }

    /// The point at `v` along the left normal from segment `k`, fraction `t`.
    fn map_at(&self, (k, t): (usize, f64), v: f64) -> DVec2 {
        // One search for the segment serves the point and the normal.
        self.points[k].lerp(self.points[k + 1], t) + self.tangent_at((k, t)).perp() * v
    }

    /// A [`CurveCursor`] on this curve, for mapping points in order along it.
    pub fn cursor(&self) -> CurveCursor<'_> {
        CurveCursor { curve: self, segment: std::cell::Cell::new(None) }
    }

    /// Winding number of the (closed) curve around `p`.
    pub fn winding(&self, p: DVec2) -> i32 {
        let mut w = 0;
        for s in self.points.windows(2) {
            let (a, b) = (s[0], s[1]);
            if a.y <= p.y {
                if b.y > p.y && (b - a).perp_dot(p - a) > 0.0 {
                    w += 1;
                }
            } else if b.y <= p.y && (b - a).perp_dot(p - a) < 0.0 {
                w -= 1;
            }
        }
        w
    }

    /// Distance from `p` to the curve.
    pub fn distance(&self, p: DVec2) -> f64 {
        self.points.windows(2).map(|s| p.distance(closest_on_segment(p, s[0], s[1]).1)).fold(f64::INFINITY, f64::min)
    }
}

/// Each point moved by `factor` of the way to the middle of its neighbours
/// (an open polyline's ends stay): one pass of Taubin's smoothing.
fn relaxed(points: &[DVec2], closed: bool, factor: f64) -> Vec<DVec2> {
    let n = points.len();
    if n < 3 {
        return points.to_vec();
    }
    (0..n)
        .map(|i| {
            if !closed && (i == 0 || i + 1 == n) {
                return points[i];
            }
            let middle = 0.5 * (points[(i + n - 1) % n] + points[(i + 1) % n]);
            points[i] + (middle - points[i]) * factor
        })
        .collect()
}

fn chaikin(points: &[DVec2], closed: bool) -> Vec<DVec2> {
    let n = points.len();
    if n < 3 {
        return points.to_vec();
    }
    let mut out = Vec::with_capacity(2 * n);
    if !closed {
        out.push(points[0]);
    }
    let segments = if closed { n } else { n - 1 };
    for i in 0..segments {
        let a = points[i];
        let b = points[(i + 1) % n];
        out.push(a.lerp(b, 0.25));
        out.push(a.lerp(b, 0.75));
    }
    if !closed {
        out.push(points[n - 1]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cursor_maps_every_point_as_the_curve_does() {
        // An uneven polyline, open and closed, and arc lengths that step
        // along, jump back and forth, and fall outside the curve.
        let points: Vec<DVec2> =
            (0..300).map(|k| DVec2::new(k as f64 + 0.3 * (k as f64).sin(), (0.05 * k as f64).cos() * 8.0)).collect();
        for closed in [false, true] {
            let curve = Curve::from_polyline(&points, closed).unwrap();
            let cursor = curve.cursor();
            let length = curve.length();
            let mut random = crate::random::SplitMix64::new(7);
            let mut u = 0.0;
            for k in 0..5000 {
                u = if k % 50 == 0 { (random.next_unit() * 1.4 - 0.2) * length } else { u + 0.37 };
                let v = random.next_unit() - 0.5;
                assert_eq!(cursor.map(u, v), curve.map(u, v), "closed {closed}, u {u}");
            }
        }
    }
}
