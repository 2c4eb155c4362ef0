//! [`InvalidSetting`]: a setting out of range, the one error every mode's
//! `Settings::validate` gives, and the checks they share.

/// A setting out of range, in words a person understands.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct InvalidSetting(pub String);

/// `Ok` when `x` is a finite number above zero; otherwise says that `what`
/// must be a positive number, followed by `unit` (" of millimetres", or
/// nothing for a ratio).
///
/// ```
/// use tracery_core::setting::positive;
/// assert!(positive("the band", 10.0, " of millimetres").is_ok());
/// let e = positive("the band", -1.0, " of millimetres").unwrap_err();
/// assert_eq!(e.to_string(), "the band must be a positive number of millimetres, not -1");
/// assert!(positive("the scale", f64::NAN, "").is_err());
/// ```
pub fn positive(what: &str, x: f64, unit: &str) -> Result<(), InvalidSetting> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(InvalidSetting(format!("{what} must be a positive number{unit}, not {x}")))
    }
}

/// [`positive`] for a length in millimetres.
pub fn positive_mm(what: &str, x: f64) -> Result<(), InvalidSetting> {
    positive(what, x, " of millimetres")
}
