//! [`Settings`]: everything a person chooses for mesh quilting, declared
//! once for the document, the command line and the app.

use serde::{Deserialize, Serialize};

use crate::setting::{InvalidSetting, positive, within};

/// Mesh quilting's settings, with the one set of defaults
/// (`docs/mesh-quilting.md` explains them).
///
/// ```
/// use tracery_core::mesh_quilt::Settings;
/// let mut settings = Settings::default();
/// assert!(settings.validate().is_ok());
/// settings.scale = 0.0;
/// assert!(settings.validate().is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[non_exhaustive]
pub struct Settings {
    /// The swatch is made this many times larger (the paper's `s`).
    pub scale: f64,
    /// Grid cells across the swatch's shorter side: the step of the
    /// translations tried when matching, and of the growing front.
    pub cells_across: usize,
    /// Weight of distance against normal difference in the matching cost
    /// (the paper's λ, per grid cell).
    pub lambda: f64,
    /// Weight of the position constraints against keeping the shape when
    /// elements are deformed to meet (the paper's μ).
    pub mu: f64,
    /// Placements whose cost is within this fraction of the best are
    /// equally good; one is picked at random, for variety.
    pub tolerance: f64,
    /// Which random choices the synthesis makes: another seed, another quilt.
    pub seed: u64,
    /// How deep the texture sits in a curved base, mm: the shell's bottom
    /// lies this far inside the model, so that elements resting on it
    /// overlap it and unite with it into one solid, rather than touching
    /// it along a face (which prints as two bodies, or not at all).
    pub sink_mm: f64,
    /// Which way the swatch's `u` axis runs over a model.
    pub direction: Direction,
}

/// Which way the swatch's `u` axis runs over a model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum Direction {
    /// Around the `z` axis, as rings round a vase.
    #[default]
    AroundAxis,
    /// Up the model, from its foot towards its top.
    AlongAxis,
    /// Along strokes drawn on the model (the app's curves on the model, or
    /// `tracery quilt --field`), interpolated between them
    /// ([`super::GuidanceField::from_strokes`]).
    AlongCurves,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            scale: 1.0,
            cells_across: 12,
            lambda: 1.0,
            mu: 1.0,
            tolerance: 0.1,
            seed: 1,
            sink_mm: 0.3,
            direction: Direction::AroundAxis,
        }
    }
}

/// The fewest grid cells across a swatch: fewer leaves no room for an
/// overlap between patches.
pub const MIN_CELLS_ACROSS: usize = 6;

/// The deepest the texture may sit in a model, mm: deeper hides the
/// elements' feet and can reach through a thin wall.
pub const MAX_SINK_MM: f64 = 3.0;

/// The smallest swatch scale.
pub const MIN_SCALE: f64 = 0.01;

/// The largest swatch scale: a 40 mm swatch four metres across.
pub const MAX_SCALE: f64 = 100.0;

/// The most grid cells across a swatch.
pub const MAX_CELLS_ACROSS: usize = 64;

impl Settings {
    /// Checks every number is in range.
    pub fn validate(&self) -> Result<(), InvalidSetting> {
        within(
            "scale",
            "the scale",
            self.scale,
            MIN_SCALE..=MAX_SCALE,
            false,
            "",
            "a swatch larger than any printer's bed",
        )?;
        if !(MIN_CELLS_ACROSS..=MAX_CELLS_ACROSS).contains(&self.cells_across) {
            return Err(InvalidSetting::new(
                "cells_across",
                format!(
                    "cells across the swatch must be {MIN_CELLS_ACROSS} to {MAX_CELLS_ACROSS}, not {}",
                    self.cells_across
                ),
            ));
        }
        positive("lambda", "lambda", self.lambda, "")?;
        positive("mu", "mu", self.mu, "")?;
        within("tolerance", "the tolerance", self.tolerance, 0.0..=1.0, false, "", "more than a whole cell")?;
        within("sink_mm", "the sink", self.sink_mm, 0.0..=MAX_SINK_MM, false, " mm", "deeper than the elements stand")?;
        Ok(())
    }
}
