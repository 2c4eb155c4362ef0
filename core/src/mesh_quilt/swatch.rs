//! [`Swatch`]: the 3D texture sample, split into its elements (connected
//! components), checked, and laid with its thinnest side up.

use rustc_hash::FxHashMap;

use glam::DVec3;

use super::{Element, QuiltError};
use crate::mesh::Mesh;

/// The most triangles a swatch may have: the paper's largest had 35 640.
pub const MAX_SWATCH_TRIANGLES: usize = 200_000;

/// An element whose lowest point lies within this share of the swatch's
/// height of its bottom rests on it.
const FLOAT_TOLERANCE: f64 = 0.01;

/// A swatch: elements in millimetres, its bounding box's lowest corner at
/// the origin and its thinnest side along `z` (the shell's height).
#[derive(Clone, Debug, PartialEq)]
pub struct Swatch {
    /// A name for reports.
    pub name: String,
    /// The elements, each a closed surface.
    pub elements: Vec<Element>,
}

impl Swatch {
    /// Splits `mesh` into elements and checks it: every edge has at most two
    /// triangles, and every element is closed. The swatch is turned so that
    /// its smallest extent is its height, and moved to the origin.
    ///
    /// ```
    /// use tracery_core::mesh::Mesh;
    /// use tracery_core::mesh_quilt::Swatch;
    /// let tetra = Mesh {
    ///     vertices: vec![[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 1.0]],
    ///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    /// };
    /// let swatch = Swatch::from_mesh("tetra", &tetra).unwrap();
    /// assert_eq!(swatch.elements.len(), 1);
    /// assert!(Swatch::from_mesh("empty", &Mesh::default()).is_err());
    /// ```
    pub fn from_mesh(name: &str, mesh: &Mesh) -> Result<Swatch, QuiltError> {
        if mesh.triangles.is_empty() {
            return Err(QuiltError::NoElements);
        }
        if mesh.triangles.len() > MAX_SWATCH_TRIANGLES {
            return Err(QuiltError::SwatchTooLarge { triangles: mesh.triangles.len(), max: MAX_SWATCH_TRIANGLES });
        }
        let mut by_edge: FxHashMap<(u32, u32), Vec<usize>> = FxHashMap::default();
        for (f, t) in mesh.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                by_edge.entry((a.min(b), a.max(b))).or_default().push(f);
            }
        }
        let crowded: Vec<&(u32, u32)> = by_edge.iter().filter(|(_, f)| f.len() > 2).map(|(e, _)| e).collect();
        if let Some(&&(a, b)) = crowded.iter().min() {
            let [p, q] = [a, b].map(|i| DVec3::from_array(mesh.vertices[i as usize]));
            return Err(QuiltError::NonManifold { edges: crowded.len(), at_mm: (0.5 * (p + q)).to_array() });
        }
        let elements = Element::from_mesh(mesh).parts();
        for (i, element) in elements.iter().enumerate() {
            if let Err(defect) = element.to_mesh().sanity_check() {
                return Err(QuiltError::OpenElement { element: i + 1, reason: defect.to_string() });
            }
        }
        Swatch::from_elements(name, elements)
    }

    /// A swatch of elements already split and checked (the built-ins), laid
    /// thinnest side up at the origin.
    pub(super) fn from_elements(name: &str, mut elements: Vec<Element>) -> Result<Swatch, QuiltError> {
        let (lo, hi) = bounds(&elements);
        let size = hi - lo;
        // A cyclic turn of the axes keeps the triangles facing out.
        let turn: fn(DVec3) -> DVec3 = if size.x <= size.y && size.x <= size.z {
            |v| DVec3::new(v.y, v.z, v.x)
        } else if size.y <= size.x && size.y <= size.z {
            |v| DVec3::new(v.z, v.x, v.y)
        } else {
            |v| v
        };
        for e in &mut elements {
            for v in &mut e.vertices {
                *v = turn(*v - lo);
            }
        }
        let (lo, hi) = bounds(&elements);
        let size = hi - lo;
        if !(size.x > 1e-6 && size.y > 1e-6) {
            return Err(QuiltError::FlatSwatch { width_mm: size.x, depth_mm: size.y });
        }
        for e in &mut elements {
            for v in &mut e.vertices {
                *v -= lo;
            }
        }
        Ok(Swatch { name: name.to_string(), elements })
    }

    /// The swatch `factor` times larger.
    pub fn scaled(&self, factor: f64) -> Swatch {
        let elements = self
            .elements
            .iter()
            .map(|e| Element {
                vertices: e.vertices.iter().map(|&v| v * factor).collect(),
                triangles: e.triangles.clone(),
            })
            .collect();
        Swatch { name: self.name.clone(), elements }
    }

    /// How high the lowest element not resting on the swatch's bottom
    /// floats over it, mm: a chain mail's flat rings, held up by the
    /// standing links through them. None when every element rests.
    ///
    /// ```
    /// use tracery_core::mesh_quilt::builtin_swatch;
    /// assert!(builtin_swatch("chainmail").unwrap().least_float_mm().is_some_and(|h| h > 2.0));
    /// assert_eq!(builtin_swatch("rivets").unwrap().least_float_mm(), None);
    /// ```
    pub fn least_float_mm(&self) -> Option<f64> {
        let floor = FLOAT_TOLERANCE * self.size_mm().z;
        self.elements
            .iter()
            .map(|e| e.vertices.iter().map(|v| v.z).fold(f64::INFINITY, f64::min))
            .filter(|&low| low > floor)
            .min_by(f64::total_cmp)
    }

    /// Width, depth and height of the bounding box, mm.
    pub fn size_mm(&self) -> DVec3 {
        let (lo, hi) = bounds(&self.elements);
        hi - lo
    }

    /// The least volume a piece of the quilt keeps to stay in it, mm³: a
    /// quarter of the smallest element's. A fragment of a cut, or what is
    /// left of a thread past the edge, below it is a crumb.
    pub fn fragment_volume_mm3(&self) -> f64 {
        0.25 * self.elements.iter().map(|e| e.to_mesh().signed_volume().abs()).fold(f64::INFINITY, f64::min)
    }

    /// Triangles in all elements.
    pub fn triangle_count(&self) -> usize {
        self.elements.iter().map(|e| e.triangles.len()).sum()
    }

    /// Every element in one mesh (separate shells).
    pub fn to_mesh(&self) -> Mesh {
        let mut mesh = Mesh::default();
        for e in &self.elements {
            mesh.append(&e.to_mesh());
        }
        mesh
    }
}

fn bounds(elements: &[Element]) -> (DVec3, DVec3) {
    elements
        .iter()
        .map(Element::bounds)
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), (l, h)| (lo.min(l), hi.max(h)))
}
