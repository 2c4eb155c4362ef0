//! Where the spline through picked points is drawn: on the chart's disk
//! itself, or, for a ring around a hole of the chart (a band round a vase,
//! whose far side was closed by a fan), in log-polar coordinates about
//! that hole.
//!
//! The chart's map is close to conformal, and a conformal map of an
//! annulus onto a disk sends the rings of a cylinder to circles about the
//! hole: `(angle, ln radius)` about the hole is then the cylinder unrolled.
//! A spline there through four points at one height on a cylinder is that
//! height's circle; the same spline on the disk is a rounded square, which
//! dips between the points once mapped back.

use std::f64::consts::{PI, TAU};

use glam::DVec2;

use super::Chart;

/// The plane the spline is drawn in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SplineDomain {
    /// The chart's disk.
    Disk,
    /// `(angle, ln radius)` about `centre` on the disk, which the closed
    /// curve goes round once (`turns` is +1 or -1, by its direction).
    AroundHole {
        /// The hole's centre on the disk.
        centre: DVec2,
        /// Times the curve goes round it, counter-clockwise positive.
        turns: f64,
    },
}

impl SplineDomain {
    /// The domain for a curve through `disk` (its points on the chart's
    /// disk): about the first filled hole a closed curve goes round once,
    /// else the disk.
    pub fn for_curve(chart: &Chart, disk: &[DVec2], closed: bool) -> SplineDomain {
        if !closed || disk.len() < 3 {
            return SplineDomain::Disk;
        }
        chart
            .hole_centres()
            .into_iter()
            .find_map(|centre| {
                let turns = winding(disk, centre);
                (turns.abs() == 1.0).then_some(SplineDomain::AroundHole { centre, turns })
            })
            .unwrap_or(SplineDomain::Disk)
    }

    /// The picked points in this domain, each angle unwrapped from the one
    /// before it, so that a spline through them turns the short way.
    pub fn controls(&self, disk: &[DVec2]) -> Vec<DVec2> {
        match *self {
            SplineDomain::Disk => disk.to_vec(),
            SplineDomain::AroundHole { centre, .. } => {
                let mut out: Vec<DVec2> = Vec::with_capacity(disk.len());
                for &p in disk {
                    let d = p - centre;
                    let angle = d.y.atan2(d.x);
                    let angle = match out.last() {
                        Some(last) => last.x + wrapped(angle - last.x),
                        None => angle,
                    };
                    out.push(DVec2::new(angle, d.length().max(f64::MIN_POSITIVE).ln()));
                }
                out
            }
        }
    }

    /// What a closed curve's controls gain per time round: the `k`-th
    /// control past the last is the `k`-th plus this.
    pub fn period(&self) -> DVec2 {
        match *self {
            SplineDomain::Disk => DVec2::ZERO,
            SplineDomain::AroundHole { turns, .. } => DVec2::new(TAU * turns, 0.0),
        }
    }

    /// A point of the domain back on the disk.
    pub fn to_disk(&self, q: DVec2) -> DVec2 {
        match *self {
            SplineDomain::Disk => q,
            SplineDomain::AroundHole { centre, .. } => centre + DVec2::from_angle(q.x) * q.y.exp(),
        }
    }
}

/// `angle` brought into (-π, π].
fn wrapped(angle: f64) -> f64 {
    let a = angle.rem_euclid(TAU);
    if a > PI { a - TAU } else { a }
}

/// How many times the closed polygon `points` goes round `centre`,
/// counter-clockwise positive (rounded; 0 when it passes through it).
fn winding(points: &[DVec2], centre: DVec2) -> f64 {
    let n = points.len();
    let mut total = 0.0;
    for k in 0..n {
        let (a, b) = (points[k] - centre, points[(k + 1) % n] - centre);
        if a.length_squared() == 0.0 || b.length_squared() == 0.0 {
            return 0.0;
        }
        total += wrapped(b.y.atan2(b.x) - a.y.atan2(a.x));
    }
    (total / TAU).round()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn winding_counts_turns_round_a_centre() {
        let square = [DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0), DVec2::new(-1.0, 0.0), DVec2::new(0.0, -1.0)];
        assert_eq!(winding(&square, DVec2::ZERO), 1.0);
        let reversed: Vec<DVec2> = square.iter().rev().copied().collect();
        assert_eq!(winding(&reversed, DVec2::ZERO), -1.0);
        assert_eq!(winding(&square, DVec2::new(3.0, 0.0)), 0.0);
    }

    #[test]
    fn controls_come_back_to_the_disk_and_unwrap_their_angles() {
        let domain = SplineDomain::AroundHole { centre: DVec2::new(0.1, -0.2), turns: 1.0 };
        let disk = [DVec2::new(0.5, 0.0), DVec2::new(0.0, 0.4), DVec2::new(-0.5, 0.0), DVec2::new(0.1, -0.6)];
        let controls = domain.controls(&disk);
        for (q, p) in controls.iter().zip(&disk) {
            assert!(domain.to_disk(*q).distance(*p) < 1e-12);
        }
        assert!(controls.windows(2).all(|w| w[1].x > w[0].x), "{controls:?}");
    }
}
