//! Meshes read from files a person brings: STL (binary or ASCII, through
//! `stl_io`) and Wavefront OBJ (through `tobj`, polygons triangulated).
//! Vertices at the same position are merged, so that a mesh written as a
//! soup of triangles (as STL always is) comes back connected.

use std::collections::HashMap;
use std::io::{BufReader, Cursor};
use std::path::Path;

use super::Mesh;

/// Most triangles a mesh read from a file may have: a base or a swatch
/// larger than this would take minutes to parameterize and more memory than
/// a desktop should give a preview.
pub const MAX_IMPORTED_TRIANGLES: usize = 2_000_000;

/// Why a mesh file could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ImportError {
    /// The file could not be opened or read.
    #[error("could not read {path}: {reason}")]
    Io {
        /// The file.
        path: String,
        /// What the system said.
        reason: String,
    },
    /// The file's name does not say STL or OBJ.
    #[error("{path} is neither an STL nor an OBJ file (by its extension)")]
    Format {
        /// The file.
        path: String,
    },
    /// The file is not a valid mesh of its kind.
    #[error("{path} is not a valid {kind} file: {reason}")]
    Parse {
        /// The file.
        path: String,
        /// STL or OBJ.
        kind: &'static str,
        /// What the parser said.
        reason: String,
    },
    /// The file holds no triangle.
    #[error("{path} holds no triangles")]
    Empty {
        /// The file.
        path: String,
    },
    /// The file holds more triangles than Tracery takes.
    #[error("{path} has {triangles} triangles; at most {MAX_IMPORTED_TRIANGLES} are taken (simplify it first)")]
    TooLarge {
        /// The file.
        path: String,
        /// How many it has.
        triangles: usize,
    },
    /// A coordinate is not a finite number.
    #[error("{path} has a vertex that is not a finite number")]
    NotFinite {
        /// The file.
        path: String,
    },
}

/// Reads an STL or OBJ file (by its extension) into a mesh in the file's own
/// units, taken as millimetres.
pub fn read_mesh_file(path: &Path) -> Result<Mesh, ImportError> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| ImportError::Io { path: name.clone(), reason: e.to_string() })?;
    let extension = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
    match extension.as_str() {
        "stl" => read_stl(&bytes, &name),
        "obj" => read_obj(&bytes, &name),
        _ => Err(ImportError::Format { path: name }),
    }
}

/// Reads STL bytes; `name` is used in messages.
///
/// ```
/// use tracery_core::mesh::{Mesh, read_stl};
/// use tracery_core::export::write_stl;
/// let tetra = Mesh {
///     vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
///     triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
/// };
/// let mut bytes = Vec::new();
/// write_stl(&tetra, &mut bytes).unwrap();
/// let back = read_stl(&bytes, "tetra.stl").unwrap();
/// assert_eq!(back.vertices.len(), 4);
/// assert_eq!(back.triangles.len(), 4);
/// ```
pub fn read_stl(bytes: &[u8], name: &str) -> Result<Mesh, ImportError> {
    let parse = |reason: String| ImportError::Parse { path: name.to_string(), kind: "STL", reason };
    let indexed = stl_io::read_stl(&mut Cursor::new(bytes)).map_err(|e| parse(e.to_string()))?;
    let positions: Vec<[f64; 3]> = indexed.vertices.iter().map(|v| v.0.map(f64::from)).collect();
    let triangles: Vec<[usize; 3]> = indexed.faces.iter().map(|f| f.vertices).collect();
    welded(&positions, &triangles, name)
}

/// Reads OBJ bytes (every object and group, polygons triangulated); `name`
/// is used in messages. Materials are ignored.
pub fn read_obj(bytes: &[u8], name: &str) -> Result<Mesh, ImportError> {
    let options = tobj::LoadOptions { triangulate: true, ..Default::default() };
    let (models, _) = tobj::load_obj_buf(&mut BufReader::new(Cursor::new(bytes)), &options, |_| {
        Err(tobj::LoadError::MaterialParseError)
    })
    .map_err(|e| ImportError::Parse { path: name.to_string(), kind: "OBJ", reason: e.to_string() })?;
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for model in &models {
        let base = positions.len();
        positions.extend(model.mesh.positions.chunks_exact(3).map(|p| [p[0], p[1], p[2]].map(f64::from)));
        for t in model.mesh.indices.chunks_exact(3) {
            let t = [t[0], t[1], t[2]].map(|i| base + i as usize);
            if t.iter().any(|&i| i >= positions.len()) {
                return Err(ImportError::Parse {
                    path: name.to_string(),
                    kind: "OBJ",
                    reason: "a face names a vertex that is not there".into(),
                });
            }
            triangles.push(t);
        }
    }
    welded(&positions, &triangles, name)
}

/// Merges vertices at exactly the same position, drops triangles that
/// collapse, and checks the size.
fn welded(positions: &[[f64; 3]], triangles: &[[usize; 3]], name: &str) -> Result<Mesh, ImportError> {
    if triangles.len() > MAX_IMPORTED_TRIANGLES {
        return Err(ImportError::TooLarge { path: name.to_string(), triangles: triangles.len() });
    }
    if positions.iter().flatten().any(|c| !c.is_finite()) {
        return Err(ImportError::NotFinite { path: name.to_string() });
    }
    let mut index: HashMap<[u64; 3], u32> = HashMap::new();
    let mut mesh = Mesh::default();
    // Negative zero and zero are one position.
    let key = |p: &[f64; 3]| p.map(|c| (c + 0.0).to_bits());
    let remap: Vec<u32> = positions
        .iter()
        .map(|p| {
            *index.entry(key(p)).or_insert_with(|| {
                mesh.vertices.push(*p);
                (mesh.vertices.len() - 1) as u32
            })
        })
        .collect();
    mesh.triangles = triangles
        .iter()
        .map(|t| t.map(|i| remap[i]))
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    if mesh.triangles.is_empty() {
        return Err(ImportError::Empty { path: name.to_string() });
    }
    Ok(mesh)
}
