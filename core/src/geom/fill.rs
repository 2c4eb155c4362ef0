//! Triangles that fill a region, for drawing it quickly (not for printing:
//! the solid comes from [`crate::mesh::extrude`], which keeps every outline
//! edge exactly).

use glam::DVec2;
use lyon::path::Path;
use lyon::tessellation::{BuffersBuilder, FillOptions, FillRule, FillTessellator, FillVertex, VertexBuffers};

use super::Region;

/// The region as triangles, through lyon's sweep-line fill tessellator:
/// several times faster than a constrained Delaunay triangulation, which is
/// what a preview redrawn while the pointer moves needs. Empty if the
/// tessellator gives up on a degenerate outline.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region, fill_triangles, signed_area};
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let mut hole = square(1.0);
/// hole.reverse();
/// let frame = Region::new(vec![Polygon { outer: square(2.0), holes: vec![hole] }]);
/// let area: f64 = fill_triangles(&frame).iter().map(|t| signed_area(t).abs()).sum();
/// assert!((area - 12.0).abs() < 1e-3);
/// ```
pub fn fill_triangles(region: &Region) -> Vec<[DVec2; 3]> {
    let mut builder = Path::builder();
    for ring in region.rings().filter(|r| r.len() >= 3) {
        builder.begin(lyon::math::point(ring[0].x as f32, ring[0].y as f32));
        for p in &ring[1..] {
            builder.line_to(lyon::math::point(p.x as f32, p.y as f32));
        }
        builder.end(true);
    }
    let path = builder.build();
    let mut buffers: VertexBuffers<DVec2, u32> = VertexBuffers::new();
    let result = FillTessellator::new().tessellate_path(
        &path,
        &FillOptions::default().with_fill_rule(FillRule::EvenOdd),
        &mut BuffersBuilder::new(&mut buffers, |v: FillVertex| {
            let p = v.position();
            DVec2::new(f64::from(p.x), f64::from(p.y))
        }),
    );
    if result.is_err() {
        return Vec::new();
    }
    buffers.indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]].map(|i| buffers.vertices[i as usize])).collect()
}
