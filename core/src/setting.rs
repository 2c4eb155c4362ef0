//! [`InvalidSetting`]: a setting out of range, the one error every mode's
//! `Settings::validate` gives, the ranges every mode shares, and the checks.
//!
//! Every number a person gives has a range, with its reason: a value out of
//! it is refused with a line that names the setting, the value and what
//! would work, before any work starts (and before anything is allocated
//! from it).

use std::ops::RangeInclusive;

/// The largest size or coordinate anything may have, mm: ten metres, more
/// than any printer's bed or laser's table, and small enough that sums and
/// squares of coordinates keep well under a micrometre of precision.
pub const WORLD_EXTENT_MM: f64 = 10_000.0;

/// The thickest print, mm: taller than any printer builds.
pub const MAX_THICKNESS_MM: f64 = 500.0;

/// The narrowest band, mm: half a millimetre, about a nozzle's width; a
/// pattern in a narrower one cannot print.
pub const MIN_BAND_MM: f64 = 0.5;

/// The widest band, mm: a metre, wider than any printer's bed.
pub const MAX_BAND_MM: f64 = 1_000.0;

/// The largest variety weight: at 10 already the fit hardly counts.
pub const MAX_VARIETY: f64 = 100.0;

/// A setting out of range, in words a person understands.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct InvalidSetting {
    /// The settings field, as named in the settings struct (`thickness_mm`):
    /// the command line names its flag from it.
    pub field: &'static str,
    /// What is wrong and what would work.
    pub message: String,
}

impl InvalidSetting {
    /// A refusal of `field`.
    pub fn new(field: &'static str, message: impl Into<String>) -> Self {
        InvalidSetting { field, message: message.into() }
    }
}

/// `Ok` when `x` is a finite number above zero; otherwise says that `what`
/// must be a positive number, followed by `unit` (" of millimetres", or
/// nothing for a ratio).
///
/// ```
/// use tracery_core::setting::positive;
/// assert!(positive("band_mm", "the band", 10.0, " of millimetres").is_ok());
/// let e = positive("band_mm", "the band", -1.0, " of millimetres").unwrap_err();
/// assert_eq!(e.to_string(), "the band must be a positive number of millimetres, not -1");
/// assert_eq!(e.field, "band_mm");
/// assert!(positive("scale", "the scale", f64::NAN, "").is_err());
/// ```
pub fn positive(field: &'static str, what: &str, x: f64, unit: &str) -> Result<(), InvalidSetting> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(InvalidSetting::new(field, format!("{what} must be a positive number{unit}, not {x}")))
    }
}

/// [`positive`] for a length in millimetres.
pub fn positive_mm(field: &'static str, what: &str, x: f64) -> Result<(), InvalidSetting> {
    positive(field, what, x, " of millimetres")
}

/// `Ok` when `x` lies in `range` (above its start when `open_start`);
/// otherwise says so, with `unit` after the numbers and `why` the range is
/// what it is.
///
/// ```
/// use tracery_core::setting::within;
/// assert!(within("thickness_mm", "the thickness", 2.0, 0.0..=500.0, true, " mm", "taller than a printer builds").is_ok());
/// let e = within("thickness_mm", "the thickness", 1e12, 0.0..=500.0, true, " mm", "taller than a printer builds")
///     .unwrap_err();
/// assert_eq!(
///     e.to_string(),
///     "the thickness must be at most 500 mm, not 1e12: more is taller than a printer builds"
/// );
/// let e = within("thickness_mm", "the thickness", -1.0, 0.0..=500.0, true, " mm", "").unwrap_err();
/// assert_eq!(e.to_string(), "the thickness must be above 0 mm, not -1");
/// ```
pub fn within(
    field: &'static str,
    what: &str,
    x: f64,
    range: RangeInclusive<f64>,
    open_start: bool,
    unit: &str,
    why: &str,
) -> Result<(), InvalidSetting> {
    let (low, high) = (*range.start(), *range.end());
    let above = if open_start { x > low } else { x >= low };
    if x.is_finite() && above && x <= high {
        return Ok(());
    }
    let message = if x > high {
        format!("{what} must be at most {high}{unit}, not {}: more is {why}", number(x))
    } else {
        let from = if open_start { "above" } else { "at least" };
        format!("{what} must be {from} {low}{unit}, not {}", number(x))
    };
    Err(InvalidSetting::new(field, message))
}

/// A number as a person would write it: `1e12` rather than twelve zeros.
///
/// ```
/// use tracery_core::setting::number;
/// assert_eq!(number(2.5), "2.5");
/// assert_eq!(number(1e12), "1e12");
/// assert_eq!(number(-3e-9), "-3e-9");
/// ```
pub fn number(x: f64) -> String {
    let magnitude = x.abs();
    if x.is_finite() && x != 0.0 && !(1e-4..1e7).contains(&magnitude) { format!("{x:e}") } else { format!("{x}") }
}

/// `Ok` when the point `(x, y)` lies within [`WORLD_EXTENT_MM`] of the origin on both axes.
pub fn on_the_table(field: &'static str, what: &str, point: &[f64]) -> Result<(), InvalidSetting> {
    if point.iter().all(|c| c.is_finite() && c.abs() <= WORLD_EXTENT_MM) {
        return Ok(());
    }
    let shown: Vec<String> = point.iter().map(|&c| number(c)).collect();
    Err(InvalidSetting::new(
        field,
        format!(
            "{what} ({}) must lie within {WORLD_EXTENT_MM} mm of the origin on every axis (ten metres, more than any printer's bed)",
            shown.join(", ")
        ),
    ))
}

/// The printed thickness, `thickness_mm`: above 0, at most [`MAX_THICKNESS_MM`].
pub fn thickness(x: f64) -> Result<(), InvalidSetting> {
    within("thickness_mm", "the thickness", x, 0.0..=MAX_THICKNESS_MM, true, " mm", "taller than any printer builds")
}

/// A band's width, `band_mm`: [`MIN_BAND_MM`] to [`MAX_BAND_MM`].
pub fn band(x: f64) -> Result<(), InvalidSetting> {
    within("band_mm", "the band", x, MIN_BAND_MM..=MAX_BAND_MM, false, " mm", "wider than any printer's bed")
}

/// The variety weight, `variety`: 0 to [`MAX_VARIETY`].
pub fn variety(x: f64) -> Result<(), InvalidSetting> {
    within("variety", "variety", x, 0.0..=MAX_VARIETY, false, "", "variety outweighing the fit")
}

/// A count as a person reads it: a count that saturated (`usize::MAX`,
/// from a product or a cast of something without bound) is said in words,
/// never as the integer it wrapped to.
///
/// ```
/// use tracery_core::setting::count;
/// assert_eq!(count(42), "42");
/// assert_eq!(count(usize::MAX), "too many to count");
/// ```
pub fn count(n: usize) -> String {
    if n == usize::MAX { "too many to count".into() } else { n.to_string() }
}
