//! Rounding a curve's tight turns, so that a band of half-height below the
//! radius turns them instead of folding its inner edge.
//!
//! The rule is a disc of the radius rolled along each side of the curve.
//! Wherever it touches the curve, the curve is kept as drawn. Where the curve
//! turns tighter than the radius toward that side (a corner, the pointed end
//! of an ellipse, a heart's point and dip), the disc cannot reach in; there
//! the curve is replaced by an arc tangent to it where the disc touches it on
//! either side. So:
//!
//! - a curve that turns nowhere tighter than the radius comes back exactly as
//!   it was;
//! - each rounded stretch lies between the drawn curve and where its sides'
//!   tangents meet: within `r (sec(θ/2) − 1)` of the drawn curve for a turn
//!   of `θ` (`r (1 − cos(θ/2))` at a sharp corner), and the curve gets shorter
//!   only by what the arcs cut off (`r (2 tan(θ/2) − θ)` at a sharp corner).
//!
//! How a stretch is bridged:
//! - its ends are the nearest points the disc touches, moved out while the
//!   arc between their tangents does not fit (a cusp turns right round at
//!   its tip and less further out);
//! - of the pairs of ends found so, the one whose tangents are as long is
//!   kept: the arc then meets the curve at both ends, as the disc does;
//! - the arc is the widest that fits between the tangents (never tighter than
//!   the radius), so a wobble on a gentle curve is bridged by that curve's own
//!   arc, not by a tighter one cutting inside it;
//! - nothing the arc replaces may lie inside its disc (a bridge reaching
//!   across a turn the other way would), and a stretch whose sides turn away
//!   from the disc is a wobble, left as it is.
//!
//! Only what is near along the curve counts: the disc meets the curve within
//! a half turn of where it stands. A spiral's next winding, or the other leg
//! of a U narrower than the disc, is another matter: no rounding could widen
//! a U without moving its legs, so it is left as drawn (and the pipeline
//! warns that the band overlaps itself). Stretches turning more than
//! [`MAX_CORNER_TURN_DEG`] between any ends are left as drawn for the same
//! reason.

use glam::DVec2;

use super::Curve;
use super::blend_geometry::{ARC_STEP_DEG, arc_from, lines_meet, quadratic_min_radius};
use super::corners::turns;
use crate::geom::{closest_on_segment, polyline_distance};

/// A stretch turning more than this (a hairpin, a U) is left as drawn: the
/// lines beside it are nearly parallel, so an arc between them would reach
/// far from the curve, degrees.
pub const MAX_CORNER_TURN_DEG: f64 = 175.0;

/// The longest segment the disc is rolled over, as a share of the radius:
/// a coarse polygon (a square of four points) gets points between its
/// corners, so the disc has somewhere to touch. Never dropped points, never
/// moved ones: a straight run keeps its line.
const SEGMENT_PER_RADIUS: f64 = 0.125;

/// How far the curve may lie off a tangent and still run straight along
/// it, as a share of the radius.
const STRAIGHT_SIDE: f64 = 1e-3;

/// How far into a bridge's disc the curve it replaces may reach, as a share
/// of the radius: what is left of the hand's wobble.
const BRIDGE_SLACK: f64 = 0.02;

/// A stretch whose sides turn more than this away from the disc is left
/// as it is, degrees: a bridge would have to reach across that turn.
const WRONG_WAY_DEG: f64 = 2.0;

/// Two tangents within this of the chord between them are joined by the
/// chord itself (a dent in a straight run), degrees.
const STRAIGHT_BRIDGE_DEG: f64 = 1.0;

/// How far a disc may overlap the curve and still count as touching it, as
/// a share of the radius: a curve turning exactly on the radius, sampled
/// into chords, dips this little inside its own osculating disc.
const TOUCH_TOLERANCE: f64 = 1e-4;

impl Curve {
    /// The curve with every turn tighter than `radius` replaced by an arc of
    /// `radius`, tangent to the curve on either side: the arc of a disc of
    /// `radius` rolled along the inside of the turn, where the disc cannot
    /// reach into it. A band of half-height below `radius` then turns
    /// without folding.
    ///
    /// The contract, which the tests check on hand-drawn strokes:
    /// - where the curve turns no tighter than `radius`, it is kept exactly
    ///   as it was; a curve that turns nowhere tighter comes back unchanged;
    /// - a rounded stretch stays within the rounding's own offset of the
    ///   curve it replaces (`radius · (1 − cos(θ/2))` for a corner turning
    ///   by `θ`), and the length changes only by what the arcs cut off;
    /// - turns of more than [`MAX_CORNER_TURN_DEG`] within one stretch, and
    ///   closed curves tighter than `radius` all the way round, are left as
    ///   they are: no arc of `radius` fits them without moving the curve.
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// let square = Curve::regular_polygon(4, 50.0).unwrap();
    /// let rounded = square.with_rounded_corners(5.0);
    /// // Each corner loses 2r and gains a quarter circle: 4·(π/2 − 2)·r in all.
    /// let expected = square.length() + 4.0 * (std::f64::consts::FRAC_PI_2 - 2.0) * 5.0;
    /// assert!((rounded.length() - expected).abs() < 0.05);
    /// // The same square sampled every half millimetre is rounded the same.
    /// let sampled = square.resampled(0.5).with_rounded_corners(5.0);
    /// assert!((sampled.length() - expected).abs() < 0.05);
    /// // A circle wider than the radius is kept as it is.
    /// let circle = Curve::circle(30.0).unwrap();
    /// assert_eq!(circle.with_rounded_corners(5.0), circle);
    /// ```
    pub fn with_rounded_corners(&self, radius: f64) -> Curve {
        let closed = self.is_closed();
        let mut points = self.points().to_vec();
        if closed {
            points.pop();
        }
        if points.len() < 3 || !radius.is_finite() || radius <= 0.0 {
            return self.clone();
        }
        let mut polyline = Polyline::densified(&points, closed, radius * SEGMENT_PER_RADIUS);
        let mut changed = false;
        for side in [1.0, -1.0] {
            changed |= polyline.roll(side, radius);
        }
        if !changed {
            return self.clone();
        }
        Curve::from_polyline(&polyline.kept(), closed).unwrap_or_else(|_| self.clone())
    }
}

/// The polyline being rounded: its points, and which of them were the
/// curve's own (points put between them only give the disc somewhere to
/// touch, and are left out of the result where they were not needed).
struct Polyline {
    points: Vec<DVec2>,
    own: Vec<bool>,
    closed: bool,
}

impl Polyline {
    /// `points` with points put into every segment longer than `longest`.
    fn densified(points: &[DVec2], closed: bool, longest: f64) -> Polyline {
        let n = points.len();
        let segments = if closed { n } else { n - 1 };
        let mut out = Vec::with_capacity(n);
        let mut own = Vec::with_capacity(n);
        // A cap on the points added, for radii far below the curve's size.
        let budget = 200_000usize.saturating_sub(n);
        let total: f64 = (0..segments).map(|i| points[i].distance(points[(i + 1) % n])).sum();
        let longest = longest.max(total / budget.max(1) as f64);
        for i in 0..n {
            out.push(points[i]);
            own.push(true);
            if i < segments {
                let (a, b) = (points[i], points[(i + 1) % n]);
                let pieces = (a.distance(b) / longest).ceil() as usize;
                for k in 1..pieces {
                    out.push(a.lerp(b, k as f64 / pieces as f64));
                    own.push(false);
                }
            }
        }
        Polyline { points: out, own, closed }
    }

    fn len(&self) -> usize {
        self.points.len()
    }

    /// The points to keep: the curve's own, and every point a rounding drew.
    fn kept(&self) -> Vec<DVec2> {
        self.points.iter().zip(&self.own).filter(|(_, own)| **own).map(|(p, _)| *p).collect()
    }

    /// The point `i` (wrapping on a loop).
    fn at(&self, i: isize) -> DVec2 {
        self.points[i.rem_euclid(self.len() as isize) as usize]
    }

    /// The unit tangent at point `i`: the mean of the directions of the
    /// segments on either side (one at an open end).
    fn tangent(&self, i: isize) -> DVec2 {
        let n = self.len() as isize;
        let back = if self.closed || i > 0 { (self.at(i) - self.at(i - 1)).normalize_or_zero() } else { DVec2::ZERO };
        let ahead =
            if self.closed || i + 1 < n { (self.at(i + 1) - self.at(i)).normalize_or_zero() } else { DVec2::ZERO };
        (back + ahead).normalize_or_zero()
    }

    /// The unit direction from point `i` to point `j`, or zero past an
    /// open end.
    fn direction(&self, i: isize, j: isize) -> DVec2 {
        let n = self.len() as isize;
        if !self.closed && (i < 0 || j >= n) {
            return DVec2::ZERO;
        }
        (self.at(j) - self.at(i)).normalize_or_zero()
    }

    /// Rolls a disc of `radius` along the `side` of the polyline (+1 its
    /// left, −1 its right) and replaces each stretch the disc cannot touch
    /// with the disc's arc; whether anything changed.
    fn roll(&mut self, side: f64, radius: f64) -> bool {
        let n = self.len();
        if n < 3 {
            return false;
        }
        let touched = self.touched(side, radius);
        if !touched.contains(&true) {
            // Tighter than the disc all the way round: a loop smaller than
            // the radius, left as it is.
            return false;
        }
        // A loop is walked from the middle of its longest touched run, so
        // that bridges may reach as far as they need either way.
        let start = if self.closed { middle_of_longest_run(&touched) } else { 0 };
        // Stretches the disc cannot touch, each between two points it does,
        // walked from a touched point (so none wraps past the walk's start).
        let order: Vec<isize> =
            if self.closed { (start as isize..(start + n) as isize).collect() } else { (0..n as isize).collect() };
        let mut stretches: Vec<(isize, isize)> = Vec::new();
        let mut k = 0;
        while k < order.len() {
            let i = order[k];
            if touched[i.rem_euclid(n as isize) as usize] {
                k += 1;
                continue;
            }
            let mut last = k;
            while last + 1 < order.len() && !touched[order[last + 1].rem_euclid(n as isize) as usize] {
                last += 1;
            }
            stretches.push((order[k], order[last]));
            k = last + 1;
        }
        // Each stretch bridged between the touched points beside it, or
        // between points further out where the arc does not fit between
        // those. A bridge reaching into the one before takes its place (a
        // corner whose jitter cut it into several tight stretches is one
        // corner), and the stretches it spans need no bridge of their own.
        let (lowest, highest) = if self.closed { (order[0], order[0] + n as isize) } else { (0, n as isize - 1) };
        let mut bridges: Vec<Bridge> = Vec::new();
        let mut s = 0;
        while s < stretches.len() {
            let (first, last) = stretches[s];
            s += 1;
            if !self.closed && (first == 0 || last == n as isize - 1) {
                // Tight up to an open end: nothing to bridge to.
                continue;
            }
            let mut ends = (first - 1, last + 1);
            // Bridges this one took the place of, put back if it fails.
            let mut taken: Vec<Bridge> = Vec::new();
            let bridge = loop {
                let Some(bridge) = self.bridge(ends, (lowest, highest), side, radius) else { break None };
                match bridges.pop() {
                    Some(before) if before.to > bridge.from => {
                        // Both from the start of the one before.
                        ends = (ends.0.min(before.from), bridge.to);
                        taken.push(before);
                    }
                    before => {
                        bridges.extend(before);
                        break Some(bridge);
                    }
                }
            };
            if bridge.is_none() {
                bridges.extend(taken.into_iter().rev());
            }
            if let Some(bridge) = bridge {
                while s < stretches.len() && stretches[s].0 < bridge.to {
                    s += 1;
                }
                bridges.push(bridge);
            }
        }
        if bridges.is_empty() {
            return false;
        }
        self.apply(&bridges);
        true
    }

    /// Whether a disc of `radius` on the `side` of each point, tangent to
    /// the polyline there, stays off the polyline nearby: nothing of it
    /// within a half turn either way lies inside the disc.
    fn touched(&self, side: f64, radius: f64) -> Vec<bool> {
        let n = self.len() as isize;
        let turns = turns(&self.points, self.closed);
        let turn = |i: isize| turns[i.rem_euclid(n) as usize];
        let limit = MAX_CORNER_TURN_DEG.to_radians();
        let longest = (0..self.len() - usize::from(!self.closed))
            .map(|i| self.at(i as isize).distance(self.at(i as isize + 1)))
            .fold(0.0, f64::max);
        // A chord of length l of a curve turning exactly on the radius lies
        // l²/8r inside its disc.
        let inside = radius * (1.0 - TOUCH_TOLERANCE) - longest * longest / (8.0 * radius);
        (0..n)
            .map(|i| {
                let normal = self.tangent(i).perp() * side;
                if normal == DVec2::ZERO {
                    return true;
                }
                let centre = self.at(i) + normal * radius;
                // Walk each way while the curve has turned less than a
                // half turn from here.
                for step in [1isize, -1] {
                    let mut swept = 0.0;
                    let mut j = i;
                    for _ in 0..n - 1 {
                        let next = j + step;
                        if !self.closed && !(0..n).contains(&next) {
                            break;
                        }
                        if centre.distance(closest_on_segment(centre, self.at(j), self.at(next)).1) < inside {
                            return false;
                        }
                        swept += turn(next);
                        if swept.abs() > limit {
                            break;
                        }
                        j = next;
                    }
                }
                true
            })
            .collect()
    }

    /// The blend bridging the stretch between the touched points `a` and
    /// `b`, or between points further out (never past `lowest` or
    /// `highest`): each end moves out while the arc between the tangents
    /// there does not reach it.
    fn bridge(
        &self,
        (a, b): (isize, isize),
        (lowest, highest): (isize, isize),
        side: f64,
        radius: f64,
    ) -> Option<Bridge> {
        let n = self.len() as isize;
        let (mut from, mut to) = (a, b);
        while to - from < n {
            let (back, ahead) = match self.blend(from, to, side, radius) {
                Blend::Fits(..) => return self.balanced(from, to, (a, b), side, radius),
                Blend::WrongWay => return None,
                Blend::Short { start, end } => (start, end),
            };
            let (back, ahead) = (back && from > lowest, ahead && to < highest);
            if !back && !ahead {
                return None;
            }
            from -= isize::from(back);
            to += isize::from(ahead);
        }
        None
    }

    /// Of the blends from a point between `from` and `a` to one between `b`
    /// and `to`, the one whose arc meets both sides at their ends (the
    /// contact points of the disc, where its sides are as long) and holds
    /// its check. Reaching further out on one side than the other would
    /// run the curve along a straight tangent across what it replaces.
    fn balanced(&self, from: isize, to: isize, (a, b): (isize, isize), side: f64, radius: f64) -> Option<Bridge> {
        let mut best: Option<(f64, Bridge)> = None;
        for f in from..=a {
            for t in b..=to {
                let Blend::Fits(arc, check) = self.blend(f, t, side, radius) else { continue };
                let uneven = match check {
                    Check::Disc { legs, .. } => (legs.0 - legs.1).abs(),
                    Check::Turn(_) => 0.0,
                };
                if best.as_ref().is_some_and(|(u, _)| *u <= uneven) || !self.holds(f, t, &arc, &check, radius) {
                    continue;
                }
                best = Some((uneven, Bridge { from: f, to: t, arc }));
            }
        }
        best.map(|(_, bridge)| bridge)
    }

    /// Whether a blend from `from` to `to` keeps to the curve it replaces.
    fn holds(&self, from: isize, to: isize, arc: &[DVec2], check: &Check, radius: f64) -> bool {
        let replaced: Vec<DVec2> = (from..=to).map(|i| self.at(i)).collect();
        match *check {
            // The bridge is the arc of a disc rolled along the curve: nothing
            // it replaces lies inside that disc (a bridge reaching across a
            // turn the other way, a heart's dip, would hold it).
            Check::Disc { centre, radius: disc, .. } => {
                replaced.iter().all(|p| p.distance(centre) >= disc - BRIDGE_SLACK * radius)
            }
            // A blend no disc draws keeps to the curve as an arc round a
            // corner of its turn would.
            Check::Turn(turn) => {
                let allowed = radius * (1.0 / (0.5 * turn.abs()).cos() - 1.0) + BRIDGE_SLACK * radius;
                arc.iter().all(|&p| polyline_distance(&replaced, false, p) <= allowed)
            }
        }
    }

    /// A blend from point `from` to point `to`, tangent to the polyline at
    /// both and turning nowhere tighter than `radius`: an arc of `radius`
    /// between the two tangents, joined to them along their lines, or a
    /// quadratic Bézier through where the tangents meet; or which end is
    /// too near for one.
    fn blend(&self, from: isize, to: isize, side: f64, radius: f64) -> Blend {
        let (p_in, p_out) = (self.at(from), self.at(to));
        // Tangent to the segments kept on either side, so that the curve
        // runs on into the blend without a kink.
        let (t_in, t_out) = (self.direction(from - 1, from), self.direction(to, to + 1));
        let both = Blend::Short { start: true, end: true };
        if t_in == DVec2::ZERO || t_out == DVec2::ZERO {
            return both;
        }
        let cross = t_in.perp_dot(t_out);
        let chord = (p_out - p_in).normalize_or_zero();
        if cross * side <= 1e-9 {
            // Tangents parallel (a dent in a straight run) or turning the
            // other way: a straight bridge where both run along it.
            let along = STRAIGHT_BRIDGE_DEG.to_radians().cos();
            if t_in.dot(chord) >= along && t_out.dot(chord) >= along {
                return Blend::Fits(Vec::new(), Check::Turn(0.0));
            }
            // Reaching further out only gathers more of a turn the other
            // way: this is a wobble on a curve that turns away from the
            // disc, not a corner to round.
            return if t_in.angle_to(t_out).abs() > WRONG_WAY_DEG.to_radians() { Blend::WrongWay } else { both };
        }
        let turn = t_in.angle_to(t_out);
        if turn.abs() > MAX_CORNER_TURN_DEG.to_radians() {
            // A cusp (a heart's dip) turns right round; further out, where
            // its sides bend back, it turns less.
            return both;
        }
        let q = lines_meet(p_in, t_in, p_out, t_out);
        // The tangents must meet ahead of the blend's start and behind its end.
        if (q - p_in).dot(t_in) <= 0.0 || (p_out - q).dot(t_out) <= 0.0 {
            return both;
        }
        let (leg_in, leg_out) = ((q - p_in).length(), (p_out - q).length());
        let reach = radius * (0.5 * turn.abs()).tan();
        if reach <= leg_in.min(leg_out) {
            // Where the tangents meet at a point of the curve (a corner
            // drawn exactly, as in an SVG path), the arc is drawn from that
            // point and its sides, not from a point computed to rounding.
            if let Some(corner) = (from + 1..to).find(|&c| self.at(c).distance(q) <= 1e-9 * radius) {
                let (d_in, d_out) = (self.at(corner) - self.at(corner - 1), self.at(corner + 1) - self.at(corner));
                let turn = d_in.perp_dot(d_out).atan2(d_in.dot(d_out));
                let half = 0.5 * turn.abs();
                let reach = radius * half.tan();
                let arc = arc_from(self.at(corner), d_in.normalize(), turn, reach, reach / half.tan());
                return Blend::Fits(arc, Check::Turn(turn));
            }
            // Where the curve runs straight along both tangents as far as
            // the arc of the radius reaches (a corner between straight
            // sides), that arc, as asked. Elsewhere the widest arc that fits
            // between the tangents: where the stretch is a wobble on a
            // gentle curve, that arc is the curve's own, not a tighter one
            // cutting inside it.
            let straight = |p: DVec2, t: DVec2, upto: f64| {
                (from..=to).map(|i| self.at(i)).all(|x| {
                    let along = (x - p).dot(t);
                    along < 0.0 || along > upto || (x - p).perp_dot(t).abs() <= STRAIGHT_SIDE * radius
                })
            };
            let reach = if straight(p_in, t_in, leg_in - reach) && straight(p_out, -t_out, leg_out - reach) {
                reach
            } else {
                leg_in.min(leg_out)
            };
            let disc = reach / (0.5 * turn.abs()).tan();
            let centre = q - t_in * reach + t_in.perp() * disc * turn.signum();
            let check = Check::Disc { centre, radius: disc, legs: (leg_in, leg_out) };
            return Blend::Fits(arc_from(q, t_in, turn, reach, disc), check);
        }
        if quadratic_min_radius(p_in, q, p_out) >= radius {
            let by_turn = (turn.abs().to_degrees() / ARC_STEP_DEG).ceil() as usize;
            let by_length = ((p_out - p_in).length() / (0.25 * radius)).ceil() as usize;
            let count = by_turn.max(by_length).max(4);
            return Blend::Fits(
                (1..count)
                    .map(|k| {
                        let s = k as f64 / count as f64;
                        p_in * (1.0 - s) * (1.0 - s) + q * 2.0 * s * (1.0 - s) + p_out * s * s
                    })
                    .collect(),
                Check::Turn(turn),
            );
        }
        Blend::Short { start: leg_in < reach, end: leg_out < reach }
    }

    /// The polyline with each bridge's points in place of those strictly
    /// between its ends (which are kept, as the curve's own).
    fn apply(&mut self, bridges: &[Bridge]) {
        let n = self.len();
        let wrap = |i: isize| i.rem_euclid(n as isize) as usize;
        let mut dropped = vec![false; n];
        // A bridge's ends are kept as the curve's own: where it leaves the
        // curve and where it rejoins it.
        let mut end = vec![false; n];
        let mut inserted: Vec<Option<&Bridge>> = vec![None; n];
        for bridge in bridges {
            for i in bridge.from + 1..bridge.to {
                dropped[wrap(i)] = true;
            }
            end[wrap(bridge.from)] = true;
            end[wrap(bridge.to)] = true;
            inserted[wrap(bridge.from)] = Some(bridge);
        }
        let mut points = Vec::with_capacity(n);
        let mut own = Vec::with_capacity(n);
        for i in (0..n).filter(|&i| !dropped[i]) {
            points.push(self.points[i]);
            own.push(self.own[i] || end[i]);
            if let Some(bridge) = inserted[i] {
                points.extend_from_slice(&bridge.arc);
                own.extend(bridge.arc.iter().map(|_| true));
            }
        }
        self.points = points;
        self.own = own;
    }
}

/// What [`Polyline::blend`] found.
enum Blend {
    /// The points between the two ends, and how to check them.
    Fits(Vec<DVec2>, Check),
    /// No blend from here or further out: the sides turn away from the
    /// disc.
    WrongWay,
    /// Which end is too near the stretch.
    Short { start: bool, end: bool },
}

/// How a blend is checked against the curve it replaces.
enum Check {
    /// It is an arc of this disc, between tangents this long.
    Disc { centre: DVec2, radius: f64, legs: (f64, f64) },
    /// It turns by this much.
    Turn(f64),
}

/// An arc replacing the points strictly between `from` and `to` (indices
/// that may run past the end of a loop).
struct Bridge {
    from: isize,
    to: isize,
    arc: Vec<DVec2>,
}

/// The middle of the longest run of `true` in a cyclic sequence that has one.
fn middle_of_longest_run(flags: &[bool]) -> usize {
    let n = flags.len();
    let Some(off) = (0..n).find(|&i| !flags[i]) else { return 0 };
    // Runs counted from just after a `false`, so none wraps.
    let (mut best_start, mut best_length, mut run_start, mut length) = (0, 0, 0, 0);
    for k in 1..=n {
        if flags[(off + k) % n] {
            if length == 0 {
                run_start = k;
            }
            length += 1;
            if length > best_length {
                (best_start, best_length) = (run_start, length);
            }
        } else {
            length = 0;
        }
    }
    (off + best_start + best_length / 2) % n
}
