//! Smooth frames along a curve on a surface, for laying a band: the
//! surface normal traced along the curve (a path on the unit sphere) is
//! smoothed by a Gaussian over arc length, the smoothing counterpart of
//! fitting a spline to it, then projected onto the curve's normal plane.
//! The raw normal of a faceted mesh jumps at every edge; the smoothed one
//! turns gradually, so the band does not kink where the mesh does.

use glam::DVec3;

use super::SurfaceCurve;

/// A frame at each point of a curve: tangent, the band's across direction
/// (`binormal`, to the left of the tangent seen from outside) and the normal.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Frames {
    /// Arc length at each point, mm.
    pub arc_mm: Vec<f64>,
    /// Unit tangents.
    pub tangents: Vec<DVec3>,
    /// Unit across directions: the band's `v`.
    pub binormals: Vec<DVec3>,
    /// Unit normals: the thickness direction.
    pub normals: Vec<DVec3>,
    /// Total length, mm (the closing segment included on a closed curve).
    pub length_mm: f64,
    /// Whether the curve closes.
    pub closed: bool,
}

impl Frames {
    /// Frames along `curve`, its normals smoothed over `smoothing_mm` (the
    /// Gaussian's standard deviation), turned by `twist_deg` about the tangent.
    pub fn along(curve: &SurfaceCurve, smoothing_mm: f64, twist_deg: f64) -> Frames {
        let points = &curve.points_mm;
        let n = points.len();
        let closed = curve.closed;
        let mut arc_mm = Vec::with_capacity(n);
        let mut walked = 0.0;
        for k in 0..n {
            if k > 0 {
                walked += points[k].distance(points[k - 1]);
            }
            arc_mm.push(walked);
        }
        let length_mm = if closed && n > 1 { walked + points[n - 1].distance(points[0]) } else { walked };
        let neighbour = |k: usize, step: isize| -> Option<usize> {
            let j = k as isize + step;
            if closed {
                Some(j.rem_euclid(n as isize) as usize)
            } else {
                (0..n as isize).contains(&j).then_some(j as usize)
            }
        };
        // Distance along the curve from k to j, the short way round when closed.
        let apart = |k: usize, j: usize| {
            let d = (arc_mm[j] - arc_mm[k]).abs();
            if closed { d.min(length_mm - d) } else { d }
        };
        // Chords to the neighbours, smoothed like the normals: a step of a
        // micrometre where the curve crosses an edge next to a sample says
        // nothing about where it heads.
        let chords: Vec<DVec3> = (0..n)
            .map(|k| {
                let ahead = neighbour(k, 1).map_or(points[k], |j| points[j]);
                let behind = neighbour(k, -1).map_or(points[k], |j| points[j]);
                ahead - behind
            })
            .collect();
        let sigma = smoothing_mm.max(1e-9);
        let tangents = smooth_along(&chords, &neighbour, &apart, TANGENT_SMOOTHING_MM.min(sigma));
        let smoothed = smooth_along(&curve.normals, &neighbour, &apart, sigma);
        let (sin, cos) = twist_deg.to_radians().sin_cos();
        let mut binormals = Vec::with_capacity(n);
        let mut normals = Vec::with_capacity(n);
        for k in 0..n {
            let t = tangents[k];
            let normal = (smoothed[k] - t * smoothed[k].dot(t)).try_normalize().unwrap_or(curve.normals[k]);
            let binormal = normal.cross(t).normalize_or_zero();
            binormals.push(binormal * cos + normal * sin);
            normals.push(normal * cos - binormal * sin);
        }
        Frames { arc_mm, tangents, binormals, normals, length_mm, closed }
    }

    /// Position, across direction and normal at arc length `u_mm`, linearly
    /// between points; on an open curve beyond its ends the line goes on
    /// straight, on a closed one `u_mm` wraps.
    pub fn at(&self, curve: &SurfaceCurve, u_mm: f64) -> (DVec3, DVec3, DVec3) {
        let n = self.arc_mm.len();
        let points = &curve.points_mm;
        let u = if self.closed { u_mm.rem_euclid(self.length_mm) } else { u_mm };
        if !self.closed && u <= 0.0 {
            return (points[0] + self.tangents[0] * u, self.binormals[0], self.normals[0]);
        }
        if !self.closed && u >= self.arc_mm[n - 1] {
            let extra = u - self.arc_mm[n - 1];
            return (points[n - 1] + self.tangents[n - 1] * extra, self.binormals[n - 1], self.normals[n - 1]);
        }
        let k = self.arc_mm.partition_point(|&a| a <= u).saturating_sub(1);
        let j = (k + 1) % n;
        let span = if j == 0 { self.length_mm - self.arc_mm[k] } else { self.arc_mm[j] - self.arc_mm[k] };
        let s = if span > 0.0 { ((u - self.arc_mm[k]) / span).clamp(0.0, 1.0) } else { 0.0 };
        let blend = |a: DVec3, b: DVec3| a * (1.0 - s) + b * s;
        let normal = blend(self.normals[k], self.normals[j]).normalize_or_zero();
        // Blended separately, the two would lean together between points.
        let across = blend(self.binormals[k], self.binormals[j]);
        let across = (across - normal * across.dot(normal)).normalize_or_zero();
        (points[k].lerp(points[j], s), across, normal)
    }

    /// The largest turn of the across direction per millimetre along the
    /// curve, degrees: how continuous the frames are.
    pub fn max_turn_deg_per_mm(&self) -> f64 {
        let n = self.arc_mm.len();
        let pairs = if self.closed { n } else { n.saturating_sub(1) };
        (0..pairs)
            .filter_map(|k| {
                let j = (k + 1) % n;
                let d = if j == 0 { self.length_mm - self.arc_mm[k] } else { self.arc_mm[j] - self.arc_mm[k] };
                // Steps shorter than a micrometre (an edge crossing next to a
                // sample) say nothing about a rate.
                (d > 1e-3).then(|| self.binormals[k].angle_between(self.binormals[j]).to_degrees() / d)
            })
            .fold(0.0, f64::max)
    }

    /// The largest geodesic curvature along the curve, 1/mm: how sharply it
    /// turns within the surface, measured over `window_mm` so that the
    /// mesh's facets do not count. A band wider than twice its inverse folds.
    pub fn max_turning_per_mm(&self, window_mm: f64) -> f64 {
        let n = self.arc_mm.len();
        let mut most: f64 = 0.0;
        for k in 0..n {
            let u = self.arc_mm[k];
            let ahead = self.tangent_at(u + 0.5 * window_mm);
            let behind = self.tangent_at(u - 0.5 * window_mm);
            if !self.closed && (u - 0.5 * window_mm < 0.0 || u + 0.5 * window_mm > self.arc_mm[n - 1]) {
                continue;
            }
            most = most.max((ahead - behind).dot(self.binormals[k]).abs() / window_mm);
        }
        most
    }

    fn tangent_at(&self, u_mm: f64) -> DVec3 {
        let n = self.arc_mm.len();
        let u = if self.closed { u_mm.rem_euclid(self.length_mm) } else { u_mm.clamp(0.0, self.arc_mm[n - 1]) };
        let k = self.arc_mm.partition_point(|&a| a <= u).saturating_sub(1);
        self.tangents[k]
    }
}

/// Tangents are smoothed over at most this, mm: enough to wash out the
/// steps at edge crossings, short enough to keep the curve's own turns.
const TANGENT_SMOOTHING_MM: f64 = 0.5;

/// `values` at each point smoothed by a Gaussian of `sigma` over arc length
/// (out to three of them), normalized.
fn smooth_along(
    values: &[DVec3],
    neighbour: &dyn Fn(usize, isize) -> Option<usize>,
    apart: &dyn Fn(usize, usize) -> f64,
    sigma: f64,
) -> Vec<DVec3> {
    let n = values.len();
    (0..n)
        .map(|k| {
            let mut sum = values[k];
            for step in [1isize, -1] {
                let mut j = k;
                for _ in 0..n {
                    let Some(next) = neighbour(j, step) else { break };
                    if next == k {
                        break;
                    }
                    j = next;
                    let d = apart(k, j);
                    if d > 3.0 * sigma {
                        break;
                    }
                    sum += values[j] * (-0.5 * (d / sigma).powi(2)).exp();
                }
            }
            sum.normalize_or_zero()
        })
        .collect()
}
