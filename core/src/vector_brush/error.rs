//! Errors a person can read.

use std::path::PathBuf;

use super::Target;
use crate::control::{Cancelled, MaybeCancelled};

/// Why an exemplar could not be loaded.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ExemplarError {
    /// The file could not be read.
    #[error("could not read {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// What the system said.
        source: std::io::Error,
    },
    /// The data is not an SVG document.
    #[error("this is not an SVG file ({0})")]
    NotSvg(String),
    /// The SVG has no filled or stroked shape.
    #[error("the SVG has no filled or stroked shape: an exemplar needs at least one")]
    NothingFilled,
    /// The shapes enclose no area.
    #[error("the SVG's shapes enclose no area (lines without a stroke width, or shapes that cancel out)")]
    ZeroArea,
    /// The drawing is absurdly large or small, or has coordinates that are not numbers.
    #[error("the drawing is {width} x {height} units; an exemplar must measure between {min} and {max} units")]
    AbsurdSize {
        /// Width found.
        width: f64,
        /// Height found.
        height: f64,
        /// Smallest accepted extent.
        min: f64,
        /// Largest accepted extent.
        max: f64,
    },
    /// Too many vertices after flattening curves.
    #[error("the drawing has {vertices} vertices after flattening curves; at most {limit} are supported")]
    TooComplex {
        /// Vertices found.
        vertices: usize,
        /// The limit.
        limit: usize,
    },
    /// The geometry could not be turned into simple polygons.
    #[error("the shapes could not be made into simple polygons: {0}")]
    NotSimple(String),
}

/// Why an exemplar could not be cut into pieces.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SliceError {
    /// The slicing options make no sense.
    #[error("invalid slicing option: {0}")]
    InvalidOption(String),
    /// Too many pieces.
    #[error("the exemplar would be cut into {pieces} pieces; at most {limit} are supported")]
    TooManyPieces {
        /// Pieces asked for.
        pieces: usize,
        /// The limit.
        limit: usize,
    },
    /// A cut crosses more portals than descriptors can hold.
    #[error("a cut crosses the exemplar {portals} times; at most {limit} crossings are supported")]
    TooManyPortals {
        /// Portals found.
        portals: usize,
        /// The limit.
        limit: usize,
    },
}

/// Which user target a failed synthesis could not meet.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Unmet {
    /// The number of components.
    Components(Target),
    /// The number of holes.
    Holes(Target),
    /// Components and holes together (each alone could be met).
    Combination {
        /// Components asked for.
        components: Target,
        /// Holes asked for.
        holes: Target,
    },
    /// The pattern fills the band, and the offsets the pieces need to line
    /// up would take it out: only a pattern smaller than the band has room.
    Band,
    /// A pattern that runs all around the loop.
    ClosedPattern,
    /// No sequence of pieces closes within the curve's length (±50%).
    NoClosingSequence,
    /// A target (components, holes or both) that this exemplar meets, but
    /// not round this loop: what does work is said.
    OnLoop {
        /// The target that is not met on the loop.
        unmet: Box<Unmet>,
        /// Whether the same targets are met on the loop with the pattern
        /// not running all around it ('closed pattern' off).
        without_closed_pattern: bool,
        /// Whether they are met along an open curve of the same length.
        along_open_curve: bool,
    },
}

impl Unmet {
    /// The targets not met, as words ("exactly 1 component(s)").
    fn targets(&self) -> Option<String> {
        match self {
            Unmet::Components(t) => Some(format!("{t} component(s)")),
            Unmet::Holes(t) => Some(format!("{t} hole(s)")),
            Unmet::Combination { components, holes } => Some(format!("{components} component(s) with {holes} hole(s)")),
            _ => None,
        }
    }
}

impl std::fmt::Display for Unmet {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unmet::Components(t) => {
                write!(f, "{t} component(s) cannot be made from this exemplar; relax the components target")
            }
            Unmet::Holes(t) => write!(f, "{t} hole(s) cannot be made from this exemplar; relax the holes target"),
            Unmet::Combination { components, holes } => write!(
                f,
                "{components} component(s) with {holes} hole(s) cannot be made together; relax one of the two targets"
            ),
            Unmet::Band => write!(
                f,
                "the pieces cannot be lined up inside the band at this scale; lower the scale so the pattern has room in the band"
            ),
            Unmet::ClosedPattern => {
                write!(f, "no pattern from this exemplar runs all around the loop; turn off 'closed pattern'")
            }
            Unmet::NoClosingSequence => write!(
                f,
                "no sequence of this exemplar's pieces closes within the curve's length; make the curve longer or cut the exemplar differently"
            ),
            Unmet::OnLoop { unmet, without_closed_pattern, along_open_curve } => {
                let targets = unmet.targets().unwrap_or_else(|| unmet.to_string());
                let works = match (without_closed_pattern, along_open_curve) {
                    (true, _) => "turn off 'closed pattern' and it can",
                    (false, true) => {
                        "along an open curve of the same length it can: draw an open curve, or relax the target"
                    }
                    (false, false) => "relax the target",
                };
                write!(f, "{targets} cannot be made round this loop from this exemplar; {works}")
            }
        }
    }
}

/// Why synthesis failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SolveError {
    /// No piece sequence meets the targets.
    #[error("no solution: {0}")]
    NoSolution(Unmet),
    /// The search was cancelled.
    #[error(transparent)]
    Cancelled(#[from] Cancelled),
    /// The search grew past the state limit.
    #[error(
        "the search needs more than {limit} states (about {megabytes} MB); shorten the curve, cut fewer pieces or relax the targets"
    )]
    TooManyStates {
        /// The state limit.
        limit: usize,
        /// Memory it stands for.
        megabytes: usize,
    },
    /// An option is out of range.
    #[error("invalid option: {0}")]
    InvalidOption(String),
}

impl MaybeCancelled for SolveError {
    fn is_cancelled(&self) -> bool {
        matches!(self, SolveError::Cancelled(_))
    }
}
