//! Polyline resampling.

use glam::DVec2;

/// Splits the edges of a ring so that none is longer than `step`, except
/// edges across the band (constant `u`): every mapping along a curve keeps
/// those straight, and leaving them whole lets seams weld exactly.
pub fn resample(ring: &[DVec2], step: f64) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(ring.len());
    for i in 0..ring.len() {
        let a = ring[i];
        let b = ring[(i + 1) % ring.len()];
        let pieces = if a.x == b.x { 1 } else { ((a.distance(b) / step).ceil() as usize).clamp(1, 10_000) };
        for k in 0..pieces {
            out.push(a.lerp(b, k as f64 / pieces as f64));
        }
    }
    out
}
