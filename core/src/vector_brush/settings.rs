//! [`Settings`]: everything a person chooses for the vector brush, declared
//! once. The document stores it, the command line's flags default to it and
//! the app's controls edit it, so the app and `tracery synth` give the same
//! pattern for the same input.

use serde::{Deserialize, Serialize};

use super::{CORNER_RADIUS, SliceOptions, SlicingMode, Target};
use crate::curve::Curve;
pub use crate::setting::InvalidSetting;
use crate::setting::{MAX_BAND_MM, band, thickness, variety, within};

/// The vector brush's settings, with the one documented set of defaults
/// (`docs/vector-brush.md` lists them).
///
/// ```
/// use tracery_core::vector_brush::{Settings, Target};
/// let mut settings = Settings::default();
/// assert_eq!(settings.components, Target::Exactly(1));
/// settings.band_mm = 14.0;
/// assert!(settings.validate().is_ok());
/// settings.band_mm = -1.0;
/// assert!(settings.validate().is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[non_exhaustive]
pub struct Settings {
    /// Connected components wanted.
    pub components: Target,
    /// Holes wanted in the lace (a loop's central opening is not counted).
    pub holes: Target,
    /// On loops, ask for a pattern that runs all around (ignored on open curves).
    pub closed_pattern: bool,
    /// Height of the band across the curve, mm.
    pub band_mm: f64,
    /// Variety: weight of the autocorrelation penalty; 0 turns it off.
    pub variety: f64,
    /// Exemplar scale relative to fitting its height to the band (1: fits).
    pub scale: f64,
    /// How the exemplar is cut.
    pub slicing: SlicingMode,
    /// Cuts through features thinner than this are dropped, mm.
    pub min_portal_mm: f64,
    /// Topology events closer than this fraction of the exemplar's height are grouped.
    pub event_grouping: f64,
    /// Printed thickness, mm.
    pub thickness_mm: f64,
    /// 0 for the best pattern; any other value perturbs it at random.
    pub seed: u64,
    /// Which of the [`ALTERNATIVES`] to make: 0 is the best pattern; each
    /// next one is made to differ from all before it (see
    /// `SolveOptions::avoid`), so it costs one more search.
    pub alternative: u32,
    /// Radius of the arcs that round the curve's sharp corners, mm. Never
    /// less than [`CORNER_RADIUS`] half bands, which the band needs to turn
    /// a corner without folding its inner edge; 0 asks for that. A larger
    /// radius squeezes the pattern less on the inside of each corner, and
    /// makes the corners rounder ([`Settings::corner_radius_used_mm`]).
    pub corner_radius_mm: f64,
    /// Turns the pattern over to the other side of the curve. Unflipped, a
    /// loop's pattern faces the same way whichever way the loop was drawn:
    /// as along a loop drawn counter-clockwise, the exemplar's top edge
    /// toward the inside and its lower edge (lace's scallops) outside. An
    /// open stroke keeps the side it was drawn with: the exemplar's top on
    /// its left.
    pub flip: bool,
}

/// The smallest exemplar scale: at a twentieth of the band the pieces are
/// specks, and the curve would need millions of them.
pub const MIN_SCALE: f64 = 0.05;

/// The largest exemplar scale (relative to fitting its height to the band).
pub const MAX_SCALE: f64 = 10.0;

/// The most cut lines uniform slicing takes: more cuts pieces thinner than
/// a nozzle from any exemplar.
pub const MAX_UNIFORM_CUTS: usize = 256;

/// How many alternatives the gallery offers (the best one included).
pub const ALTERNATIVES: u32 = 6;

impl Default for Settings {
    fn default() -> Self {
        Settings {
            components: Target::Exactly(1),
            holes: Target::Any,
            closed_pattern: true,
            band_mm: 10.0,
            variety: 0.8,
            scale: 1.0,
            slicing: SlicingMode::Topology,
            min_portal_mm: 0.0,
            event_grouping: SliceOptions::default().event_grouping,
            thickness_mm: 2.0,
            seed: 0,
            alternative: 0,
            corner_radius_mm: 0.0,
            flip: false,
        }
    }
}

impl Settings {
    /// Checks every number is in range.
    pub fn validate(&self) -> Result<(), InvalidSetting> {
        band(self.band_mm)?;
        within(
            "scale",
            "the scale",
            self.scale,
            MIN_SCALE..=MAX_SCALE,
            false,
            "",
            "an exemplar many bands tall, cut to one band",
        )?;
        thickness(self.thickness_mm)?;
        variety(self.variety)?;
        within(
            "min_portal_mm",
            "the minimum portal",
            self.min_portal_mm,
            0.0..=self.band_mm.max(0.0),
            false,
            " mm (the band)",
            "wider than the band, which would drop every cut",
        )?;
        within(
            "event_grouping",
            "event grouping",
            self.event_grouping,
            0.0..=1.0,
            false,
            "",
            "grouping across the band",
        )?;
        within(
            "corner_radius_mm",
            "the corner radius",
            self.corner_radius_mm,
            0.0..=MAX_BAND_MM,
            false,
            " mm",
            "wider than any printer's bed",
        )?;
        if self.components == Target::Exactly(0) {
            return Err(InvalidSetting::new("components", "a pattern has at least 1 component, not 0"));
        }
        if let SlicingMode::Uniform { cuts } = self.slicing
            && !(1..=MAX_UNIFORM_CUTS).contains(&cuts)
        {
            return Err(InvalidSetting::new(
                "slicing",
                format!("uniform slicing takes 1 to {MAX_UNIFORM_CUTS} cut lines, not {cuts}"),
            ));
        }
        if self.alternative >= ALTERNATIVES {
            return Err(InvalidSetting::new(
                "alternative",
                format!("the alternative must be between 0 and {}, not {}", ALTERNATIVES - 1, self.alternative),
            ));
        }
        Ok(())
    }

    /// The radius the curve's sharp corners are rounded with, mm: the one
    /// asked for, or the least the band needs where that is less.
    ///
    /// ```
    /// use tracery_core::vector_brush::Settings;
    /// let mut settings = Settings::default();
    /// // A 10 mm band needs arcs of 6.25 mm at least.
    /// assert_eq!(settings.corner_radius_used_mm(), 6.25);
    /// settings.corner_radius_mm = 12.0;
    /// assert_eq!(settings.corner_radius_used_mm(), 12.0);
    /// ```
    pub fn corner_radius_used_mm(&self) -> f64 {
        self.corner_radius_mm.max(self.corner_radius_least_mm())
    }

    /// `curve` run the way the pattern is laid along it: a loop
    /// counter-clockwise, an open stroke as drawn, and either the other
    /// way when [`Settings::flip`] is set.
    ///
    /// ```
    /// use tracery_core::curve::Curve;
    /// use tracery_core::vector_brush::Settings;
    /// let mut settings = Settings::default();
    /// let clockwise = Curve::circle(20.0).unwrap().reversed();
    /// assert!(settings.oriented(&clockwise).signed_area() > 0.0);
    /// settings.flip = true;
    /// assert!(settings.oriented(&clockwise).signed_area() < 0.0);
    /// ```
    pub fn oriented(&self, curve: &Curve) -> Curve {
        let reverse = if curve.is_closed() { (curve.signed_area() < 0.0) != self.flip } else { self.flip };
        if reverse { curve.reversed() } else { curve.clone() }
    }

    /// The least radius the band needs to turn a sharp corner without
    /// folding its inner edge, mm: [`CORNER_RADIUS`] half bands.
    pub fn corner_radius_least_mm(&self) -> f64 {
        CORNER_RADIUS * 0.5 * self.band_mm
    }

    /// Millimetres per exemplar unit for an exemplar `exemplar_height` units tall.
    pub fn mm_per_unit(&self, exemplar_height: f64) -> f64 {
        self.scale * self.band_mm / exemplar_height.max(f64::MIN_POSITIVE)
    }
}
