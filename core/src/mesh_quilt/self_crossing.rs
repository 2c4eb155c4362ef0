//! Whether an element's surface passes through itself: two of its
//! triangles that share no corner yet meet. A stitch whose strip twists,
//! or a piece bent through itself where it was joined, makes such an
//! element; it is closed edge by edge, yet it prints wrong and the booleans
//! refuse it.

use rustc_hash::FxHashMap;

use glam::DVec3;

use super::Element;

/// Grid cells are this many mean edge lengths wide: a triangle spans a few.
const CELL_EDGES: f64 = 2.0;

/// Most cells one triangle is filed in; a larger one is tested against
/// every triangle instead.
const MAX_CELLS_PER_TRIANGLE: i64 = 64;

/// Whether two triangles of `element` that share no vertex cross: an edge
/// of one through the inside of the other. Touching does not count: where
/// a stitch joins two pieces, their facing loops lie together, and the
/// faces beside them touch without crossing. Pairs are found on a grid of
/// boxes.
///
/// ```
/// use glam::DVec3;
/// use tracery_core::mesh_quilt::{Element, crosses_itself};
/// let tetra = Element {
///     vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
/// };
/// assert!(!crosses_itself(&tetra));
/// // The same tetrahedron again, shifted into the first: the surface crosses.
/// let mut two = tetra.clone();
/// two.append(&tetra.translated(DVec3::splat(0.2)));
/// assert!(crosses_itself(&two));
/// ```
pub fn crosses_itself(element: &Element) -> bool {
    !crossing_pairs(element, 1).is_empty()
}

/// Up to `most` pairs of triangles of `element` that cross, as
/// [`crosses_itself`] finds them, each pair once with the lower index
/// first.
pub fn crossing_pairs(element: &Element, most: usize) -> Vec<(u32, u32)> {
    let n = element.triangles.len();
    let mut found = Vec::new();
    if n < 2 || most == 0 {
        return found;
    }
    let corners = |t: usize| element.triangles[t].map(|v| element.vertices[v as usize]);
    let edges: f64 = (0..n).map(corners).map(|[a, b, c]| a.distance(b) + b.distance(c) + c.distance(a)).sum();
    let cell = (CELL_EDGES * edges / (3 * n) as f64).max(1e-9);
    let key = |p: DVec3| (p / cell).floor().as_i64vec3();
    let boxes: Vec<(DVec3, DVec3)> = (0..n)
        .map(|t| {
            let [a, b, c] = corners(t);
            (a.min(b).min(c), a.max(b).max(c))
        })
        .collect();
    let mut grid: FxHashMap<(i64, i64, i64), Vec<u32>> = FxHashMap::default();
    let mut large: Vec<usize> = Vec::new();
    for (t, &(lo, hi)) in boxes.iter().enumerate() {
        let (a, b) = (key(lo), key(hi));
        if (b - a + 1).element_product() > MAX_CELLS_PER_TRIANGLE {
            large.push(t);
            continue;
        }
        for x in a.x..=b.x {
            for y in a.y..=b.y {
                for z in a.z..=b.z {
                    grid.entry((x, y, z)).or_default().push(t as u32);
                }
            }
        }
    }
    let meet = |s: usize, t: usize| {
        let (bs, bt) = (boxes[s], boxes[t]);
        let apart = bs.1.cmplt(bt.0).any() || bt.1.cmplt(bs.0).any();
        let shared = element.triangles[s].iter().any(|v| element.triangles[t].contains(v));
        !apart && !shared && (edge_through(corners(s), corners(t)) || edge_through(corners(t), corners(s)))
    };
    let from_large = large.iter().flat_map(|&s| (0..n).filter(move |&t| t != s).map(move |t| (s, t)));
    let from_grid = grid.values().flat_map(|members| {
        members
            .iter()
            .enumerate()
            .flat_map(move |(k, &s)| members[k + 1..].iter().map(move |&t| (s as usize, t as usize)))
    });
    // A pair filed together in several cells comes up once per cell; only
    // the few that cross are worth remembering to report once.
    let mut crossing = from_large
        .chain(from_grid)
        .map(|(s, t)| (s.min(t) as u32, s.max(t) as u32))
        .filter(|&(s, t)| meet(s as usize, t as usize));
    while found.len() < most {
        match crossing.next() {
            Some(pair) if !found.contains(&pair) => found.push(pair),
            Some(_) => {}
            None => break,
        }
    }
    found
}

/// Share of a triangle's or an edge's extent within which a meeting is
/// taken as touching rather than crossing: far below any feature, above
/// rounding.
const TOUCH_SHARE: f64 = 1e-7;

/// Whether an edge of triangle `a` passes through the inside of triangle
/// `b`, away from `b`'s edges and from the edge's own ends.
fn edge_through(a: [DVec3; 3], b: [DVec3; 3]) -> bool {
    let (e1, e2) = (b[1] - b[0], b[2] - b[0]);
    let normal = e1.cross(e2);
    // A triangle with no area has no inside to pass through.
    if normal.length_squared() <= f64::EPSILON * e1.length_squared() * e2.length_squared() {
        return false;
    }
    (0..3).any(|k| {
        let (p, q) = (a[k], a[(k + 1) % 3]);
        let d = q - p;
        let h = d.cross(e2);
        let det = e1.dot(h);
        // Parallel to the plane: touching at most.
        if det.abs() <= TOUCH_SHARE * d.length() * normal.length() {
            return false;
        }
        let s = p - b[0];
        let u = s.dot(h) / det;
        let qv = s.cross(e1);
        let v = d.dot(qv) / det;
        let along = e2.dot(qv) / det;
        let inside = TOUCH_SHARE..=1.0 - TOUCH_SHARE;
        u > TOUCH_SHARE && v > TOUCH_SHARE && u + v < 1.0 - TOUCH_SHARE && inside.contains(&along)
    })
}
