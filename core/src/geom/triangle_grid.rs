//! [`TriangleGrid`]: triangles of a flat layout (a chart, a patch laid
//! flat) bucketed on a square grid, for finding the triangle under a point.

use glam::DVec2;

/// How far outside a triangle, in barycentric terms, a point may lie and
/// still be found in it: points on a shared edge land in one of the two.
pub const LOCATE_SLACK: f64 = 1e-9;

/// Buckets of triangles on a square grid over a box.
///
/// ```
/// use tracery_core::geom::TriangleGrid;
/// use glam::DVec2;
/// let uv = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE];
/// let triangles = [[0, 1, 2], [1, 3, 2]];
/// let grid = TriangleGrid::new(&uv, &triangles, DVec2::ZERO, DVec2::ONE);
/// let (t, b) = grid.locate(&uv, &triangles, DVec2::new(0.8, 0.7)).unwrap();
/// assert_eq!(t, 1);
/// assert!((b.iter().sum::<f64>() - 1.0).abs() < 1e-12);
/// assert!(grid.locate(&uv, &triangles, DVec2::new(2.0, 0.5)).is_none());
/// ```
#[derive(Clone, Debug)]
pub struct TriangleGrid {
    low: DVec2,
    cell: DVec2,
    cells: usize,
    buckets: Vec<Vec<u32>>,
}

impl TriangleGrid {
    /// Buckets `triangles` (corners indexing `uv`) over the box from `low`
    /// to `high`; triangles reaching outside it go to the edge cells.
    pub fn new(uv: &[DVec2], triangles: &[[u32; 3]], low: DVec2, high: DVec2) -> TriangleGrid {
        let cells = ((triangles.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let cell = ((high - low) / cells as f64).max(DVec2::splat(f64::MIN_POSITIVE));
        let mut grid = TriangleGrid { low, cell, cells, buckets: vec![Vec::new(); cells * cells] };
        for (t, tri) in triangles.iter().enumerate() {
            let p = tri.map(|v| uv[v as usize]);
            let (lo, hi) = (grid.index(p[0].min(p[1]).min(p[2])), grid.index(p[0].max(p[1]).max(p[2])));
            for y in lo.1..=hi.1 {
                for x in lo.0..=hi.0 {
                    grid.buckets[y * cells + x].push(t as u32);
                }
            }
        }
        grid
    }

    fn index(&self, p: DVec2) -> (usize, usize) {
        let q = ((p - self.low) / self.cell).floor().max(DVec2::ZERO);
        ((q.x as usize).min(self.cells - 1), (q.y as usize).min(self.cells - 1))
    }

    /// The triangles whose boxes reach `p`'s cell.
    pub fn candidates(&self, p: DVec2) -> &[u32] {
        if !p.is_finite() {
            return &[];
        }
        let (x, y) = self.index(p);
        &self.buckets[y * self.cells + x]
    }

    /// The first triangle holding `p`, with `p`'s barycentric coordinates in it.
    pub fn locate(&self, uv: &[DVec2], triangles: &[[u32; 3]], p: DVec2) -> Option<(u32, [f64; 3])> {
        self.candidates(p).iter().find_map(|&t| {
            let b = barycentric(triangles[t as usize].map(|v| uv[v as usize]), p);
            b.iter().all(|&c| c >= -LOCATE_SLACK).then_some((t, b))
        })
    }
}

/// Barycentric coordinates of `p` in the triangle `[a, b, c]` (unclamped).
pub fn barycentric([a, b, c]: [DVec2; 3], p: DVec2) -> [f64; 3] {
    let area = (b - a).perp_dot(c - a);
    let l1 = (p - a).perp_dot(c - a) / area;
    let l2 = (b - a).perp_dot(p - a) / area;
    [1.0 - l1 - l2, l1, l2]
}
