//! The result as textured triangles: a fine grid per piece, its corners in
//! the plane and in the exemplar, with each seam's remapping applied to the
//! texture coordinates, fading to nothing at the piece's left edge.

use glam::DVec2;

use super::{RasterExemplar, RasterSynthesis};
use crate::product::TexturedMesh;

/// Grid spacing inside a piece, exemplar pixels: fine enough for the
/// stitching's deformation to look smooth.
const GRID_PX: f64 = 3.0;

/// The pieces of `synthesis` as textured triangles; `stitched` applies the
/// seams' remapping.
pub fn textured_mesh(exemplar: &RasterExemplar, synthesis: &RasterSynthesis, stitched: bool) -> TexturedMesh {
    let ribbon = &synthesis.ribbon;
    let c = ribbon.column_px as f64;
    let rows = (c / GRID_PX).ceil().max(1.0) as usize;
    let mut mesh = TexturedMesh { texture: Some(exemplar.texture.clone()), ..TexturedMesh::default() };
    for (i, piece) in ribbon.pieces.iter().enumerate() {
        let [tl, tr, br, bl] = piece.corners_mm;
        let [rt, rb] = piece.right_px;
        let width_px = rt.x.abs().max(rb.x.abs());
        let columns = (width_px / GRID_PX).ceil().max(1.0) as usize;
        let (x, y) = synthesis.path.positions[i];
        let origin = DVec2::new(f64::from(x), f64::from(y));
        let remap = synthesis.seams.get(i).and_then(|s| s.as_ref()).filter(|_| stitched);
        // Shift along the right edge at height fraction b, in samples.
        let shift = |b: f64| -> f64 {
            let Some(seam) = remap else { return 0.0 };
            let s = (b * c - 0.5).clamp(0.0, c - 1.0);
            let (k, f) = (s.floor() as usize, s.fract());
            let at = |k: usize| f64::from(seam.remap[k.min(seam.remap.len() - 1)]) - k as f64;
            at(k) * (1.0 - f) + at(k + 1) * f
        };
        let first = mesh.positions_mm.len() as u32;
        for j in 0..=rows {
            let b = j as f64 / rows as f64;
            // The same expressions on both sides of a seam, so that
            // neighbouring pieces share their edge's points exactly.
            let (left_mm, right_mm) = (tl * (1.0 - b) + bl * b, tr * (1.0 - b) + br * b);
            let right_uv = rt * (1.0 - b) + rb * b;
            let left_uv = DVec2::new(0.0, c * b);
            let delta = (rb - rt) / c * shift(b);
            for k in 0..=columns {
                let a = k as f64 / columns as f64;
                mesh.positions_mm.push(left_mm * (1.0 - a) + right_mm * a);
                mesh.uvs_px.push(origin + left_uv * (1.0 - a) + right_uv * a + delta * a);
            }
        }
        let stride = columns as u32 + 1;
        for j in 0..rows as u32 {
            for k in 0..columns as u32 {
                let v = first + j * stride + k;
                mesh.triangles.push([v, v + 1, v + stride + 1]);
                mesh.triangles.push([v, v + stride + 1, v + stride]);
            }
        }
    }
    mesh
}
