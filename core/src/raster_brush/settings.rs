//! [`Settings`]: everything a person chooses for the raster brush, declared
//! once for the document, the command line and the app.

pub use crate::setting::InvalidSetting;
use crate::setting::{MAX_BAND_MM, band, thickness, variety, within};
use serde::{Deserialize, Serialize};

/// The raster brush's settings, with the one set of defaults
/// (`docs/raster-brush.md` explains them).
///
/// ```
/// use tracery_core::raster_brush::Settings;
/// let mut settings = Settings::default();
/// assert!(settings.validate().is_ok());
/// settings.step_mm = 0.0;
/// assert!(settings.validate().is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[non_exhaustive]
pub struct Settings {
    /// Width of the ribbon across the curve (the paper's b), mm.
    pub band_mm: f64,
    /// Length of a piece along the curve (the paper's δ), mm.
    pub step_mm: f64,
    /// The pattern's height (its opaque rows) as a fraction of the band
    /// (the paper's s); what is left lets the pattern wander across the band.
    pub scale: f64,
    /// Deform the pieces so that their seams meet (the paper's stitching).
    pub stitching: bool,
    /// Printed thickness of the traced outline, mm.
    pub thickness_mm: f64,
    /// Variety: how much a random cost per piece and position (up to
    /// `variety` × [`VARIETY_COST`]) moves the search off its single best
    /// answer, so that where the pattern jumps in the exemplar changes
    /// along the curve; 0 turns it off.
    pub variety: f64,
    /// Which random costs variety draws: another seed, another pattern.
    pub seed: u64,
}

/// The random cost per piece at variety 1: half a jump, so that variety
/// alone never breaks a continuation but decides between near ties.
pub const VARIETY_COST: f64 = 0.5 * super::JUMP_COST;

impl Default for Settings {
    fn default() -> Self {
        Settings { band_mm: 10.0, step_mm: 2.0, scale: 0.75, stitching: true, thickness_mm: 2.0, variety: 0.5, seed: 0 }
    }
}

/// The largest scale: above it the band is narrower than the pattern, and
/// no piece could slice it without cutting through it.
pub const MAX_SCALE: f64 = 1.0;

/// The smallest scale: a pattern a twentieth of its band is a speck.
pub const MIN_SCALE: f64 = 0.05;

/// The shortest piece along the curve, mm: a tenth of a millimetre, finer
/// than any nozzle or laser spot, and a floor under the pieces' count (a
/// 10 m curve makes 100,000 at most).
pub const MIN_STEP_MM: f64 = 0.1;

impl Settings {
    /// Checks every number is in range.
    pub fn validate(&self) -> Result<(), InvalidSetting> {
        band(self.band_mm)?;
        within(
            "step_mm",
            "the step",
            self.step_mm,
            MIN_STEP_MM..=MAX_BAND_MM,
            false,
            " mm",
            "wider than any printer's bed",
        )?;
        thickness(self.thickness_mm)?;
        variety(self.variety)?;
        within(
            "scale",
            "the scale (the pattern's height as a fraction of the band)",
            self.scale,
            MIN_SCALE..=MAX_SCALE,
            false,
            "",
            "a pattern taller than its band",
        )?;
        Ok(())
    }
}
