//! What region fill adds to a document: a fill is a closed curve whose
//! inside is filled with a curve texture, and a pen stroke is a plain line
//! of a chosen width; pen strokes inside a fill are what the person drew
//! there, which the fill grows around (and which autocomplete and clone
//! continue).

use serde::{Deserialize, Serialize};
use tracery_core::DVec2;
use tracery_core::geom::ring_contains;
use tracery_core::region_fill::{self, BUILTIN_CURVES, CurveExemplar};

use super::{Document, DocumentError, ExemplarRef, file_stem};

/// Whether a pen stroke (its smoothed points, mm) lies in the region inside
/// `outline` (a fill's smoothed outline): most of its points do. The fill
/// gathers its strokes and each stroke finds its fill by this one test.
pub fn inside(outline: &[DVec2], points: &[DVec2]) -> bool {
    let count = points.iter().filter(|&&p| ring_contains(outline, p)).count();
    2 * count > points.len()
}

/// The curve exemplar a new fill starts with.
pub const DEFAULT_CURVE_EXEMPLAR: &str = "spirals";

/// A region fill's choices: its curve exemplar, the mode's settings, and
/// whether the whole region fills by itself.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RegionFillItem {
    /// The curve exemplar (a built-in, see `tracery list --curves`).
    pub exemplar: ExemplarRef,
    /// The settings, the same struct `tracery fill` uses.
    pub settings: region_fill::Settings,
    /// Whether the whole region is filled around the pen strokes in it; off,
    /// only the strokes print, and autocomplete suggests more as they are drawn.
    pub fill_automatically: bool,
}

impl Default for RegionFillItem {
    fn default() -> Self {
        RegionFillItem {
            exemplar: ExemplarRef::Builtin(DEFAULT_CURVE_EXEMPLAR.into()),
            settings: region_fill::Settings::default(),
            fill_automatically: true,
        }
    }
}

/// A pen stroke: the curve drawn with a round pen, as it prints.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PenItem {
    /// The pen's width, mm.
    pub width_mm: f64,
    /// The printed thickness, mm.
    pub thickness_mm: f64,
    /// Whether a closed stroke is a filled shape (its outline the curve,
    /// the width unused): a discrete element such as a berry or a dot.
    pub filled: bool,
}

impl PenItem {
    /// A pen drawing like the strokes of a fill with `settings`.
    pub fn for_fill(settings: &region_fill::Settings) -> PenItem {
        PenItem { width_mm: settings.stroke_width_mm, thickness_mm: settings.thickness_mm, filled: false }
    }

    /// Whether a stroke with this pen along a curve that is `closed` is a filled shape.
    pub fn fills(&self, closed: bool) -> bool {
        self.filled && closed
    }
}

impl Default for PenItem {
    fn default() -> Self {
        PenItem::for_fill(&region_fill::Settings::default())
    }
}

impl Document {
    /// Imports an SVG curve exemplar for region fill, checking it loads
    /// (stroked paths, or filled shapes' outlines); returns its reference.
    pub fn import_curves(&mut self, file_name: &str, svg: &str) -> Result<ExemplarRef, DocumentError> {
        let base = file_stem(file_name);
        let exemplar = CurveExemplar::from_svg_data(base.clone(), svg.as_bytes())
            .map_err(|e| DocumentError::Exemplar(format!("{file_name}: {e}")))?;
        exemplar
            .validate(region_fill::MIN_DELTA_MM)
            .map_err(|e| DocumentError::Exemplar(format!("{file_name}: {e}")))?;
        Ok(self.add_imported_svg(&base, svg, &BUILTIN_CURVES))
    }

    /// Loads the curve exemplar a fill refers to: a built-in, or an
    /// imported SVG read for its strokes and shapes.
    pub fn curve_exemplar(&self, r: &ExemplarRef) -> Result<CurveExemplar, DocumentError> {
        match r {
            ExemplarRef::Builtin(name) => CurveExemplar::builtin(name).ok_or_else(|| {
                let known = BUILTIN_CURVES.join(", ");
                DocumentError::Exemplar(format!("there is no built-in curve exemplar '{name}' (known: {known})"))
            }),
            ExemplarRef::Imported(name) => {
                let imported = self.imported_svg(name)?;
                CurveExemplar::from_svg_data(name.clone(), imported.svg.as_bytes())
                    .map_err(|e| DocumentError::Exemplar(e.to_string()))
            }
        }
    }
}
