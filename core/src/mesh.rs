//! Triangle meshes: extrusion of a planar pattern, STL output, and checks.

use std::io::Write;

use lyon::path::EndpointId;
use lyon::path::commands::PathCommands;
use lyon::tessellation::{
    BuffersBuilder, FillOptions, FillRule as LyonFill, FillTessellator, FillVertex, VertexBuffers, VertexSource,
};

use crate::Region;

/// A triangle mesh in millimetres.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub vertices: Vec<[f64; 3]>,
    /// Triangles as vertex indices, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

/// Why a mesh could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    /// The pattern is empty.
    #[error("there is no pattern to turn into a mesh")]
    Empty,
    /// Thickness is not a positive number.
    #[error("the thickness {0} mm must be a positive number")]
    Thickness(f64),
    /// The tessellator failed on the pattern's outline.
    #[error("the pattern's outline could not be triangulated: {0}")]
    Tessellation(String),
}

/// Extrudes `region` (millimetres, in the plane `z = 0`) to `thickness_mm`:
/// a closed, 2-manifold, consistently oriented mesh with one shell per component.
///
/// Top and bottom faces come from a constrained tessellation of the region
/// whose vertices are exactly the rings' vertices (matched by id, not by
/// position), and the walls join the same vertices, so the mesh is watertight
/// by construction.
pub fn extrude(region: &Region, thickness_mm: f64) -> Result<Mesh, MeshError> {
    if !(thickness_mm.is_finite() && thickness_mm > 0.0) {
        return Err(MeshError::Thickness(thickness_mm));
    }
    let rings: Vec<&Vec<glam::DVec2>> = region.rings().filter(|r| r.len() >= 3).collect();
    if rings.is_empty() {
        return Err(MeshError::Empty);
    }
    let center = region.bounds().map_or(glam::DVec2::ZERO, |b| b.center());
    let mut flat: Vec<glam::DVec2> = Vec::new();
    let mut builder = PathCommands::builder();
    for ring in &rings {
        let first = flat.len();
        for (k, p) in ring.iter().enumerate() {
            let id = EndpointId((first + k) as u32);
            if k == 0 {
                builder.begin(id);
            } else {
                builder.line_to(id);
            }
            flat.push(*p);
        }
        builder.end(true);
    }
    let commands = builder.build();
    let positions: Vec<lyon::math::Point> =
        flat.iter().map(|p| lyon::math::point((p.x - center.x) as f32, (p.y - center.y) as f32)).collect();
    let mut buffers: VertexBuffers<u32, u32> = VertexBuffers::new();
    {
        let mut output = BuffersBuilder::new(&mut buffers, |v: FillVertex| {
            for source in v.sources() {
                if let VertexSource::Endpoint { id } = source {
                    return id.0;
                }
            }
            // A vertex the tessellator had to add: the outline was not clean.
            u32::MAX
        });
        let options = FillOptions::default().with_fill_rule(LyonFill::NonZero).with_tolerance(1e-4);
        FillTessellator::new()
            .tessellate_with_ids(commands.iter(), &(positions.as_slice(), &[][..]), None, &options, &mut output)
            .map_err(|e| MeshError::Tessellation(format!("{e:?}")))?;
    }
    let source_of: Vec<u32> = buffers.vertices.clone();
    if source_of.contains(&u32::MAX) {
        return Err(MeshError::Tessellation("the outline crosses itself".into()));
    }
    let count = flat.len() as u32;
    let mut mesh = Mesh { vertices: Vec::with_capacity(2 * flat.len()), triangles: Vec::new() };
    for p in &flat {
        mesh.vertices.push([p.x, p.y, 0.0]);
    }
    for p in &flat {
        mesh.vertices.push([p.x, p.y, thickness_mm]);
    }
    for tri in buffers.indices.chunks_exact(3) {
        let (a, b, c) = (source_of[tri[0] as usize], source_of[tri[1] as usize], source_of[tri[2] as usize]);
        if a == b || b == c || a == c {
            continue;
        }
        // Orient by the triangle's own winding so the top faces up.
        let (pa, pb, pc) = (flat[a as usize], flat[b as usize], flat[c as usize]);
        let ccw = (pb - pa).perp_dot(pc - pa) > 0.0;
        let (b, c) = if ccw { (b, c) } else { (c, b) };
        mesh.triangles.push([a + count, b + count, c + count]);
        mesh.triangles.push([a, c, b]);
    }
    let mut start = 0u32;
    for ring in &rings {
        let n = ring.len() as u32;
        for k in 0..n {
            let a = start + k;
            let b = start + (k + 1) % n;
            // Outer rings run counter-clockwise and holes clockwise, so the
            // material is on the left of every edge and the wall faces right.
            mesh.triangles.push([a, b, b + count]);
            mesh.triangles.push([a, b + count, a + count]);
        }
        start += n;
    }
    Ok(mesh)
}

impl Mesh {
    /// Number of shells: groups of triangles connected through shared edges.
    pub fn shell_count(&self) -> usize {
        let n = self.triangles.len();
        let mut parent: Vec<usize> = (0..n).collect();
        fn find(parent: &mut [usize], mut x: usize) -> usize {
            while parent[x] != x {
                parent[x] = parent[parent[x]];
                x = parent[x];
            }
            x
        }
        let mut by_edge: std::collections::HashMap<(u32, u32), usize> = std::collections::HashMap::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let key = (a.min(b), a.max(b));
                if let Some(&other) = by_edge.get(&key) {
                    let (ra, rb) = (find(&mut parent, t), find(&mut parent, other));
                    parent[ra] = rb;
                } else {
                    by_edge.insert(key, t);
                }
            }
        }
        (0..n).filter(|&t| find(&mut parent, t) == t).count()
    }

    /// Writes a binary STL (millimetres).
    pub fn write_stl(&self, out: &mut impl Write) -> std::io::Result<()> {
        let mut header = [0u8; 80];
        let text = b"Tracery pattern, millimetres";
        header[..text.len()].copy_from_slice(text);
        out.write_all(&header)?;
        out.write_all(&(self.triangles.len() as u32).to_le_bytes())?;
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| glam::DVec3::from(self.vertices[i as usize]));
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
}
