//! How much stitching deformed the pieces: the Jacobian of the map from the
//! exemplar to band space, sampled along each piece's outline, and its worst
//! stretch and shear.
//!
//! Stretch is how much a length changes, whichever way; shear is how far two
//! directions at right angles in the exemplar are from a right angle after
//! the map. A rotation has neither, so a stitch that turns features instead
//! of shearing them shows here as less shear.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::geom::Polygon;

/// Most outline samples taken from one piece: enough to see the bends near
/// seams, few enough that measuring costs a small share of stitching.
pub const SAMPLES_PER_PIECE: usize = 128;

/// The Jacobians of a map at sample points, as `[∂u/∂x, ∂u/∂y, ∂v/∂x, ∂v/∂y]`
/// (`x`, `y` in the exemplar; `u`, `v` in band space).
///
/// ```
/// use tracery_core::vector_brush::Distortion;
///
/// // Stretched 1.2 times along the band, and sheared by 45° across it.
/// let d = Distortion::new(vec![[1.2, 0.0, 0.0, 1.0], [1.0, 0.0, 1.0, 1.0]]);
/// assert!((d.shear_max_deg() - 45.0).abs() < 1e-9);
/// assert!(d.stretch_max() >= 1.2);
/// // Pressed to half its height: lengths across halve.
/// let mut flat = Distortion::new(vec![[1.0, 0.0, 0.0, 1.0]]);
/// flat.scale_across(0.5);
/// assert!((flat.stretch_max() - 2.0).abs() < 1e-9);
/// ```
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Distortion {
    jacobians: Vec<[f64; 4]>,
}

impl Distortion {
    /// Jacobians measured elsewhere.
    pub fn new(jacobians: Vec<[f64; 4]>) -> Self {
        Distortion { jacobians }
    }

    /// Samples `map` along the outline of `polygons`, a piece spanning
    /// `x_min..x_max`: at most [`SAMPLES_PER_PIECE`] points, evenly spaced
    /// along the rings, each with forward differences of step `step`, the
    /// one along `x` taken towards the piece's middle so that it never
    /// crosses a cut. Points closer than `margin_x` to `x_min` or `x_max` are
    /// skipped: the map snaps there.
    pub(crate) fn sample(
        polygons: &[Polygon],
        (x_min, x_max): (f64, f64),
        margin_x: f64,
        step: f64,
        map: impl Fn(DVec2) -> DVec2,
    ) -> Self {
        let perimeter: f64 = polygons.iter().flat_map(|p| p.rings()).map(|r| crate::geom::ring_perimeter(r)).sum();
        if perimeter <= 0.0 || step <= 0.0 {
            return Distortion::default();
        }
        let spacing = perimeter / SAMPLES_PER_PIECE as f64;
        let middle = 0.5 * (x_min + x_max);
        let mut jacobians = Vec::with_capacity(SAMPLES_PER_PIECE + 8);
        // Arc length left before the next sample, carried across edges.
        let mut to_next = 0.5 * spacing;
        for ring in polygons.iter().flat_map(|p| p.rings()) {
            for (k, &a) in ring.iter().enumerate() {
                let b = ring[(k + 1) % ring.len()];
                let length = a.distance(b);
                let mut along = to_next;
                while along < length {
                    let p = a.lerp(b, along / length);
                    along += spacing;
                    if p.x - x_min < margin_x || x_max - p.x < margin_x {
                        continue;
                    }
                    let hx = if p.x < middle { step } else { -step };
                    let at = map(p);
                    let du = (map(p + DVec2::new(hx, 0.0)) - at) / hx;
                    let dv = (map(p + DVec2::new(0.0, step)) - at) / step;
                    jacobians.push([du.x, dv.x, du.y, dv.y]);
                }
                to_next = along - length;
            }
        }
        Distortion { jacobians }
    }

    /// The samples of several pieces together.
    pub fn join(parts: impl IntoIterator<Item = Distortion>) -> Self {
        Distortion { jacobians: parts.into_iter().flat_map(|d| d.jacobians).collect() }
    }

    /// How many points were sampled.
    pub fn sample_count(&self) -> usize {
        self.jacobians.len()
    }

    /// Scales `v` by `factor`, as [`super::BandPattern::fit_within`] does to the pattern.
    pub fn scale_across(&mut self, factor: f64) {
        for j in &mut self.jacobians {
            j[2] *= factor;
            j[3] *= factor;
        }
    }

    /// The largest factor by which a length grows or shrinks at a sample,
    /// `max(σ₁, 1/σ₂)` over the singular values `σ₁ ≥ σ₂` (1 for no
    /// change; 1 when nothing was sampled).
    pub fn stretch_max(&self) -> f64 {
        self.jacobians
            .iter()
            .map(|&j| {
                let (large, small) = singular_values(j);
                large.max(1.0 / small.max(1e-12))
            })
            .fold(1.0, f64::max)
    }

    /// The largest shear at a sample, in degrees: how far the images of the
    /// exemplar's `x` and `y` directions are from a right angle.
    pub fn shear_max_deg(&self) -> f64 {
        self.jacobians.iter().map(|&j| shear_deg(j)).fold(0.0, f64::max)
    }
}

/// `σ₁ ≥ σ₂` of the 2×2 matrix `[a, b; c, d]`.
fn singular_values([a, b, c, d]: [f64; 4]) -> (f64, f64) {
    let sum = a * a + b * b + c * c + d * d;
    let det = a * d - b * c;
    let root = (sum * sum - 4.0 * det * det).max(0.0).sqrt();
    (((sum + root) / 2.0).sqrt(), ((sum - root) / 2.0).max(0.0).sqrt())
}

fn shear_deg([a, b, c, d]: [f64; 4]) -> f64 {
    let (x, y) = (DVec2::new(a, c), DVec2::new(b, d));
    if x.length_squared() == 0.0 || y.length_squared() == 0.0 {
        return 90.0;
    }
    (90.0 - x.angle_to(y).abs().to_degrees()).abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_neither_stretch_nor_shear() {
        let (s, c) = 0.7f64.sin_cos();
        let d = Distortion::new(vec![[c, -s, s, c]]);
        assert!((d.stretch_max() - 1.0).abs() < 1e-12);
        assert!(d.shear_max_deg() < 1e-9);
    }

    #[test]
    fn a_shear_along_the_band_is_its_angle() {
        // v += 0.5 u: the image of x leans by atan(0.5).
        let d = Distortion::new(vec![[1.0, 0.0, 0.5, 1.0]]);
        assert!((d.shear_max_deg() - 0.5f64.atan().to_degrees()).abs() < 1e-9);
        // Area is kept, so one singular value is above 1 and the other below.
        let (large, small) = singular_values([1.0, 0.0, 0.5, 1.0]);
        assert!((large * small - 1.0).abs() < 1e-12 && large > 1.2);
    }

    #[test]
    fn samples_follow_the_outline_and_skip_the_cuts() {
        let square = Polygon {
            outer: vec![DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)],
            holes: Vec::new(),
        };
        let d = Distortion::sample(std::slice::from_ref(&square), (0.0, 4.0), 0.1, 1e-6, |p| {
            DVec2::new(1.5 * p.x, p.y + 0.25 * p.x)
        });
        // About half the outline lies on the two cuts, which are skipped.
        assert!((SAMPLES_PER_PIECE / 2 - 4..=SAMPLES_PER_PIECE / 2 + 4).contains(&d.sample_count()));
        assert!((d.stretch_max() - singular_values([1.5, 0.0, 0.25, 1.0]).0).abs() < 1e-6);
        assert!((d.shear_max_deg() - (0.25f64 / 1.5).atan().to_degrees()).abs() < 1e-6);
    }
}
