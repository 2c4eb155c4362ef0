//! Large outlines cut into vertical slabs, so that their caps are
//! triangulated on every core: a pattern along a loop is one group of
//! overlapping rings (its holes lie inside its outline) with tens of
//! thousands of vertices, and one triangulation of it took as long as the
//! whole synthesis.

use spade::Point2;

/// Vertices per slab, at least: below this a triangulation takes a few
/// milliseconds and cutting would not pay for itself.
const SLAB_VERTICES: usize = 10_000;

/// Most slabs one group is cut into.
const MAX_SLABS: usize = 8;

/// The constraint edges (indices into `points`) of each slab of the rings
/// of `group`, or `None` where the group is too small to cut, or cannot be
/// cut cleanly (then `points` and `rings` are as they were).
///
/// Cut lines are vertical, at `f32` abscissae strictly between those of
/// the group's vertices, so no vertex lies on one and every ring crosses
/// them properly. Each crossing becomes a vertex of its ring (`rings` is
/// updated, so walls and caps share it), at the line's exact abscissa and
/// an ordinate rounded to `f32` like every other vertex. Along a line the
/// crossings alternate out, in, out, …, so the stretches between the
/// first and second, third and fourth, … are inside: each is a constraint
/// edge of the slabs on both sides, which therefore meet on the same
/// vertices and edges. The caps stay watertight, and the flood that tells
/// inside from outside (`geom::faces_inside`) sees each slab closed.
pub(super) fn slab_edges(
    points: &mut Vec<Point2<f64>>,
    rings: &mut [Vec<usize>],
    group: &[usize],
) -> Option<Vec<Vec<[usize; 2]>>> {
    let count: usize = group.iter().map(|&r| rings[r].len()).sum();
    let slabs = (count / SLAB_VERTICES).min(MAX_SLABS);
    if slabs < 2 {
        return None;
    }
    let cuts = cut_lines(group.iter().flat_map(|&r| rings[r].iter().map(|&i| points[i].x)), slabs);
    if cuts.is_empty() {
        return None;
    }
    let slab_of = |x: f64| cuts.partition_point(|&c| c < x);
    // New rings and points are kept aside until the cut is known to be clean.
    let mut added: Vec<Point2<f64>> = Vec::new();
    let mut crossings: Vec<Vec<(f64, usize)>> = vec![Vec::new(); cuts.len()];
    let mut cut_rings: Vec<Vec<usize>> = Vec::with_capacity(group.len());
    for &r in group {
        let ring = &rings[r];
        let mut out: Vec<usize> = Vec::with_capacity(ring.len());
        for k in 0..ring.len() {
            let (ia, ib) = (ring[k], ring[(k + 1) % ring.len()]);
            out.push(ia);
            let (a, b) = (points[ia], points[ib]);
            let (lo, hi) = (slab_of(a.x.min(b.x)), slab_of(a.x.max(b.x)));
            // The lines between `a` and `b`, in the order the edge meets them.
            for step in 0..hi - lo {
                let line = if a.x < b.x { lo + step } else { hi - 1 - step };
                let c = cuts[line];
                let y = f64::from((a.y + (c - a.x) / (b.x - a.x) * (b.y - a.y)) as f32);
                let id = points.len() + added.len();
                added.push(Point2::new(c, y));
                crossings[line].push((y, id));
                out.push(id);
            }
        }
        cut_rings.push(out);
    }
    let mut edges: Vec<Vec<[usize; 2]>> = vec![Vec::new(); cuts.len() + 1];
    for (line, along) in crossings.iter_mut().enumerate() {
        along.sort_unstable_by(|p, q| p.0.total_cmp(&q.0));
        // An odd count or two crossings rounded together: not clean.
        if along.len() % 2 == 1 || along.windows(2).any(|w| w[0].0 == w[1].0) {
            return None;
        }
        // Each slab gets the stretch with its own side on the left, as its
        // rings' edges have their material (`inside_faces` checks both).
        for pair in along.chunks_exact(2) {
            edges[line].push([pair[0].1, pair[1].1]);
            edges[line + 1].push([pair[1].1, pair[0].1]);
        }
    }
    points.extend(added);
    for (&r, ring) in group.iter().zip(cut_rings) {
        rings[r] = ring;
    }
    for &r in group {
        let ring = &rings[r];
        for k in 0..ring.len() {
            let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
            // Every edge now lies in one slab: its midpoint says which.
            edges[slab_of(0.5 * (points[a].x + points[b].x))].push([a, b]);
        }
    }
    Some(edges)
}

/// Up to `slabs - 1` vertical lines that cut the abscissae `xs` into
/// `slabs` groups of about equal size, each an `f32` strictly between two
/// of them; ascending.
fn cut_lines(xs: impl Iterator<Item = f64>, slabs: usize) -> Vec<f64> {
    let mut xs: Vec<f64> = xs.collect();
    xs.sort_unstable_by(f64::total_cmp);
    xs.dedup();
    let mut cuts: Vec<f64> = Vec::with_capacity(slabs - 1);
    for j in 1..slabs {
        // From the quantile on, the first gap an `f32` fits strictly inside.
        let cut = (j * xs.len() / slabs).max(1)..xs.len();
        let c = cut.into_iter().find_map(|i| {
            let c = f64::from((0.5 * (xs[i - 1] + xs[i])) as f32);
            (xs[i - 1] < c && c < xs[i]).then_some(c)
        });
        if let Some(c) = c
            && cuts.last().is_none_or(|&last| last < c)
        {
            cuts.push(c);
        }
    }
    cuts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cut_lines_fall_strictly_between_vertices() {
        let xs: Vec<f64> = (0..1000).map(|i| f64::from((i as f64 * 0.37) as f32)).collect();
        let cuts = cut_lines(xs.iter().copied(), 4);
        assert_eq!(cuts.len(), 3);
        for c in cuts {
            assert!(xs.iter().all(|&x| x != c));
            assert_eq!(c, f64::from(c as f32));
        }
    }

    #[test]
    fn neighbouring_f32_values_leave_no_room_for_a_cut() {
        let a = 1.0f32;
        let b = f32::from_bits(a.to_bits() + 1);
        assert!(cut_lines([f64::from(a), f64::from(b)].into_iter(), 2).is_empty());
    }
}
