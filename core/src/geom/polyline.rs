//! Polyline refinement under a mapping.

use glam::DVec2;

/// Maps a ring through `map`, adding points wherever the mapped edge would
/// stray from its chord: every edge is first split into pieces no longer
/// than `max_step`, then halved until the mapped midpoint lies within
/// `tolerance` of the mapped chord (at most 8 halvings). Edges across the band
/// (constant `u`) stay whole: every mapping along a curve keeps those
/// straight, and leaving them whole lets seams weld exactly.
///
/// A straight edge that `map` moves rigidly gets no new point, so the
/// output has as many vertices as the deformation needs, not as a fixed step
/// would give.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::refine_mapped;
/// let square = [DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0), DVec2::new(1.0, 1.0), DVec2::new(0.0, 1.0)];
/// // A shift needs no new point; a bend does.
/// assert_eq!(refine_mapped(&square, |p| p + DVec2::X, 10.0, 1e-3).len(), 4);
/// let bent = refine_mapped(&square, |p| DVec2::new(p.x, p.y + p.x * p.x), 10.0, 1e-3);
/// assert!(bent.len() > 8);
/// ```
pub fn refine_mapped(ring: &[DVec2], map: impl Fn(DVec2) -> DVec2, max_step: f64, tolerance: f64) -> Vec<DVec2> {
    fn halve(
        out: &mut Vec<DVec2>,
        map: &impl Fn(DVec2) -> DVec2,
        (a, b): (DVec2, DVec2),
        (ma, mb): (DVec2, DVec2),
        tolerance: f64,
        depth: u32,
    ) {
        if depth == 0 {
            return;
        }
        let m = 0.5 * (a + b);
        let mm = map(m);
        if mm.distance(0.5 * (ma + mb)) <= tolerance {
            return;
        }
        halve(out, map, (a, m), (ma, mm), tolerance, depth - 1);
        out.push(mm);
        halve(out, map, (m, b), (mm, mb), tolerance, depth - 1);
    }
    let mut out = Vec::with_capacity(ring.len() * 2);
    let n = ring.len();
    let mapped: Vec<DVec2> = ring.iter().map(|&p| map(p)).collect();
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        out.push(mapped[i]);
        if a.x == b.x {
            continue;
        }
        let pieces = ((a.distance(b) / max_step.max(1e-12)).ceil() as usize).clamp(1, 10_000);
        let mut previous = (a, mapped[i]);
        for k in 1..=pieces {
            let next = if k == pieces {
                (b, mapped[(i + 1) % n])
            } else {
                let p = a.lerp(b, k as f64 / pieces as f64);
                (p, map(p))
            };
            halve(&mut out, &map, (previous.0, next.0), (previous.1, next.1), tolerance, 8);
            if k < pieces {
                out.push(next.1);
            }
            previous = next;
        }
    }
    out
}
