//! [`Settings`]: everything a person chooses for region fill, declared once
//! for the document, the command line and the app.

pub use crate::setting::InvalidSetting;
use crate::setting::{MAX_BAND_MM, thickness, within};
use serde::{Deserialize, Serialize};

/// Region fill's settings, with the one set of defaults
/// (`docs/region-fill.md` explains them).
///
/// ```
/// use tracery_core::region_fill::Settings;
/// let mut settings = Settings::default();
/// assert!(settings.validate().is_ok());
/// settings.stroke_width_mm = -1.0;
/// assert!(settings.validate().is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[non_exhaustive]
pub struct Settings {
    /// Sample spacing at the finest level (the paper's δ), mm; the two
    /// coarser levels double it twice.
    pub delta_mm: f64,
    /// Neighbourhood radius in spacings (the paper's r / δ). Not a whole
    /// number, so that samples evenly spaced along a path do not sit right
    /// on the rim, in one neighbourhood and out of its twin by a rounding.
    pub radius_spacings: f64,
    /// Search and assignment steps at each level.
    pub iterations: usize,
    /// The exemplar is drawn this many times larger (below 1, smaller)
    /// before the fill learns from it: an imported drawing in arbitrary
    /// units is brought to the size its pattern should have.
    pub exemplar_scale: f64,
    /// Which random choices the synthesis makes: another seed, another fill.
    pub seed: u64,
    /// Width of the pen the paths are drawn with, mm: the strokes' width in
    /// the SVG and in the printed solid.
    pub stroke_width_mm: f64,
    /// Width of a frame along the region's edge, inside it, mm; 0 for none.
    pub frame_mm: f64,
    /// Thickness of the printed solid, mm.
    pub thickness_mm: f64,
    /// Join every piece of the print to the rest with short bridges, so it
    /// prints as one object.
    pub one_piece: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            delta_mm: 1.5,
            radius_spacings: 3.1,
            iterations: 7,
            exemplar_scale: 1.0,
            seed: 1,
            stroke_width_mm: 0.8,
            frame_mm: 0.0,
            thickness_mm: 1.5,
            one_piece: false,
        }
    }
}

/// The finest sample spacing allowed, mm: finer would only multiply the
/// samples of a pattern no printer or pen could show.
pub const MIN_DELTA_MM: f64 = 0.2;

/// The widest stroke and frame, mm: wider than a hand.
pub const MAX_STROKE_WIDTH_MM: f64 = 100.0;

/// The smallest exemplar scale: a drawing in points shrunk to a hundredth.
pub const MIN_EXEMPLAR_SCALE: f64 = 0.01;

/// The largest exemplar scale.
pub const MAX_EXEMPLAR_SCALE: f64 = 100.0;

/// The most steps at one level: the paper's 7 settle a fill; far more only waste time.
pub const MAX_ITERATIONS: usize = 50;

impl Settings {
    /// Checks every number is in range.
    pub fn validate(&self) -> Result<(), InvalidSetting> {
        within(
            "delta_mm",
            "the sample spacing",
            self.delta_mm,
            MIN_DELTA_MM..=MAX_BAND_MM,
            false,
            " mm",
            "wider than any printer's bed",
        )?;
        within(
            "stroke_width_mm",
            "the stroke width",
            self.stroke_width_mm,
            0.0..=MAX_STROKE_WIDTH_MM,
            true,
            " mm",
            "a stroke wider than a hand",
        )?;
        thickness(self.thickness_mm)?;
        within(
            "frame_mm",
            "the frame",
            self.frame_mm,
            0.0..=MAX_STROKE_WIDTH_MM,
            false,
            " mm",
            "a frame wider than a hand",
        )?;
        within(
            "radius_spacings",
            "the neighbourhood radius",
            self.radius_spacings,
            1.5..=8.0,
            false,
            " spacings",
            "a neighbourhood too wide to match",
        )?;
        within(
            "exemplar_scale",
            "the exemplar scale",
            self.exemplar_scale,
            MIN_EXEMPLAR_SCALE..=MAX_EXEMPLAR_SCALE,
            false,
            "",
            "an exemplar far larger than any region",
        )?;
        if !(1..=MAX_ITERATIONS).contains(&self.iterations) {
            return Err(InvalidSetting::new(
                "iterations",
                format!("the steps per level must be between 1 and {MAX_ITERATIONS}, not {}", self.iterations),
            ));
        }
        Ok(())
    }

    /// The neighbourhood radius at the finest level, mm.
    pub fn radius_mm(&self) -> f64 {
        self.radius_spacings * self.delta_mm
    }
}
