//! [`Shade`]: a cylinder or a cone of revolution, the surface a lamp shade
//! is wrapped onto, and its maps from sheet coordinates to 3D and to the
//! flat development.

use glam::{DVec2, DVec3};
use serde::{Deserialize, Serialize};

/// Radii closer than this, relative to the larger, make a cylinder: the
/// apex of such a cone is so far away that its development is a rectangle
/// to within a micrometre on any shade a printer can make.
const CYLINDER_RELATIVE_TOLERANCE: f64 = 1e-9;

/// Why a shade's shape cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ShadeError {
    /// Not the numbers the flag needs.
    #[error("{flag} must be {form}, in millimetres, not '{text}'")]
    Form {
        /// The flag.
        flag: &'static str,
        /// What it should look like.
        form: &'static str,
        /// What was given.
        text: String,
    },
    /// A size that is not positive.
    #[error("the shade's {what} must be a positive number of millimetres, not {value}")]
    Size {
        /// Which size.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// Larger than a printer or a person could use.
    #[error("the shade's {what} of {value} mm is over the {limit} mm this program makes")]
    TooLarge {
        /// Which size.
        what: &'static str,
        /// The value given.
        value: f64,
        /// The most allowed.
        limit: f64,
    },
    /// Rows cannot overlap by their own height or more.
    #[error("rows {band_mm} mm high cannot overlap by {overlap_mm} mm: make the band wider or the overlap smaller")]
    Overlap {
        /// The overlap asked for.
        overlap_mm: f64,
        /// The rows' height.
        band_mm: f64,
    },
    /// The rims leave no room for the pattern.
    #[error(
        "rims of {rim_mm} mm at the top and the bottom leave no room for a pattern on a shade {slant_mm:.1} mm high"
    )]
    RimsFill {
        /// The rims' height.
        rim_mm: f64,
        /// The shade's height along its surface.
        slant_mm: f64,
    },
}

/// Largest radius or height of a shade, mm: a metre covers every lamp a
/// person prints or cuts, and keeps meshes within memory.
pub const MAX_SHADE_MM: f64 = 1000.0;

/// A surface of revolution about the `z` axis, from `z = 0` up: a cylinder
/// when both radii are equal, else a cone (cut off before its apex).
///
/// Points on it are given in *sheet* coordinates: the angle `theta` about
/// the axis (counter-clockwise seen from above, so to the right seen from
/// outside) and `slant_mm`, the distance up the surface from the bottom rim.
///
/// ```
/// use tracery_core::surface::Shade;
/// let cone = Shade::cone(60.0, 40.0, 100.0).unwrap();
/// let top = cone.point(0.0, cone.slant_height_mm());
/// assert!((top.x - 40.0).abs() < 1e-9 && (top.z - 100.0).abs() < 1e-9);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shade {
    /// Radius at the bottom, mm.
    pub bottom_radius_mm: f64,
    /// Radius at the top, mm.
    pub top_radius_mm: f64,
    /// Height along the axis, mm.
    pub height_mm: f64,
}

impl Default for Shade {
    fn default() -> Self {
        Shade { bottom_radius_mm: 50.0, top_radius_mm: 50.0, height_mm: 80.0 }
    }
}

fn checked(what: &'static str, value: f64) -> Result<f64, ShadeError> {
    if !(value.is_finite() && value > 0.0) {
        return Err(ShadeError::Size { what, value });
    }
    if value > MAX_SHADE_MM {
        return Err(ShadeError::TooLarge { what, value, limit: MAX_SHADE_MM });
    }
    Ok(value)
}

fn numbers(flag: &'static str, form: &'static str, text: &str, count: usize) -> Result<Vec<f64>, ShadeError> {
    let bad = || ShadeError::Form { flag, form, text: text.to_string() };
    let values: Vec<f64> =
        text.split(',').map(|t| t.trim().parse::<f64>().map_err(|_| bad())).collect::<Result<_, _>>()?;
    if values.len() != count {
        return Err(bad());
    }
    Ok(values)
}

impl Shade {
    /// A cylinder of `radius_mm` and `height_mm`.
    pub fn cylinder(radius_mm: f64, height_mm: f64) -> Result<Shade, ShadeError> {
        Shade::cone(radius_mm, radius_mm, height_mm)
    }

    /// A cone from `bottom_radius_mm` at `z = 0` to `top_radius_mm` at `height_mm`.
    pub fn cone(bottom_radius_mm: f64, top_radius_mm: f64, height_mm: f64) -> Result<Shade, ShadeError> {
        Ok(Shade {
            bottom_radius_mm: checked("bottom radius", bottom_radius_mm)?,
            top_radius_mm: checked("top radius", top_radius_mm)?,
            height_mm: checked("height", height_mm)?,
        })
    }

    /// A cylinder from `R,H` (the command line's `--cylinder`).
    pub fn parse_cylinder(text: &str) -> Result<Shade, ShadeError> {
        let v = numbers("--cylinder", "R,H", text, 2)?;
        Shade::cylinder(v[0], v[1])
    }

    /// A cone from `R1,R2,H` (the command line's `--cone`).
    pub fn parse_cone(text: &str) -> Result<Shade, ShadeError> {
        let v = numbers("--cone", "R1,R2,H", text, 3)?;
        Shade::cone(v[0], v[1], v[2])
    }

    /// Checks the numbers, as [`Shade::cone`] does.
    pub fn validate(&self) -> Result<(), ShadeError> {
        Shade::cone(self.bottom_radius_mm, self.top_radius_mm, self.height_mm).map(|_| ())
    }

    /// Length of the surface from the bottom rim to the top rim, mm.
    pub fn slant_height_mm(&self) -> f64 {
        self.height_mm.hypot(self.bottom_radius_mm - self.top_radius_mm)
    }

    /// Radius `slant_mm` up the surface, mm.
    pub fn radius_at(&self, slant_mm: f64) -> f64 {
        let t = slant_mm / self.slant_height_mm();
        self.bottom_radius_mm + (self.top_radius_mm - self.bottom_radius_mm) * t
    }

    /// Whether the radii are equal (see [`CYLINDER_RELATIVE_TOLERANCE`]).
    pub fn is_cylinder(&self) -> bool {
        let larger = self.bottom_radius_mm.max(self.top_radius_mm);
        (self.bottom_radius_mm - self.top_radius_mm).abs() <= CYLINDER_RELATIVE_TOLERANCE * larger
    }

    /// The point at angle `theta` and `slant_mm` up the surface, mm.
    pub fn point(&self, theta: f64, slant_mm: f64) -> DVec3 {
        let t = slant_mm / self.slant_height_mm();
        let r = self.radius_at(slant_mm);
        DVec3::new(r * theta.cos(), r * theta.sin(), self.height_mm * t)
    }

    /// The unit normal pointing away from the axis at angle `theta`.
    pub fn outward_normal(&self, theta: f64) -> DVec3 {
        let s = self.slant_height_mm();
        let across = self.height_mm / s;
        let up = (self.bottom_radius_mm - self.top_radius_mm) / s;
        DVec3::new(across * theta.cos(), across * theta.sin(), up)
    }

    /// The development: where the point at `theta` (0 to 2π) and `slant_mm`
    /// lies when the surface is cut along `theta = 0` and laid flat without
    /// stretching, mm. A cylinder unrolls into a rectangle from `x = 0`; a
    /// cone into an annular sector, centred on `x = 0` with the middle of
    /// its bottom edge at the origin. Either way `y` grows up the surface.
    ///
    /// ```
    /// use tracery_core::surface::Shade;
    /// let cylinder = Shade::cylinder(10.0, 50.0).unwrap();
    /// let p = cylinder.developed(std::f64::consts::PI, 20.0);
    /// assert!((p.x - 10.0 * std::f64::consts::PI).abs() < 1e-9 && (p.y - 20.0).abs() < 1e-9);
    /// ```
    pub fn developed(&self, theta: f64, slant_mm: f64) -> DVec2 {
        if self.is_cylinder() {
            return DVec2::new(self.bottom_radius_mm * theta, slant_mm);
        }
        let s = self.slant_height_mm();
        // Sine of the half-angle at the apex: radius per mm of slant.
        let sin_half = (self.bottom_radius_mm - self.top_radius_mm).abs() / s;
        let apex_to_bottom = self.bottom_radius_mm / sin_half;
        let narrows_upward = self.bottom_radius_mm > self.top_radius_mm;
        let d = if narrows_upward { apex_to_bottom - slant_mm } else { apex_to_bottom + slant_mm };
        // Arc length is kept: radius(slant) · theta = d · psi.
        let psi = (theta - std::f64::consts::PI) * sin_half;
        match narrows_upward {
            true => DVec2::new(d * psi.sin(), apex_to_bottom - d * psi.cos()),
            false => DVec2::new(d * psi.sin(), d * psi.cos() - apex_to_bottom),
        }
    }
}
