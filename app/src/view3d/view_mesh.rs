//! A mesh as the 3D view draws it: `f32` positions and indices, made once
//! from a core mesh and shared with the GPU upload by `Arc`.

use glam::Vec3;
use tracery_core::mesh::Mesh;

/// An axis-aligned box, mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// The low corner.
    pub min: Vec3,
    /// The high corner.
    pub max: Vec3,
}

impl Bounds {
    /// Nothing: the union's identity.
    pub const EMPTY: Bounds = Bounds { min: Vec3::INFINITY, max: Vec3::NEG_INFINITY };

    /// Whether the box holds any point.
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x
    }

    /// The box holding both.
    pub fn union(&self, other: &Bounds) -> Bounds {
        Bounds { min: self.min.min(other.min), max: self.max.max(other.max) }
    }

    /// The centre.
    pub fn centre(&self) -> Vec3 {
        if self.is_empty() { Vec3::ZERO } else { (self.min + self.max) / 2.0 }
    }

    /// Half the diagonal.
    pub fn radius(&self) -> f32 {
        if self.is_empty() { 0.0 } else { (self.max - self.min).length() / 2.0 }
    }
}

/// Triangles ready for the GPU.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewMesh {
    /// Vertex positions, mm.
    pub positions: Vec<[f32; 3]>,
    /// Three vertex indices per triangle.
    pub indices: Vec<u32>,
    /// The box around the positions.
    pub bounds: Bounds,
}

impl ViewMesh {
    /// The view's copy of `mesh`.
    pub fn new(mesh: &Mesh) -> ViewMesh {
        let positions: Vec<[f32; 3]> = mesh.vertices.iter().map(|v| v.map(|c| c as f32)).collect();
        let bounds = positions
            .iter()
            .fold(Bounds::EMPTY, |b, &p| Bounds { min: b.min.min(Vec3::from(p)), max: b.max.max(Vec3::from(p)) });
        let indices = mesh.triangles.iter().flatten().copied().collect();
        ViewMesh { positions, indices, bounds }
    }

    /// How many triangles it has.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }
}
