//! A curve drawn on a base model, from the points a person picked to the
//! smooth frames a band is laid along: snap, chart, trace, frame, and the
//! band narrowed where the curve turns too tightly for it.

use serde::{Deserialize, Serialize};

use super::{Chart, ChartError, Frames, SurfaceCurve, SurfaceMesh, TraceError, trace};
use crate::report::{Timings, Warning};
use crate::setting::{InvalidSetting, MAX_BAND_MM, on_the_table, within};

/// How a curve is drawn on a surface: one settings struct for the command
/// line and the app.
///
/// ```
/// use tracery_core::surface::SurfaceSettings;
/// let mut s = SurfaceSettings::default();
/// s.points_mm = SurfaceSettings::parse_points("0,30,20; 30,0,20").unwrap();
/// assert_eq!(s.points_mm.len(), 2);
/// assert!(s.validate().is_ok());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[non_exhaustive]
pub struct SurfaceSettings {
    /// The picked points, mm, in order; snapped onto the surface.
    pub points_mm: Vec<[f64; 3]>,
    /// Whether the curve closes back to the first point (a ring around a vase).
    pub closed: bool,
    /// Turns the band about the curve, degrees (0: lying on the surface).
    pub twist_deg: f64,
    /// Longest step of the traced curve between mesh edges, mm.
    pub step_mm: f64,
    /// What is made: the pattern alone, united with the model, or cut out
    /// of a shell of it.
    pub output: SurfaceOutput,
    /// The wall of the shell a pattern is carved out of, mm.
    pub wall_mm: f64,
}

/// What a pattern on a surface is made into.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum SurfaceOutput {
    /// The pattern alone: a shell lying on the surface.
    #[default]
    Pattern,
    /// The pattern united with the model into one solid, standing out of it.
    Emboss,
    /// The pattern cut out of the model hollowed to a shell of
    /// [`SurfaceSettings::wall_mm`]: openings where the pattern is.
    Carve,
}

/// How deep an embossed band's underside sinks into the model, mm: the
/// two solids then overlap instead of touching face to face, so that the
/// union is sure to weld them into one body. A carved band reaches this
/// far past both sides of the shell, so the cut goes clean through.
pub const EMBOSS_SINK_MM: f64 = 0.3;

impl Default for SurfaceSettings {
    fn default() -> Self {
        SurfaceSettings {
            points_mm: Vec::new(),
            closed: false,
            twist_deg: 0.0,
            step_mm: 0.5,
            output: SurfaceOutput::Pattern,
            wall_mm: 2.0,
        }
    }
}

impl SurfaceOutput {
    /// What a curve's band is made into when its object also holds the
    /// model (see [`object_holds_model`]): a pattern lying on the model is
    /// embossed, sunk [`EMBOSS_SINK_MM`] into it. Laid exactly on the
    /// surface, its underside would touch the model face to face and
    /// along edges, and the union of the two can come out pinched (two
    /// corners at one place), which the next union refuses and a slicer
    /// reads as edges shared by four faces.
    ///
    /// ```
    /// use tracery_core::surface::SurfaceOutput;
    /// assert_eq!(SurfaceOutput::Pattern.in_object(true), SurfaceOutput::Emboss);
    /// assert_eq!(SurfaceOutput::Pattern.in_object(false), SurfaceOutput::Pattern);
    /// assert_eq!(SurfaceOutput::Carve.in_object(true), SurfaceOutput::Carve);
    /// ```
    pub fn in_object(self, holds_model: bool) -> SurfaceOutput {
        match self {
            SurfaceOutput::Pattern if holds_model => SurfaceOutput::Emboss,
            other => other,
        }
    }
}

/// Whether an object made of curves with these `outputs` holds the model:
/// when it is asked for (`with_model`: a texture or a shade's foot), or
/// when any curve is embossed or carved.
///
/// ```
/// use tracery_core::surface::{SurfaceOutput, object_holds_model};
/// assert!(!object_holds_model([SurfaceOutput::Pattern, SurfaceOutput::Pattern], false));
/// assert!(object_holds_model([SurfaceOutput::Pattern, SurfaceOutput::Emboss], false));
/// assert!(object_holds_model([], true));
/// ```
pub fn object_holds_model(outputs: impl IntoIterator<Item = SurfaceOutput>, with_model: bool) -> bool {
    with_model || outputs.into_iter().any(|o| o != SurfaceOutput::Pattern)
}

/// Points closer to the surface than this were on it, mm: a point moved
/// further is reported.
pub const SNAP_REPORT_MM: f64 = 1e-3;

/// The finest curve step, mm: finer than any nozzle.
pub const MIN_STEP_MM: f64 = 0.05;

/// The thickest wall a pattern is carved from, mm: thicker than the models
/// a band is laid on, which are a hand's size to a vase's.
pub const MAX_WALL_MM: f64 = 50.0;

/// Why a curve could not be drawn on a surface.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DrawnError {
    /// Bad points or settings.
    #[error(transparent)]
    Setting(#[from] InvalidSetting),
    /// No chart.
    #[error(transparent)]
    Chart(#[from] ChartError),
    /// No curve.
    #[error(transparent)]
    Trace(#[from] TraceError),
}

impl SurfaceSettings {
    /// Reads points written `x,y,z;x,y,z;...` (mm).
    pub fn parse_points(text: &str) -> Result<Vec<[f64; 3]>, DrawnError> {
        text.split(';')
            .map(str::trim)
            .filter(|p| !p.is_empty())
            .enumerate()
            .map(|(k, p)| {
                let numbers: Vec<f64> =
                    p.split(',').map(|c| c.trim().parse::<f64>()).collect::<Result<_, _>>().map_err(|_| {
                        InvalidSetting::new("points_mm", format!("point {} ({p}) is not three numbers x,y,z", k + 1))
                    })?;
                match numbers[..] {
                    [x, y, z] => {
                        on_the_table("points_mm", &format!("point {}", k + 1), &[x, y, z])?;
                        Ok([x, y, z])
                    }
                    _ => Err(InvalidSetting::new(
                        "points_mm",
                        format!("point {} ({p}) is not three numbers x,y,z", k + 1),
                    )),
                }
            })
            .collect::<Result<_, InvalidSetting>>()
            .map_err(DrawnError::from)
    }

    /// These settings as a part of an object that does or does not hold
    /// the model: a pattern is embossed where it does
    /// ([`SurfaceOutput::in_object`]). A curve's band and its part in the
    /// object are both made from these.
    ///
    /// ```
    /// use tracery_core::surface::{SurfaceOutput, SurfaceSettings};
    /// let pattern = SurfaceSettings::default();
    /// assert_eq!(pattern.in_object(true).output, SurfaceOutput::Emboss);
    /// assert_eq!(pattern.in_object(false), pattern);
    /// ```
    pub fn in_object(&self, holds_model: bool) -> SurfaceSettings {
        SurfaceSettings { output: self.output.in_object(holds_model), ..self.clone() }
    }

    /// Checks the settings.
    pub fn validate(&self) -> Result<(), DrawnError> {
        let least = if self.closed { 3 } else { 2 };
        if self.points_mm.len() < least {
            return Err(InvalidSetting::new(
                "points_mm",
                format!(
                    "{} curve needs at least {least} points; {} given",
                    if self.closed { "a closed" } else { "an open" },
                    self.points_mm.len()
                ),
            )
            .into());
        }
        for (k, point) in self.points_mm.iter().enumerate() {
            on_the_table("points_mm", &format!("point {}", k + 1), point)?;
        }
        within(
            "twist_deg",
            "the twist",
            self.twist_deg,
            -90.0..=90.0,
            false,
            " degrees",
            "a band standing past upright",
        )?;
        within(
            "step_mm",
            "the curve step",
            self.step_mm,
            MIN_STEP_MM..=MAX_BAND_MM,
            false,
            " mm",
            "wider than any printer's bed",
        )?;
        within(
            "wall_mm",
            "the wall",
            self.wall_mm,
            0.0..=MAX_WALL_MM,
            true,
            " mm",
            "thicker than the models a pattern is carved from",
        )?;
        Ok(())
    }
}

/// A curve drawn on a surface, ready for a band.
#[derive(Clone, Debug)]
pub struct Drawn {
    /// The curve, on the surface.
    pub curve: SurfaceCurve,
    /// Its frames.
    pub frames: Frames,
    /// The band to lay along it, mm (narrowed where needed).
    pub band_mm: f64,
    /// How far each picked point moved onto the surface, mm.
    pub moved_mm: Vec<f64>,
    /// Triangles in the chart that was laid flat.
    pub chart_triangles: usize,
    /// What the person should know.
    pub warnings: Vec<Warning>,
}

/// Share of the inverse turning a half band may reach: the band's inner
/// edge stops short of the centre of the curve's turn.
const FOLD_MARGIN: f64 = 0.8;

/// Draws the curve of `settings` on `surface` for a band `band_mm` wide.
pub fn draw_on(
    surface: &SurfaceMesh,
    settings: &SurfaceSettings,
    band_mm: f64,
    timings: &mut Timings,
) -> Result<Drawn, DrawnError> {
    settings.validate()?;
    let mut warnings = Vec::new();
    let snapped: Vec<_> = settings.points_mm.iter().map(|&p| surface.closest_point(p)).collect();
    let moved_mm: Vec<f64> = snapped
        .iter()
        .zip(&settings.points_mm)
        .map(|(s, p)| s.position_mm.distance(glam::DVec3::from_array(*p)))
        .collect();
    if moved_mm.iter().any(|&d| d > SNAP_REPORT_MM) {
        warnings.push(Warning::PointsSnapped { moved_mm: moved_mm.clone() });
    }
    let chart = timings.time("chart", || Chart::around(surface, &snapped, settings.closed, 1.5 * band_mm))?;
    let curve = timings.time("trace", || trace(surface, &chart, &snapped, settings.closed, settings.step_mm))?;
    let frames = timings.time("frames", || Frames::along(&curve, 0.5 * band_mm, settings.twist_deg));
    let turning = frames.max_turning_per_mm(0.5 * band_mm);
    let mut band = band_mm;
    if turning > 0.0 && 0.5 * band * turning > FOLD_MARGIN {
        band = 2.0 * FOLD_MARGIN / turning;
        warnings.push(Warning::BandNarrowedOnSurface { asked_mm: band_mm, used_mm: band });
    }
    Ok(Drawn { curve, frames, band_mm: band, moved_mm, chart_triangles: chart.triangle_count(), warnings })
}
