//! Sharp corners of a curve: kept where a path is resampled, and replaced
//! by circular arcs (or blends into the curve) so that a band turns them
//! instead of folding over itself.
//!
//! A corner is a vertex that turns by [`CORNER_ANGLE_DEG`] or more, or a run
//! of such vertices turning the same way on a tighter radius than the arc
//! wanted (a small arc of the path, flattened). Each arc reaches as far along
//! the straight runs beside the corner as half of each run, not only half of
//! the next segment: on a path sampled every half millimetre that was a
//! quarter of a millimetre, so a square frame drawn in SVG kept its corners
//! sharp where the same frame given as `square:` had them rounded. Where the
//! curve beside a corner is not straight, the corner is blended into it.

use glam::DVec2;

use super::Curve;

/// A vertex that turns by more than this is a corner that
/// [`Curve::with_rounded_corners`] rounds, degrees.
pub const CORNER_ANGLE_DEG: f64 = 5.0;

/// How far a point may lie off the line of a straight run and still belong
/// to it, as a share of the rounding radius: a resampled straight segment
/// lies on its line to rounding; a drawn stroke does not, and its run ends
/// at the next point, as before.
const STRAIGHT_TOLERANCE: f64 = 1e-3;

/// A corner turning more than this (a hairpin) is left as it is: the lines
/// beside it are nearly parallel, so where they meet is ill-defined, degrees.
const MAX_CORNER_TURN_DEG: f64 = 175.0;

/// Degrees of arc between the points that draw a rounded corner.
const ARC_STEP_DEG: f64 = 3.0;

impl Curve {
    /// The curve with points about every `spacing` units of arc length, its
    /// corners (vertices turning [`CORNER_ANGLE_DEG`] or more) kept where
    /// they are: each stretch between two corners is sampled evenly on its
    /// own. Sampled straight through, a corner is cut by a short chord, and
    /// the straight sides beside it no longer meet where they were drawn.
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// let square = Curve::regular_polygon(4, 50.0).unwrap();
    /// let sampled = square.resampled_keeping_corners(0.7);
    /// for corner in square.points() {
    ///     assert!(sampled.points().iter().any(|p| p.distance(*corner) < 1e-9));
    /// }
    /// assert!((sampled.length() - square.length()).abs() < 1e-9);
    /// ```
    pub fn resampled_keeping_corners(&self, spacing: f64) -> Curve {
        let closed = self.is_closed();
        let mut points = self.points().to_vec();
        if closed {
            points.pop();
        }
        let n = points.len();
        let threshold = CORNER_ANGLE_DEG.to_radians();
        let corners: Vec<usize> =
            (0..n).zip(turns(&points, closed)).filter(|(_, t)| t.abs() >= threshold).map(|(i, _)| i).collect();
        if n < 3 || corners.is_empty() || spacing.is_nan() || spacing <= 0.0 {
            return self.resampled(spacing);
        }
        // Stretches from corner to corner (and from the ends, when open).
        let mut stops: Vec<usize> = corners.clone();
        if closed {
            stops.push(corners[0] + n);
        } else {
            stops.insert(0, 0);
            stops.push(n - 1);
        }
        let mut out: Vec<DVec2> = Vec::new();
        for pair in stops.windows(2) {
            let stretch: Vec<DVec2> = (pair[0]..=pair[1]).map(|i| points[i % n]).collect();
            let Ok(piece) = Curve::from_polyline(&stretch, false) else { continue };
            let count = ((piece.length() / spacing).ceil() as usize).max(1);
            // Each stretch's last point is the next one's first.
            out.extend((0..count).map(|k| piece.point(piece.length() * k as f64 / count as f64)));
        }
        if !closed {
            out.push(points[n - 1]);
        }
        Curve::from_polyline(&out, closed).unwrap_or_else(|_| self.resampled(spacing))
    }

    /// The curve with every sharp corner replaced by a circular arc of
    /// `radius`, or by a blend into the curve where the stretches beside the
    /// corner are not straight (an arc smaller than `radius` where neither
    /// fits), so that a band of half-height below `radius` turns the corner
    /// without folding. Vertices that turn less than [`CORNER_ANGLE_DEG`] are
    /// left as they are: finely sampled smooth curves come back unchanged.
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
    /// let circle = Curve::circle(30.0).unwrap();
    /// assert_eq!(circle.with_rounded_corners(5.0), circle);
    /// ```
    pub fn with_rounded_corners(&self, radius: f64) -> Curve {
        let closed = self.is_closed();
        let mut points = self.points().to_vec();
        if closed {
            points.pop();
        }
        if points.len() < 3 || radius.is_nan() || radius <= 0.0 {
            return self.clone();
        }
        match rounded(&points, closed, radius) {
            Some(out) => Curve::from_polyline(&out, closed).unwrap_or_else(|_| self.clone()),
            None => self.clone(),
        }
    }
}

/// A corner found on the polyline: the vertices it drops, inclusive and in
/// order (wrapping on a closed curve), and the arc that replaces them.
struct Corner {
    first: usize,
    last: usize,
    arc: Vec<DVec2>,
}

/// The polyline with its corners rounded, or `None` where it has none.
fn rounded(points: &[DVec2], closed: bool, radius: f64) -> Option<Vec<DVec2>> {
    let n = points.len();
    let threshold = CORNER_ANGLE_DEG.to_radians();
    let at = |i: isize| points[i.rem_euclid(n as isize) as usize];
    let turns = turns(points, closed);
    let turn = |i: isize| turns[i.rem_euclid(n as isize) as usize];
    let is_corner = |i: isize| turn(i).abs() >= threshold;
    if !(0..n as isize).any(is_corner) {
        return None;
    }
    // Two neighbouring corners are one where they turn the same way on an
    // arc tighter than `radius`: the segment between them is shorter than
    // the radius times the angle they turn by on average.
    let joined = |i: isize| {
        is_corner(i)
            && is_corner(i + 1)
            && (closed || i + 1 < n as isize)
            && turn(i).signum() == turn(i + 1).signum()
            && at(i).distance(at(i + 1)) < radius * 0.5 * (turn(i).abs() + turn(i + 1).abs())
    };
    // On a loop, start where no run is cut in two; a loop that is one run
    // all the way round is a small closed curve, left as it is.
    let start = if closed { (0..n as isize).find(|&i| !joined(i - 1))? } else { 0 };
    let mut runs: Vec<(isize, isize)> = Vec::new();
    let mut i = start;
    while i < start + n as isize {
        if !is_corner(i) {
            i += 1;
            continue;
        }
        let mut last = i;
        while last + 1 < start + n as isize && joined(last) {
            last += 1;
        }
        runs.push((i, last));
        i = last + 1;
    }
    // Two corners turning the same way, both within what the arc of their
    // turns together would take (its reach either side), are one corner: a
    // corner cut by a chord (a drawn stroke's control points seldom fall on
    // the corner) is two half corners a few millimetres apart, each of
    // which could only take a tiny arc.
    let run_turn = |(a, b): (isize, isize)| (a..=b).map(turn).sum::<f64>();
    let arc_reach = |t: f64| radius * (0.5 * t.abs()).tan();
    let overlapping = |first: (isize, isize), second: (isize, isize)| {
        let (t1, t2, both) = (run_turn(first), run_turn(second), run_turn((first.0, second.1)));
        let gap: f64 = (first.1..second.0).map(|i| at(i).distance(at(i + 1))).sum();
        t1.signum() == t2.signum() && both.abs() < MAX_CORNER_TURN_DEG.to_radians() && gap < 2.0 * arc_reach(both)
    };
    let mut merged: Vec<(isize, isize)> = Vec::with_capacity(runs.len());
    for run in runs {
        match merged.last_mut() {
            Some(last) if overlapping(*last, run) => last.1 = run.1,
            _ => merged.push(run),
        }
    }
    if closed && merged.len() >= 2 {
        let (first, last) = (merged[0], merged[merged.len() - 1]);
        let wrapped = (first.0 + n as isize, first.1 + n as isize);
        if overlapping(last, wrapped) {
            merged.remove(0);
            let end = merged.len() - 1;
            merged[end].1 = wrapped.1;
        }
    }
    let runs = merged;
    // The corner of runs `first..=last` (one run, or two taken together),
    // and whether it turns on the whole radius.
    let round = |first: usize, last: usize| -> (Option<Corner>, bool) {
        let (a, b) = (runs[first].0, runs[last].1);
        // The previous and the next corner (whose arcs take the other half
        // of what lies between) or an open end.
        let previous_end = match first {
            0 if closed => runs[runs.len() - 1].1 - n as isize,
            0 => 0,
            _ => runs[first - 1].1,
        };
        let next_start = match runs.get(last + 1) {
            Some(next) => next.0,
            None if closed => runs[0].0 + n as isize,
            None => n as isize - 1,
        };
        // How far a blend may reach: half the way to the neighbouring
        // corners, all the way to an open end (keeping a segment there to
        // take the tangent from).
        let lowest = if !closed && first == 0 { 1 } else { (previous_end + a + 1) / 2 };
        let highest = if !closed && last + 1 == runs.len() { n as isize - 2 } else { (b + next_start) / 2 };
        let total = run_turn((a, b));
        let arc = if total.abs() < MAX_CORNER_TURN_DEG.to_radians() {
            arc_corner(&at, (a, b), total, (previous_end, next_start), n, radius)
        } else {
            None
        };
        // Where the arc falls short of the radius (the stretches beside the
        // corner are curved, or it is a cusp), a blend into the curve on
        // either side, if one turns wide enough.
        match arc {
            Some((corner, r)) if r >= radius * (1.0 - 1e-9) => (Some(corner), true),
            arc => match blended_corner(&at, (a, b), (lowest, highest), n, radius) {
                Some(blend) => (Some(blend), true),
                None => (arc.map(|(c, _)| c), false),
            },
        }
    };
    let mut corners: Vec<Corner> = Vec::new();
    let mut k = 0;
    while k < runs.len() {
        let (corner, full) = round(k, k);
        // A corner that cannot turn on the whole radius, taken together
        // with the next one where that one turns the same way (a corner cut
        // by a chord, its halves too far apart to count as overlapping).
        if !full
            && k + 1 < runs.len()
            && run_turn(runs[k]).signum() == run_turn(runs[k + 1]).signum()
            && let (Some(both), true) = round(k, k + 1)
        {
            corners.push(both);
            k += 2;
            continue;
        }
        corners.extend(corner);
        k += 1;
    }
    if corners.is_empty() {
        return None;
    }
    // Each vertex's corner, where one drops it; each corner is drawn where
    // its first dropped vertex was. A corner reaching into vertices another
    // already drops is left out (each keeps to half the way to the next,
    // so only rounding could make two meet).
    let mut dropped_by: Vec<Option<usize>> = vec![None; n];
    for (c, corner) in corners.iter().enumerate() {
        let span = (corner.last + n - corner.first) % n + 1;
        let vertices = || (0..span).map(|k| (corner.first + k) % n);
        if vertices().all(|i| dropped_by[i].is_none()) {
            vertices().for_each(|i| dropped_by[i] = Some(c));
        }
    }
    let mut out = Vec::with_capacity(n + corners.iter().map(|c| c.arc.len()).sum::<usize>());
    for (i, &point) in points.iter().enumerate() {
        match dropped_by[i] {
            None => out.push(point),
            Some(c) if corners[c].first == i => out.extend_from_slice(&corners[c].arc),
            Some(_) => {}
        }
    }
    Some(out)
}

/// The arc of `radius` tangent to the lines into and out of the run
/// `a..=b`, turning by `total`, reaching along the straight runs beside it
/// as far as half of each (so less than `radius` where they are short), and
/// the radius it has.
fn arc_corner(
    at: &impl Fn(isize) -> DVec2,
    (a, b): (isize, isize),
    total: f64,
    (previous_end, next_start): (isize, isize),
    n: usize,
    radius: f64,
) -> Option<(Corner, f64)> {
    let tolerance = STRAIGHT_TOLERANCE * radius;
    let t_in = (at(a) - at(a - 1)).normalize_or_zero();
    let t_out = (at(b + 1) - at(b)).normalize_or_zero();
    let cross = t_in.perp_dot(t_out);
    if t_in == DVec2::ZERO || t_out == DVec2::ZERO || cross.abs() < 1e-12 {
        return None;
    }
    // Where the lines of the segments into and out of the run meet.
    let apex = if a == b { at(a) } else { lines_meet(at(a - 1), t_in, at(b + 1), t_out) };
    let back = straight_run(&at, apex, -t_in, a - 1, -1, previous_end.max(b + 1 - n as isize), tolerance);
    let ahead = straight_run(&at, apex, t_out, b + 1, 1, next_start.min(a - 1 + n as isize), tolerance);
    let half_turn = 0.5 * total.abs();
    let reach = (radius * half_turn.tan()).min(0.5 * back.0).min(0.5 * ahead.0);
    if reach <= 0.0 {
        return None;
    }
    // Drop every vertex of the run, and those beside it nearer the apex
    // than the arc's ends.
    let mut first = a;
    while first > back.1 && at(first - 1).distance(apex) < reach {
        first -= 1;
    }
    let mut last = b;
    while last < ahead.1 && at(last + 1).distance(apex) < reach {
        last += 1;
    }
    let r = reach / half_turn.tan();
    let arc = arc_from(apex, t_in, total, reach, r);
    let wrap = |i: isize| i.rem_euclid(n as isize) as usize;
    Some((Corner { first: wrap(first), last: wrap(last), arc }, r))
}

/// A blend from a vertex before the run `a..=b` to one after it, tangent
/// to the curve at both: an arc of `radius` between the two tangents where
/// they are long enough for it, or else a quadratic Bézier through the point
/// where they meet; the nearest such pair of vertices whose blend turns on
/// no tighter radius than `radius`, its ends between `lowest` and
/// `highest`. Where the curve beside a corner is curved (the sides of a
/// heart's point, the taper of a smoothed stroke's corner), no straight run
/// leads to it, and an arc tangent to the segments next to the corner would
/// be tiny.
fn blended_corner(
    at: &impl Fn(isize) -> DVec2,
    (a, b): (isize, isize),
    (lowest, highest): (isize, isize),
    n: usize,
    radius: f64,
) -> Option<Corner> {
    let steps = (a - lowest).min(highest - b);
    for m in 1..=steps {
        let (i_in, i_out) = (a - m, b + m);
        let (p_in, p_out) = (at(i_in), at(i_out));
        let t_in = (p_in - at(i_in - 1)).normalize_or_zero();
        let t_out = (at(i_out + 1) - p_out).normalize_or_zero();
        let cross = t_in.perp_dot(t_out);
        if cross.abs() < 1e-9 {
            continue;
        }
        let q = lines_meet(p_in, t_in, p_out, t_out);
        // The tangents must meet ahead of the blend's start and behind its end.
        if (q - p_in).dot(t_in) <= 0.0 || (p_out - q).dot(t_out) <= 0.0 {
            continue;
        }
        let turn = t_in.angle_to(t_out);
        let (leg_in, leg_out) = ((q - p_in).length(), (p_out - q).length());
        let reach = radius * (0.5 * turn.abs()).tan();
        let blend: Vec<DVec2> = if turn.abs() < MAX_CORNER_TURN_DEG.to_radians() && reach <= leg_in.min(leg_out) {
            // An arc of the radius between the two tangents, joined to the
            // curve along them: the tangents' own lines are straight, so
            // nothing turns tighter than the arc.
            arc_from(q, t_in, turn, reach, radius)
        } else if quadratic_min_radius(p_in, q, p_out) >= radius {
            let by_turn = (turn.abs().to_degrees() / ARC_STEP_DEG).ceil() as usize;
            let by_length = ((p_out - p_in).length() / (0.25 * radius)).ceil() as usize;
            let count = by_turn.max(by_length).max(4);
            (1..count)
                .map(|k| {
                    let s = k as f64 / count as f64;
                    p_in * (1.0 - s) * (1.0 - s) + q * 2.0 * s * (1.0 - s) + p_out * s * s
                })
                .collect()
        } else {
            continue;
        };
        let wrap = |i: isize| i.rem_euclid(n as isize) as usize;
        return Some(Corner { first: wrap(i_in + 1), last: wrap(i_out - 1), arc: blend });
    }
    None
}

/// The tightest radius of curvature of the quadratic Bézier `p0, p1, p2`,
/// sampled finely enough for the blends here.
fn quadratic_min_radius(p0: DVec2, p1: DVec2, p2: DVec2) -> f64 {
    let second = 2.0 * (p2 - 2.0 * p1 + p0);
    (0..=32)
        .map(|k| {
            let s = k as f64 / 32.0;
            let first = 2.0 * ((1.0 - s) * (p1 - p0) + s * (p2 - p1));
            let cross = first.perp_dot(second).abs();
            if cross < 1e-300 { f64::INFINITY } else { first.length().powi(3) / cross }
        })
        .fold(f64::INFINITY, f64::min)
}

/// The signed turn at each vertex of a polyline, radians: wrapping on a
/// loop, zero at an open curve's ends.
fn turns(points: &[DVec2], closed: bool) -> Vec<f64> {
    let n = points.len();
    (0..n)
        .map(|i| {
            if !closed && (i == 0 || i + 1 == n) {
                return 0.0;
            }
            let (prev, here, next) = (points[(i + n - 1) % n], points[i], points[(i + 1) % n]);
            let (d_in, d_out) = (here - prev, next - here);
            d_in.perp_dot(d_out).atan2(d_in.dot(d_out))
        })
        .collect()
}

/// Where the line through `p` along `t` meets the line through `q` along
/// `u` (the two not parallel).
fn lines_meet(p: DVec2, t: DVec2, q: DVec2, u: DVec2) -> DVec2 {
    p + t * (q - p).perp_dot(u) / t.perp_dot(u)
}

/// An arc turning by `turn` from the point `reach` before `apex` on the
/// line along `t_in` through it, on a circle of `radius`, its points every
/// [`ARC_STEP_DEG`] or closer.
fn arc_from(apex: DVec2, t_in: DVec2, turn: f64, reach: f64, radius: f64) -> Vec<DVec2> {
    let arc_start = apex - t_in * reach;
    let centre = arc_start + t_in.perp() * radius * turn.signum();
    let steps = ((turn.abs().to_degrees() / ARC_STEP_DEG).ceil() as usize).max(2);
    (0..=steps).map(|k| centre + DVec2::from_angle(turn * k as f64 / steps as f64).rotate(arc_start - centre)).collect()
}

/// How far a straight run goes from `apex` in `direction`, walking the
/// vertices from `from` by `step` up to `limit` (inclusive) while they stay
/// on the line and move along it, and the last vertex on it: the length the
/// arc may take half of.
fn straight_run(
    at: &impl Fn(isize) -> DVec2,
    apex: DVec2,
    direction: DVec2,
    from: isize,
    step: isize,
    limit: isize,
    tolerance: f64,
) -> (f64, isize) {
    let mut length = 0.0;
    let mut last = from - step;
    let mut j = from;
    while (step > 0 && j <= limit) || (step < 0 && j >= limit) {
        let offset = at(j) - apex;
        let along = offset.dot(direction);
        if offset.perp_dot(direction).abs() > tolerance || along <= length {
            break;
        }
        length = along;
        last = j;
        j += step;
    }
    (length, last)
}
