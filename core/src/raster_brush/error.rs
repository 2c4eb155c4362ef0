//! Errors a person can read.

use super::InvalidSetting;
use crate::control::{Cancelled, MaybeCancelled};
use crate::export::RenderError;
use crate::mesh::MeshError;

/// Why a raster exemplar could not be loaded.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ExemplarError {
    /// Not a PNG, or a damaged one.
    #[error("this is not a PNG picture ({0})")]
    NotPng(String),
    /// No alpha channel: the pattern cannot be told from its background.
    #[error("the picture has no transparency: an exemplar needs a transparent background around its pattern")]
    NoAlpha,
    /// Nothing opaque.
    #[error("the picture is fully transparent: there is no pattern in it")]
    FullyTransparent,
    /// Nothing transparent.
    #[error("the picture is fully opaque: an exemplar needs a transparent background around its pattern")]
    FullyOpaque,
    /// Too large to search.
    #[error(
        "the picture is {width} x {height} pixels; an exemplar may be at most {max_width} x {max_height} (scale it down)"
    )]
    TooLarge {
        /// Width found.
        width: u32,
        /// Height found.
        height: u32,
        /// Widest accepted.
        max_width: u32,
        /// Tallest accepted.
        max_height: u32,
    },
    /// Too small to cut into pieces.
    #[error("the picture is {width} x {height} pixels; an exemplar needs at least {min} pixels each way")]
    TooSmall {
        /// Width found.
        width: u32,
        /// Height found.
        height: u32,
        /// The minimum.
        min: u32,
    },
}

/// Why a raster synthesis failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RasterError {
    /// The raster brush needs a curve.
    #[error("the raster brush runs along curves: give line:, circle:, wave: or svg:, not a rectangle")]
    NotACurve,
    /// A setting is out of range.
    #[error(transparent)]
    Setting(#[from] InvalidSetting),
    /// The curve is shorter than one piece.
    #[error(
        "the curve is {length_mm:.1} mm long, shorter than one piece ({step_mm:.1} mm): draw a longer curve or lower the step"
    )]
    CurveTooShort {
        /// The curve's length, mm.
        length_mm: f64,
        /// One piece, mm.
        step_mm: f64,
    },
    /// A piece fits nowhere in the exemplar.
    #[error(
        "piece {piece} (at {at_mm:.1} mm along the curve) fits nowhere in the exemplar: the band is too narrow for the pattern there, or the curve bends too sharply; widen the band or lower the scale"
    )]
    Unplaceable {
        /// The piece, from the start.
        piece: usize,
        /// Where it starts along the curve, mm.
        at_mm: f64,
    },
    /// The ribbon is too large to check at the exemplar's resolution.
    #[error(
        "the ribbon would need {} cells to check for fold-overs (at most {max}); lower the scale or shorten the curve",
        crate::setting::count(*cells)
    )]
    TooLarge {
        /// Cells needed.
        cells: usize,
        /// The limit.
        max: usize,
    },
    /// The result could not be rendered.
    #[error(transparent)]
    Render(#[from] RenderError),
    /// The traced outline could not be made into a solid.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// The person asked to stop.
    #[error(transparent)]
    Cancelled(#[from] Cancelled),
}

impl MaybeCancelled for RasterError {
    fn is_cancelled(&self) -> bool {
        matches!(self, RasterError::Cancelled(_))
    }
}
