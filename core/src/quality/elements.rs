//! Measures of the discrete elements of a pattern (dots, leaves: filled
//! shapes), read from the shapes and the paths alone: how densely they
//! lie, whether any overlap, and how many touch a path.

use glam::DVec2;

use crate::geom::{Polygon, Rect, polyline_distance};

/// An element is taken to touch a path when its outline comes this close
/// to the path's middle line, mm: within the half width of a thin pen.
pub const TOUCH_MM: f64 = 0.3;

/// What the elements of a pattern look like, counted within a window.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ElementStatistics {
    /// Elements whose centre lies in the window.
    pub count: usize,
    /// Elements per 100 mm² of the window.
    pub per_100mm2: f64,
    /// Pairs of elements (any centre in the window) that overlap.
    pub overlapping_pairs: usize,
    /// The share of the counted elements whose outline comes within
    /// [`TOUCH_MM`] of a path, or that a path enters.
    pub touching_share: f64,
}

/// [`ElementStatistics`] of `elements` beside `paths` (points, closed),
/// counting elements whose centre (the mean of its outer points) lies in
/// `bounds` shrunk by `margin_mm`, away from the edge where a fill cuts off.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Rect, disc};
/// use tracery_core::quality::element_statistics;
/// let dots = [disc(DVec2::new(5.0, 5.0), 1.0, 16), disc(DVec2::new(6.0, 5.0), 1.0, 16), disc(DVec2::new(5.0, 9.0), 1.0, 16)];
/// let stem = (vec![DVec2::new(0.0, 10.0), DVec2::new(10.0, 10.0)], false);
/// let s = element_statistics(&dots, &[stem], &Rect::new(DVec2::ZERO, DVec2::splat(10.0)), 0.0);
/// assert_eq!((s.count, s.overlapping_pairs), (3, 1));
/// assert!((s.per_100mm2 - 3.0).abs() < 1e-9);
/// assert!((s.touching_share - 1.0 / 3.0).abs() < 1e-9, "the dot at y = 9 touches the stem");
/// ```
pub fn element_statistics(
    elements: &[Polygon],
    paths: &[(Vec<DVec2>, bool)],
    bounds: &Rect,
    margin_mm: f64,
) -> ElementStatistics {
    let window = bounds.inflate(-margin_mm);
    let centre = |p: &Polygon| p.outer.iter().copied().sum::<DVec2>() / p.outer.len().max(1) as f64;
    let boxes: Vec<Option<Rect>> = elements.iter().map(|e| Rect::from_points(e.outer.iter().copied())).collect();
    let in_window: Vec<bool> = elements.iter().map(|e| window.contains(centre(e))).collect();
    let counted: Vec<usize> = (0..elements.len()).filter(|&k| in_window[k]).collect();
    let mut overlapping_pairs = 0;
    for a in 0..elements.len() {
        for b in a + 1..elements.len() {
            let (Some(ba), Some(bb)) = (boxes[a], boxes[b]) else { continue };
            let counts = in_window[a] || in_window[b];
            if ba.overlaps(&bb) && counts && overlap(&elements[a], &elements[b]) {
                overlapping_pairs += 1;
            }
        }
    }
    let touching = counted.iter().filter(|&&k| touches(&elements[k], paths)).count();
    let area = (window.width() * window.height()).max(1e-9);
    ElementStatistics {
        count: counted.len(),
        per_100mm2: 100.0 * counted.len() as f64 / area,
        overlapping_pairs,
        touching_share: if counted.is_empty() { 0.0 } else { touching as f64 / counted.len() as f64 },
    }
}

/// Whether two shapes share area: a point of one inside the other, or
/// their outlines crossing.
fn overlap(a: &Polygon, b: &Polygon) -> bool {
    if a.outer.iter().any(|&p| b.contains(p)) || b.outer.iter().any(|&p| a.contains(p)) {
        return true;
    }
    let edges = |p: &Polygon| {
        let n = p.outer.len();
        (0..n).map(move |i| (p.outer[i], p.outer[(i + 1) % n])).collect::<Vec<_>>()
    };
    let (ea, eb) = (edges(a), edges(b));
    ea.iter().any(|&(p, q)| eb.iter().any(|&(r, s)| segments_cross(p, q, r, s)))
}

/// Whether segments `pq` and `rs` cross at a point inside both.
fn segments_cross(p: DVec2, q: DVec2, r: DVec2, s: DVec2) -> bool {
    let side = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    let (d1, d2) = (side(r, s, p), side(r, s, q));
    let (d3, d4) = (side(p, q, r), side(p, q, s));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

/// Whether a path comes within [`TOUCH_MM`] of `element`'s outline or
/// enters it.
fn touches(element: &Polygon, paths: &[(Vec<DVec2>, bool)]) -> bool {
    paths.iter().any(|(points, closed)| {
        points.iter().any(|&p| element.contains(p))
            || element.outer.iter().any(|&p| polyline_distance(points, *closed, p) <= TOUCH_MM)
    })
}
