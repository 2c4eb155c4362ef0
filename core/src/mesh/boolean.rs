//! Booleans of closed meshes (union, difference, intersection), through `boolmesh`: a
//! port of Manifold's algorithm, which keeps its output closed and
//! manifold even where the two inputs touch along faces.

use boolmesh::prelude::{Manifold, OpType, compute_boolean};

use super::Mesh;

/// Why a boolean could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum BooleanError {
    /// One of the two meshes is not closed and manifold.
    #[error("the {which} is not a closed, manifold mesh, so it cannot be combined with another")]
    NotManifold {
        /// Which input: "model" or "pattern".
        which: &'static str,
    },
    /// The boolean itself failed.
    #[error("the pattern could not be combined with the model: {0}")]
    Failed(String),
}

fn manifold(mesh: &Mesh, which: &'static str) -> Result<Manifold, BooleanError> {
    let positions: Vec<f64> = mesh.vertices.iter().flatten().copied().collect();
    let indices: Vec<usize> = mesh.triangles.iter().flatten().map(|&i| i as usize).collect();
    Manifold::new(&positions, &indices).map_err(|_| BooleanError::NotManifold { which })
}

/// Whether the booleans take `mesh` as a solid. A boolean's own output can
/// fail this: cutting a solid that passes through itself can leave a pinch
/// (two vertices at one place) that is closed edge by edge yet refused as
/// the input of the next boolean.
///
/// ```
/// use tracery_core::mesh::{Mesh, is_boolean_solid};
/// let tetra = Mesh {
///     vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
/// };
/// assert!(is_boolean_solid(&tetra));
/// assert!(!is_boolean_solid(&Mesh { triangles: tetra.triangles[..3].to_vec(), ..tetra }));
/// ```
pub fn is_boolean_solid(mesh: &Mesh) -> bool {
    manifold(mesh, "model").is_ok()
}

fn mesh_of(m: &Manifold) -> Mesh {
    Mesh {
        vertices: m.ps.iter().map(|p| [p.x, p.y, p.z]).collect(),
        triangles: m.hs.chunks(3).map(|t| [t[0].tail as u32, t[1].tail as u32, t[2].tail as u32]).collect(),
    }
}

fn combine(model: &Mesh, pattern: &Mesh, op: OpType) -> Result<Mesh, BooleanError> {
    let result = compute_boolean(&manifold(model, "model")?, &manifold(pattern, "pattern")?, op)
        .map_err(BooleanError::Failed)?;
    let mut mesh = mesh_of(&result);
    // Where two surfaces nearly meet, corners come out a fraction of a
    // micrometre apart, and an STL's `f32` would merge them.
    super::collapse_short_edges(&mut mesh, super::MIN_EDGE_MM);
    Ok(mesh)
}

/// Everything inside `model` or `pattern` (both closed and facing out).
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::mesh::{extrude, union_solids};
/// let square = |x: f64| Region::new(vec![Polygon {
///     outer: vec![DVec2::new(x, 0.0), DVec2::new(x + 2.0, 0.0), DVec2::new(x + 2.0, 2.0), DVec2::new(x, 2.0)],
///     holes: vec![],
/// }]);
/// let both = union_solids(&extrude(&square(0.0), 1.0).unwrap(), &extrude(&square(1.0), 1.0).unwrap()).unwrap();
/// assert!(both.sanity_check().is_ok());
/// assert_eq!(both.shell_count(), 1);
/// assert!((both.signed_volume() - 6.0).abs() < 1e-9);
/// ```
pub fn union_solids(model: &Mesh, pattern: &Mesh) -> Result<Mesh, BooleanError> {
    combine(model, pattern, OpType::Add)
}

/// Everything inside `model` and outside `pattern`.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::mesh::{difference_solids, extrude};
/// let square = |x: f64, s: f64| Region::new(vec![Polygon {
///     outer: vec![DVec2::new(x, x), DVec2::new(x + s, x), DVec2::new(x + s, x + s), DVec2::new(x, x + s)],
///     holes: vec![],
/// }]);
/// // A 1 mm square post through a 4 mm square plate: a plate with a hole.
/// let post = extrude(&square(1.5, 1.0), 3.0).unwrap().vertices.iter().map(|v| [v[0], v[1], v[2] - 1.0]).collect();
/// let post = tracery_core::mesh::Mesh { vertices: post, ..extrude(&square(1.5, 1.0), 3.0).unwrap() };
/// let plate = difference_solids(&extrude(&square(0.0, 4.0), 1.0).unwrap(), &post).unwrap();
/// assert!(plate.sanity_check().is_ok());
/// assert!((plate.signed_volume() - 15.0).abs() < 1e-9);
/// ```
pub fn difference_solids(model: &Mesh, pattern: &Mesh) -> Result<Mesh, BooleanError> {
    combine(model, pattern, OpType::Subtract)
}

/// Everything inside both `model` and `pattern`.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::mesh::{extrude, intersect_solids};
/// let square = |x: f64| Region::new(vec![Polygon {
///     outer: vec![DVec2::new(x, 0.0), DVec2::new(x + 2.0, 0.0), DVec2::new(x + 2.0, 2.0), DVec2::new(x, 2.0)],
///     holes: vec![],
/// }]);
/// let both = intersect_solids(&extrude(&square(0.0), 1.0).unwrap(), &extrude(&square(1.5), 1.0).unwrap()).unwrap();
/// assert!(both.sanity_check().is_ok());
/// assert!((both.signed_volume() - 1.0).abs() < 1e-9);
/// ```
pub fn intersect_solids(model: &Mesh, pattern: &Mesh) -> Result<Mesh, BooleanError> {
    combine(model, pattern, OpType::Intersect)
}
