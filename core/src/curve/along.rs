//! Where a pattern goes, as the command line's `--along` says it: a curve
//! (`line:`, `circle:`, `wave:`, the frames `square:` (side), `hexagon:` and
//! `star:` (radius), `svg:`) or a rectangle (`rect:WxH`).

use std::path::{Path, PathBuf};

use super::{Curve, CurveError, first_path_points};
use crate::setting::WORLD_EXTENT_MM;

/// Distance under which an SVG path's last point closes it onto its first, mm.
pub const SVG_CLOSE_TOLERANCE: f64 = 1e-6;

/// Spacing of the samples of a curve taken from an SVG path, mm: as fine as
/// a drawn stroke's.
pub const SVG_SPACING_MM: f64 = 0.5;

/// Where a pattern goes.
#[derive(Clone, Debug, PartialEq)]
pub enum Along {
    /// Along a curve, in millimetres.
    Curve(Curve),
    /// Filling a rectangle, centred on `x = 0`, from `y = 0` up.
    Rectangle {
        /// Width, mm.
        width_mm: f64,
        /// Height, mm.
        height_mm: f64,
    },
}

/// Why an `--along` specification could not be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum AlongError {
    /// Not `KIND:VALUE`.
    #[error(
        "curve '{0}' must look like KIND:VALUE (line:120, circle:25, wave:120, square:60, hexagon:30, star:40, heart:60, rect:80x50 or svg:FILE.svg)"
    )]
    Form(String),
    /// An unknown kind.
    #[error("unknown curve kind '{0}': use line, circle, wave, square, hexagon, star, heart, rect or svg")]
    Kind(String),
    /// A size that is not a positive number of millimetres up to [`WORLD_EXTENT_MM`].
    #[error("{what} must be a positive number of millimetres up to {WORLD_EXTENT_MM} (ten metres), not '{text}'")]
    Size {
        /// Which size.
        what: &'static str,
        /// What was given.
        text: String,
    },
    /// An SVG path reaching farther than [`WORLD_EXTENT_MM`] from the origin.
    #[error(
        "in {path}: the path reaches {reach_mm:e} mm from the origin, more than {WORLD_EXTENT_MM} mm (ten metres): check the file's units"
    )]
    TooFar {
        /// The file.
        path: PathBuf,
        /// How far it reaches, mm.
        reach_mm: f64,
    },
    /// A rectangle not given as `WxH`.
    #[error("rectangle '{0}' must be WxH, in millimetres")]
    Rectangle(String),
    /// The SVG file could not be read.
    #[error("could not read {path}: {message}")]
    Io {
        /// The file.
        path: PathBuf,
        /// What the system said.
        message: String,
    },
    /// The curve could not be built.
    #[error("{context}{source}")]
    Curve {
        /// Where it came from, if from a file.
        context: String,
        /// Why.
        source: CurveError,
    },
}

impl From<CurveError> for AlongError {
    fn from(source: CurveError) -> Self {
        AlongError::Curve { context: String::new(), source }
    }
}

fn positive(what: &'static str, text: &str) -> Result<f64, AlongError> {
    match text.trim().parse::<f64>() {
        Ok(value) if value.is_finite() && value > 0.0 && value <= WORLD_EXTENT_MM => Ok(value),
        _ => Err(AlongError::Size { what, text: text.to_string() }),
    }
}

impl Along {
    /// Reads a specification.
    ///
    /// ```
    /// use tracery_core::curve::Along;
    /// let Along::Curve(circle) = Along::parse("circle:25").unwrap() else { panic!() };
    /// assert!(circle.is_closed());
    /// assert!(matches!(Along::parse("rect:80x50"), Ok(Along::Rectangle { .. })));
    /// assert!(Along::parse("line:-5").is_err());
    /// ```
    pub fn parse(spec: &str) -> Result<Along, AlongError> {
        let (kind, value) = spec.split_once(':').ok_or_else(|| AlongError::Form(spec.to_string()))?;
        let curve = match kind {
            "line" => Curve::line(positive("the line length", value)?)?,
            "circle" => Curve::circle(positive("the circle radius", value)?)?,
            "wave" => Curve::wave(positive("the wave length", value)?)?,
            "square" => {
                Curve::regular_polygon(4, positive("the square's side", value)? * std::f64::consts::FRAC_1_SQRT_2)?
            }
            "hexagon" => Curve::regular_polygon(6, positive("the hexagon's radius", value)?)?,
            "star" => Curve::star(5, positive("the star's radius", value)?)?,
            "heart" => Curve::heart(positive("the heart's width", value)?)?,
            "rect" => {
                let (w, h) = value.split_once(['x', 'X']).ok_or_else(|| AlongError::Rectangle(value.to_string()))?;
                return Ok(Along::Rectangle {
                    width_mm: positive("the rectangle width", w)?,
                    height_mm: positive("the rectangle height", h)?,
                });
            }
            "svg" => Along::curve_from_svg(Path::new(value))?,
            _ => return Err(AlongError::Kind(kind.to_string())),
        };
        Ok(Along::Curve(curve))
    }

    /// The first path of an SVG file, flattened, as a curve in millimetres
    /// (the file's own size where it gives one in mm, cm, in, pt or pc; one
    /// user unit a millimetre otherwise), resampled every
    /// [`SVG_SPACING_MM`] so that a path of a few long segments gets
    /// tangents along them, not only at its corners, and with its corners
    /// kept where they are drawn.
    pub fn curve_from_svg(path: &Path) -> Result<Curve, AlongError> {
        let data =
            std::fs::read(path).map_err(|e| AlongError::Io { path: path.to_path_buf(), message: e.to_string() })?;
        let context = format!("in {}: ", path.display());
        let points =
            first_path_points(&data).map_err(|source| AlongError::Curve { context: context.clone(), source })?;
        // Checked before resampling, which allocates by the path's length.
        let reach_mm = points.iter().map(|p| p.x.abs().max(p.y.abs())).fold(0.0, f64::max);
        if reach_mm.is_nan() || reach_mm > WORLD_EXTENT_MM {
            return Err(AlongError::TooFar { path: path.to_path_buf(), reach_mm });
        }
        let closed = points.len() > 2
            && points.first().zip(points.last()).is_some_and(|(a, b)| a.distance(*b) < SVG_CLOSE_TOLERANCE);
        let curve = Curve::from_polyline(&points, closed).map_err(|source| AlongError::Curve { context, source })?;
        Ok(curve.resampled_keeping_corners(SVG_SPACING_MM))
    }

    /// The length the pattern runs along, mm (a rectangle's width).
    pub fn length_mm(&self) -> f64 {
        match self {
            Along::Curve(curve) => curve.length(),
            Along::Rectangle { width_mm, .. } => *width_mm,
        }
    }
}
