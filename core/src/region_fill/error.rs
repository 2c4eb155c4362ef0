//! [`FillError`]: why a fill could not be made, in words a person understands.

use crate::control::{Cancelled, MaybeCancelled};
use crate::curve::CurveError;
use crate::mesh::MeshError;

use super::{InvalidSetting, SampleError};

/// Why a fill could not be made.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum FillError {
    /// A setting is out of range.
    #[error(transparent)]
    Setting(#[from] InvalidSetting),
    /// The exemplar has nothing to learn from.
    #[error("the exemplar has no stroked path or filled shape: a curve exemplar needs at least one")]
    NoStrokes,
    /// The exemplar would have too many samples.
    #[error(
        "the exemplar is too large: {samples} samples at this spacing, and at most {max} are allowed (draw it smaller or raise the spacing)"
    )]
    ExemplarTooLarge {
        /// Samples it would have.
        samples: usize,
        /// The cap.
        max: usize,
    },
    /// The exemplar could not be sampled.
    #[error(transparent)]
    Sample(#[from] SampleError),
    /// The region spec is not one this program knows.
    #[error(
        "'{0}' is not a region: use rect:WIDTHxHEIGHT, circle:RADIUS (mm, up to 10000) or svg:FILE.svg (within 10000 mm of its origin)"
    )]
    BadRegionSpec(String),
    /// The drawing a region or exemplar was to come from could not be read.
    #[error(transparent)]
    Drawing(#[from] CurveError),
    /// A file could not be read.
    #[error("could not read {path}: {message}")]
    Read {
        /// The file.
        path: String,
        /// What went wrong.
        message: String,
    },
    /// The region has no area.
    #[error("the region is empty: it needs a closed outline with some area")]
    EmptyRegion,
    /// The region's outline crosses itself.
    #[error("the region's outline crosses itself near ({x_mm:.1}, {y_mm:.1}) mm: draw it without crossings")]
    RegionCrossesItself {
        /// Where, mm.
        x_mm: f64,
        /// Where, mm.
        y_mm: f64,
    },
    /// No neighbourhood fits in the region.
    #[error(
        "the region is too small: nowhere in it is there room for a neighbourhood {diameter_mm:.1} mm across (make it larger or lower the sample spacing)"
    )]
    RegionTooSmall {
        /// The neighbourhood's diameter, mm.
        diameter_mm: f64,
    },
    /// The region would take too many samples.
    #[error(
        "the region is too large: about {samples} samples at this spacing, and at most {max} are allowed (raise the spacing)"
    )]
    RegionTooLarge {
        /// Samples it would take.
        samples: usize,
        /// The cap.
        max: usize,
    },
    /// The synthesis kept nothing of the exemplar.
    #[error(
        "nothing of the exemplar survived the fill: at {:.0} x {:.0} mm it may be far larger than the {:.0} x {:.0} mm region, or its detail finer than the {delta_mm} mm sample spacing (change the exemplar scale)",
        exemplar_mm[0], exemplar_mm[1], region_mm[0], region_mm[1]
    )]
    NothingSynthesized {
        /// The exemplar's size as the fill learns from it, mm.
        exemplar_mm: [f64; 2],
        /// The size of the region's bounds, mm.
        region_mm: [f64; 2],
        /// The finest sample spacing, mm.
        delta_mm: f64,
    },
    /// Nothing survived, from an exemplar of one or two lines: nothing in
    /// it repeats or meets for a pattern to learn.
    #[error(
        "nothing of the exemplar survived the fill: it is only {paths} line(s) (the longest {longest_mm:.0} mm), with nothing that repeats or meets for a pattern to learn; draw an exemplar of several curves"
    )]
    FewCurves {
        /// Paths of the exemplar, as the fill learns it.
        paths: usize,
        /// The longest of them, mm.
        longest_mm: f64,
    },
    /// The solid could not be made.
    #[error("the print could not be made: {0}")]
    Mesh(#[from] MeshError),
    /// Stopped on request.
    #[error(transparent)]
    Cancelled(#[from] Cancelled),
    /// A fault in Tracery itself, caught in a worker.
    #[error(transparent)]
    Internal(#[from] crate::control::Internal),
}

impl MaybeCancelled for FillError {
    fn is_cancelled(&self) -> bool {
        matches!(self, FillError::Cancelled(_))
    }
}
