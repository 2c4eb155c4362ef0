//! [`QuiltError`]: why a quilt could not be made, in words a person understands.

use crate::control::{Cancelled, MaybeCancelled};
use crate::mesh::ImportError;
use crate::setting::InvalidSetting;

/// Why a quilt could not be made.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum QuiltError {
    /// A setting is out of range.
    #[error(transparent)]
    Setting(#[from] InvalidSetting),
    /// A mesh file could not be read.
    #[error(transparent)]
    Import(#[from] ImportError),
    /// The swatch has no triangles.
    #[error("the swatch has no triangles: a swatch needs at least one element (a closed mesh)")]
    NoElements,
    /// An edge of the swatch has more than two triangles.
    #[error(
        "the swatch is not manifold: {edges} edge(s) have more than two triangles, the first near ({:.1}, {:.1}, {:.1}) mm",
        at_mm[0], at_mm[1], at_mm[2]
    )]
    NonManifold {
        /// How many edges.
        edges: usize,
        /// Where the first one is, mm.
        at_mm: [f64; 3],
    },
    /// An element of the swatch is not a closed surface.
    #[error(
        "element {element} of the swatch is not a closed surface ({reason}); every element must be a closed mesh to be printed"
    )]
    OpenElement {
        /// Which element, from 1.
        element: usize,
        /// What is wrong.
        reason: String,
    },
    /// The swatch has too many triangles.
    #[error("the swatch has {triangles} triangles, and at most {max} are allowed (simplify it first)")]
    SwatchTooLarge {
        /// Its triangles.
        triangles: usize,
        /// The cap.
        max: usize,
    },
    /// The swatch is flat or a point.
    #[error("the swatch is {width_mm:.2} x {depth_mm:.2} mm seen from above: it needs some width and depth")]
    FlatSwatch {
        /// Its width, mm.
        width_mm: f64,
        /// Its depth, mm.
        depth_mm: f64,
    },
    /// The quilt would have too many triangles.
    #[error(
        "the quilt would have about {triangles} triangles, and at most {max} are allowed (make the area smaller or the scale larger)"
    )]
    OutputTooLarge {
        /// Its triangles, estimated.
        triangles: usize,
        /// The cap.
        max: usize,
    },
    /// Every element laid was left out again: the print would be empty.
    #[error(
        "no element of the swatch stays on the model ({0}); try a smaller scale, or check that the model's faces look outward"
    )]
    NothingPlaced(String),
    /// The base spec is not one this program knows.
    #[error("'{0}' is not a base: use plane:WIDTHxHEIGHT (mm), a built-in base's name, or an STL or OBJ file")]
    BadBase(String),
    /// The guidance field cannot be used.
    #[error("the guidance field is not usable: {0}")]
    BadField(String),
    /// The texture could not be cut at the floor.
    #[error("the texture could not be cut flat where the model stands: {0}")]
    Floor(#[from] crate::mesh::BooleanError),
    /// The texture could not be united with the model.
    #[error(transparent)]
    Assembly(#[from] crate::surface::AssemblyError),
    /// The work was cancelled.
    #[error(transparent)]
    Cancelled(#[from] Cancelled),
    /// A fault in Tracery itself, caught in a worker.
    #[error(transparent)]
    Internal(#[from] crate::control::Internal),
}

impl MaybeCancelled for QuiltError {
    fn is_cancelled(&self) -> bool {
        matches!(self, QuiltError::Cancelled(_))
    }
}
