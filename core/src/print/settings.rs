//! [`PrintSettings`]: the printer a document is made for.

use serde::{Deserialize, Serialize};

/// The printer a document is made for, shared by every mode whose product
/// is planar or printable.
///
/// ```
/// use tracery_core::print::PrintSettings;
/// let s = PrintSettings::default();
/// assert_eq!(s.min_width_mm(), 0.4);
/// assert!(s.validate().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[non_exhaustive]
pub struct PrintSettings {
    /// Nozzle diameter, mm: the narrowest wall it lays down, and so the
    /// thinnest feature and the narrowest gap it prints.
    pub nozzle_mm: f64,
    /// Layer height, mm.
    pub layer_height_mm: f64,
    /// Thicken features thinner than the nozzle to its width.
    pub thicken: bool,
    /// A bridge between pieces (a portal) narrower than this many nozzle
    /// widths is flagged as weak.
    pub bridge_nozzles: f64,
}

impl Default for PrintSettings {
    fn default() -> Self {
        PrintSettings { nozzle_mm: 0.4, layer_height_mm: 0.2, thicken: false, bridge_nozzles: 1.5 }
    }
}

/// A print setting out of range.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PrintSettingsError {
    /// The nozzle is not between 0.05 and 3 mm.
    #[error("the nozzle diameter must be between 0.05 and 3 mm, not {0}")]
    Nozzle(f64),
    /// The layer height is not between 0.01 mm and the nozzle.
    #[error("the layer height must be between 0.01 mm and the nozzle diameter, not {0}")]
    LayerHeight(f64),
    /// The bridge factor is negative or absurd.
    #[error("the weak-bridge limit must be between 0 and 20 nozzle widths, not {0}")]
    Bridge(f64),
}

impl PrintSettings {
    /// The thinnest feature and the narrowest gap that print, mm.
    pub fn min_width_mm(&self) -> f64 {
        self.nozzle_mm
    }

    /// Bridges narrower than this are weak, mm.
    pub fn min_bridge_mm(&self) -> f64 {
        self.bridge_nozzles * self.nozzle_mm
    }

    /// With a nozzle of `nozzle_mm`.
    pub fn with_nozzle_mm(self, nozzle_mm: f64) -> Self {
        PrintSettings { nozzle_mm, ..self }
    }

    /// With thin features thickened or not.
    pub fn with_thicken(self, thicken: bool) -> Self {
        PrintSettings { thicken, ..self }
    }

    /// Checks every value is in range.
    pub fn validate(&self) -> Result<(), PrintSettingsError> {
        if !(0.05..=3.0).contains(&self.nozzle_mm) {
            return Err(PrintSettingsError::Nozzle(self.nozzle_mm));
        }
        if !(self.layer_height_mm >= 0.01 && self.layer_height_mm <= self.nozzle_mm) {
            return Err(PrintSettingsError::LayerHeight(self.layer_height_mm));
        }
        if !(0.0..=20.0).contains(&self.bridge_nozzles) {
            return Err(PrintSettingsError::Bridge(self.bridge_nozzles));
        }
        Ok(())
    }
}
