//! Needles: spikes of an outline thinner than `f32` can tell apart.
//!
//! An outline can run out to a tip and back along nearly the same line, a
//! spike a ten-millionth of a millimetre wide (stitching and mapping leave
//! them where a cut grazes a stroke's end; drawings have them where strokes
//! were joined). Rounded to `f32`, the way back touches or crosses the way
//! out, and the mesher cuts the tip off as a body of its own. A spike that
//! thin has no material: it is dropped.

use glam::DVec2;

use super::closest_on_segment;

/// Whether `p → v → q` runs out to `v` and back: the two edges point in
/// opposite directions and one end lies within `width` of the other edge.
fn is_needle(p: DVec2, v: DVec2, q: DVec2, width: f64) -> bool {
    let along = |x: DVec2, a: DVec2, b: DVec2| closest_on_segment(x, a, b).1.distance(x);
    (v - p).dot(q - v) < 0.0 && (along(p, v, q) <= width || along(q, p, v) <= width)
}

/// `ring` (closed) without the tips of spikes narrower than `width` at
/// their base, however many vertices they have.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::without_needles;
/// // A square with a spike out of its right side, 1e-7 wide.
/// let mut ring = vec![
///     DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0), DVec2::new(1.0, 0.5),
///     DVec2::new(2.0, 0.5 + 1e-7), DVec2::new(1.0, 0.5 + 2e-7), DVec2::new(1.0, 1.0), DVec2::new(0.0, 1.0),
/// ];
/// without_needles(&mut ring, 1e-5);
/// assert!(ring.iter().all(|p| p.x <= 1.0));
/// ```
pub fn without_needles(ring: &mut Vec<DVec2>, width: f64) {
    let mut out: Vec<DVec2> = Vec::with_capacity(ring.len());
    for &p in ring.iter() {
        out.push(p);
        while out.len() >= 3 && is_needle(out[out.len() - 3], out[out.len() - 2], out[out.len() - 1], width) {
            out.remove(out.len() - 2);
        }
    }
    // The ring closes: tips at its start and end.
    while out.len() >= 3 {
        let n = out.len();
        if is_needle(out[n - 2], out[n - 1], out[0], width) {
            out.pop();
        } else if is_needle(out[n - 1], out[0], out[1], width) {
            out.remove(0);
        } else {
            break;
        }
    }
    *ring = out;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sharp_but_real_corner_stays() {
        // A thin wedge, 0.01 wide at its base: narrow, but material.
        let wedge = vec![DVec2::new(0.0, 0.0), DVec2::new(5.0, 0.005), DVec2::new(0.0, 0.01)];
        let mut ring = wedge.clone();
        without_needles(&mut ring, 1e-5);
        assert_eq!(ring, wedge);
    }

    #[test]
    fn a_needle_over_the_rings_start_goes_too() {
        let mut ring = vec![
            DVec2::new(2.0, 0.5),
            DVec2::new(1.0, 0.5 + 2e-7),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 0.5),
        ];
        without_needles(&mut ring, 1e-5);
        assert_eq!(ring.len(), 6);
        assert!(ring.iter().all(|p| p.x <= 1.0));
    }
}
