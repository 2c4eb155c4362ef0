//! Bridges that join the parts of a region into one: the shortest set of
//! straight links between parts (a minimum spanning tree of the parts over
//! the Delaunay triangulation of their outline points, which holds every
//! Euclidean nearest link), each drawn with a round pen.

use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation};

use super::{Region, brush_stroke, union};
use crate::DVec2;
use crate::disjoint_sets::DisjointSets;

/// An outline point and the part it belongs to.
struct Labelled {
    at: Point2<f64>,
    part: usize,
}

impl HasPosition for Labelled {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.at
    }
}

/// `region` with its parts joined by bridges `width_mm` wide, and the
/// bridges' centre lines (as few and as short as joins every part, over
/// outline points). A region of one part comes back as it is.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region, join_parts};
/// let square = |x: f64| Polygon {
///     outer: vec![DVec2::new(x, 0.0), DVec2::new(x + 2.0, 0.0), DVec2::new(x + 2.0, 2.0), DVec2::new(x, 2.0)],
///     holes: vec![],
/// };
/// let (joined, bridges) = join_parts(&Region::new(vec![square(0.0), square(5.0), square(10.0)]), 0.8);
/// assert_eq!(joined.component_count(), 1);
/// assert_eq!(bridges.len(), 2);
/// assert!(bridges.iter().all(|[a, b]| (a.distance(*b) - 3.0).abs() < 1e-9));
/// ```
pub fn join_parts(region: &Region, width_mm: f64) -> (Region, Vec<[DVec2; 2]>) {
    if region.polygons.len() < 2 {
        return (region.clone(), Vec::new());
    }
    let mut triangulation: DelaunayTriangulation<Labelled> = DelaunayTriangulation::new();
    for (part, polygon) in region.polygons.iter().enumerate() {
        for p in polygon.rings().flatten() {
            // A point the triangulation cannot hold (not finite) is only left out.
            let _ = triangulation.insert(Labelled { at: Point2::new(p.x, p.y), part });
        }
    }
    let mut links: Vec<(f64, usize, usize, [DVec2; 2])> = triangulation
        .undirected_edges()
        .filter_map(|edge| {
            let [a, b] = edge.vertices();
            let (a, b) = (a.data(), b.data());
            (a.part != b.part).then(|| {
                let (pa, pb) = (DVec2::new(a.at.x, a.at.y), DVec2::new(b.at.x, b.at.y));
                (pa.distance(pb), a.part, b.part, [pa, pb])
            })
        })
        .collect();
    links.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut parts = DisjointSets::new(region.polygons.len());
    let bridges: Vec<[DVec2; 2]> =
        links.into_iter().filter(|(_, a, b, _)| parts.join(*a, *b)).map(|(_, _, _, line)| line).collect();
    let strokes: Vec<Region> = bridges.iter().map(|line| brush_stroke(line, width_mm, false)).collect();
    let mut all: Vec<&Region> = vec![region];
    all.extend(strokes.iter());
    (union(&all), bridges)
}
