//! Binary STL, in millimetres.

use std::io::Write;

use crate::mesh::Mesh;

/// Writes `mesh` as a binary STL (millimetres). STL stores `f32`: meshes
/// made by [`crate::mesh::extrude`] are already rounded to it and welded.
///
/// ```
/// use tracery_core::{export::write_stl, mesh::extrude};
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let mut hole = square(1.0);
/// hole.reverse();
/// let frame = Region::new(vec![Polygon { outer: square(2.0), holes: vec![hole] }]);
/// let mesh = extrude(&frame, 2.0).unwrap();
/// let mut bytes = Vec::new();
/// write_stl(&mesh, &mut bytes).unwrap();
/// assert_eq!(bytes.len(), 84 + 50 * mesh.triangles.len());
/// ```
pub fn write_stl(mesh: &Mesh, out: &mut impl Write) -> std::io::Result<()> {
    let mut header = [0u8; 80];
    let text = b"Tracery pattern, millimetres";
    header[..text.len()].copy_from_slice(text);
    out.write_all(&header)?;
    out.write_all(&(mesh.triangles.len() as u32).to_le_bytes())?;
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| glam::DVec3::from(mesh.vertices[i as usize]));
        let normal = (b - a).cross(c - a).normalize_or_zero();
        for v in [normal, a, b, c] {
            for x in [v.x, v.y, v.z] {
                out.write_all(&(x as f32).to_le_bytes())?;
            }
        }
        out.write_all(&0u16.to_le_bytes())?;
    }
    Ok(())
}
