//! The document a person edits: curves, each with its mode's settings, and
//! imported exemplars. Saved as `.ron` with a `format_version`; imported
//! exemplars are embedded so a project opens anywhere. Files written before
//! versioning (format 0) are read by [`legacy`] and converted.

mod fill;
mod history;
pub mod legacy;
mod model;
mod raster;

pub use fill::{DEFAULT_CURVE_EXEMPLAR, PenItem, RegionFillItem, inside};
pub use history::History;
pub use model::{BaseRef, ImportedModel, ModelScene, ShadeItem, SurfaceCurveItem};
pub use raster::{AvoidStroke, DEFAULT_RASTER_EXEMPLAR, ImportedRaster, RasterBrushItem, avoided_region};

use serde::{Deserialize, Serialize};
use tracery_core::DVec2;
use tracery_core::curve::Curve;
use tracery_core::print::{JumpRings, PrintSettings};
use tracery_core::vector_brush::{self, Exemplar, LoadOptions, builtin};

/// The format this version writes. Older formats are converted on opening.
pub const FORMAT_VERSION: u32 = 1;

/// How far apart the smoothed curve's samples are, mm.
pub const SMOOTHING_SPACING_MM: f64 = 0.5;

/// Which exemplar a curve uses.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ExemplarRef {
    /// A built-in exemplar, by name.
    Builtin(String),
    /// An imported exemplar, by its name in [`Document::imported`].
    Imported(String),
}

impl ExemplarRef {
    /// The name shown to people.
    pub fn name(&self) -> &str {
        match self {
            ExemplarRef::Builtin(n) | ExemplarRef::Imported(n) => n,
        }
    }
}

impl Default for ExemplarRef {
    fn default() -> Self {
        ExemplarRef::Builtin("lace".into())
    }
}

/// A vector-brush curve's choices: its exemplar and the mode's settings.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct VectorBrushItem {
    /// The exemplar.
    pub exemplar: ExemplarRef,
    /// The settings, the same struct the command line uses.
    pub settings: vector_brush::Settings,
}

/// Which mode makes a curve's pattern, with that mode's settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum ModeSettings {
    /// Topology-constrained vector patterns along the curve.
    VectorBrush(VectorBrushItem),
    /// Bitmap exemplars laid along the curve.
    RasterBrush(RasterBrushItem),
    /// The inside of the closed curve filled with a curve texture.
    RegionFill(RegionFillItem),
    /// The curve drawn with a round pen.
    Pen(PenItem),
}

impl From<VectorBrushItem> for ModeSettings {
    fn from(item: VectorBrushItem) -> Self {
        ModeSettings::VectorBrush(item)
    }
}

impl From<RasterBrushItem> for ModeSettings {
    fn from(item: RasterBrushItem) -> Self {
        ModeSettings::RasterBrush(item)
    }
}

impl From<RegionFillItem> for ModeSettings {
    fn from(item: RegionFillItem) -> Self {
        ModeSettings::RegionFill(item)
    }
}

impl Default for ModeSettings {
    fn default() -> Self {
        ModeSettings::VectorBrush(VectorBrushItem::default())
    }
}

impl ModeSettings {
    /// The band's height across the curve, mm (for hit testing and overlays).
    pub fn band_mm(&self) -> f64 {
        match self {
            ModeSettings::VectorBrush(v) => v.settings.band_mm,
            ModeSettings::RasterBrush(r) => r.settings.band_mm,
            // A fill is picked by its outline.
            ModeSettings::RegionFill(_) => 0.0,
            ModeSettings::Pen(p) => p.width_mm,
        }
    }

    /// Whether a curve of this mode is always a loop (a region's outline).
    pub fn always_closed(&self) -> bool {
        matches!(self, ModeSettings::RegionFill(_))
    }

    /// A copy for a newly drawn curve: the same choices, the best pattern.
    pub fn for_new_curve(&self) -> ModeSettings {
        let mut out = self.clone();
        match &mut out {
            ModeSettings::VectorBrush(v) => {
                v.settings.seed = 0;
                v.settings.alternative = 0;
            }
            ModeSettings::RasterBrush(_) | ModeSettings::RegionFill(_) | ModeSettings::Pen(_) => {}
        }
        out
    }

    /// The exemplar the mode draws with, if it has one.
    pub fn exemplar_mut(&mut self) -> Option<&mut ExemplarRef> {
        match self {
            ModeSettings::VectorBrush(v) => Some(&mut v.exemplar),
            ModeSettings::RasterBrush(r) => Some(&mut r.exemplar),
            ModeSettings::RegionFill(f) => Some(&mut f.exemplar),
            ModeSettings::Pen(_) => None,
        }
    }

    /// Whether the mode offers alternative solutions for the gallery.
    pub fn has_alternatives(&self) -> bool {
        match self {
            ModeSettings::VectorBrush(_) => true,
            // One result: the search is exact.
            ModeSettings::RasterBrush(_) => false,
            // One result per seed.
            ModeSettings::RegionFill(_) | ModeSettings::Pen(_) => false,
        }
    }

    /// Which of the gallery's solutions the curve uses (0: the best).
    pub fn alternative(&self) -> u32 {
        match self {
            ModeSettings::VectorBrush(v) => v.settings.alternative,
            // These modes have one result.
            ModeSettings::RasterBrush(_) | ModeSettings::RegionFill(_) | ModeSettings::Pen(_) => 0,
        }
    }

    /// Uses the gallery's solution `k`.
    pub fn set_alternative(&mut self, k: u32) {
        match self {
            ModeSettings::VectorBrush(v) => v.settings.alternative = k,
            ModeSettings::RasterBrush(_) | ModeSettings::RegionFill(_) | ModeSettings::Pen(_) => {}
        }
    }
}

/// One curve and its pattern settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CurveItem {
    /// Stable id (for results and selection).
    pub id: u64,
    /// Control points in mm, `y` up; the curve is smoothed through them.
    pub points: Vec<[f64; 2]>,
    /// Whether the curve is a loop.
    pub closed: bool,
    /// The mode and its settings.
    pub mode: ModeSettings,
    /// Jump rings for hanging the piece (none in older projects).
    #[serde(default)]
    pub jump_rings: JumpRings,
}

impl CurveItem {
    /// The control points as vectors.
    pub fn control_points(&self) -> Vec<DVec2> {
        self.points.iter().map(|p| DVec2::new(p[0], p[1])).collect()
    }

    /// The smooth curve through the control points.
    pub fn curve(&self) -> Option<Curve> {
        Curve::from_stroke(&self.control_points(), self.closed, SMOOTHING_SPACING_MM).ok()
    }
}

/// An exemplar imported from SVG, embedded in the document.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImportedExemplar {
    /// Name (from the file name), unique in the document.
    pub name: String,
    /// The SVG source.
    pub svg: String,
}

/// Why a document could not be read, or an exemplar found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DocumentError {
    /// The text is not a project.
    #[error("not a Tracery project: {0}")]
    NotAProject(String),
    /// A newer Tracery wrote it.
    #[error("this project was written by a newer Tracery (format {found}; this one reads up to {FORMAT_VERSION})")]
    TooNew {
        /// The version found.
        found: u32,
    },
    /// The project could not be written out.
    #[error("could not write the project: {0}")]
    Write(String),
    /// A curve refers to an imported exemplar that is not in the document.
    #[error("the imported exemplar '{0}' is missing")]
    MissingExemplar(String),
    /// An exemplar did not load.
    #[error("{0}")]
    Exemplar(String),
    /// A model did not load.
    #[error("{0}")]
    Model(String),
}

/// A Tracery project.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Document {
    /// The format this document is in ([`FORMAT_VERSION`] once loaded).
    pub format_version: u32,
    /// Curves, in drawing order.
    pub curves: Vec<CurveItem>,
    /// Imported exemplars.
    pub imported: Vec<ImportedExemplar>,
    /// Imported PNG exemplars of the raster brush (absent in older projects).
    pub imported_raster: Vec<ImportedRaster>,
    /// Areas painted with the avoidance brush, which raster patterns leave empty.
    pub avoid: Vec<AvoidStroke>,
    /// The next curve id.
    pub next_id: u64,
    /// The printer the patterns are made for (absent in older projects: the defaults).
    pub print: PrintSettings,
    /// The model workspace: a 3D model and curves drawn on it (absent in older projects).
    pub model: ModelScene,
}

impl Default for Document {
    fn default() -> Self {
        Document {
            format_version: FORMAT_VERSION,
            curves: Vec::new(),
            imported: Vec::new(),
            imported_raster: Vec::new(),
            avoid: Vec::new(),
            next_id: 0,
            print: PrintSettings::default(),
            model: ModelScene::default(),
        }
    }
}

/// An imported exemplar's name from its file's name.
fn file_stem(file_name: &str) -> String {
    std::path::Path::new(file_name)
        .file_stem()
        .map_or_else(|| "imported".to_string(), |s| s.to_string_lossy().into_owned())
}

/// `base`, or `base 2`, `base 3`… : the first that `taken` does not claim.
fn unique_name(base: &str, taken: impl Fn(&str) -> bool) -> String {
    let mut name = base.to_string();
    let mut k = 2;
    while taken(&name) {
        name = format!("{base} {k}");
        k += 1;
    }
    name
}

/// Only the version, to decide how to read the rest.
#[derive(Deserialize)]
struct VersionProbe {
    /// Absent before versioning: format 0.
    #[serde(default)]
    format_version: u32,
}

impl Document {
    /// Adds a curve and returns its id.
    pub fn add_curve(&mut self, points: Vec<DVec2>, closed: bool, mode: ModeSettings) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        let points = points.iter().map(|p| [p.x, p.y]).collect();
        self.curves.push(CurveItem { id, points, closed, mode, jump_rings: JumpRings::default() });
        id
    }

    /// Adds a curve on the model with `template`'s settings and no points
    /// yet; returns its id.
    pub fn add_surface_curve(&mut self, template: &SurfaceCurveItem) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        let mut surface = template.surface.clone();
        surface.points_mm.clear();
        self.model.curves.push(SurfaceCurveItem { id, surface, ..template.clone() });
        id
    }

    /// Adds `shade` to the model workspace under a new id; returns the id.
    pub fn add_shade(&mut self, shade: ShadeItem) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        self.model.shades.push(ShadeItem { id, ..shade });
        id
    }

    /// Whether anything was drawn or imported that a person would miss:
    /// curves on the canvas or on the model, shades, or an imported model.
    pub fn has_drawing(&self) -> bool {
        !self.curves.is_empty()
            || !self.model.curves.is_empty()
            || !self.model.shades.is_empty()
            || !self.model.imported.is_empty()
    }

    /// The curve with `id`.
    pub fn curve(&self, id: u64) -> Option<&CurveItem> {
        self.curves.iter().find(|c| c.id == id)
    }

    /// The curve with `id`, mutable.
    pub fn curve_mut(&mut self, id: u64) -> Option<&mut CurveItem> {
        self.curves.iter_mut().find(|c| c.id == id)
    }

    /// The imported SVG exemplar named `name`.
    pub fn imported_svg(&self, name: &str) -> Result<&ImportedExemplar, DocumentError> {
        self.imported.iter().find(|e| e.name == name).ok_or_else(|| DocumentError::MissingExemplar(name.to_string()))
    }

    /// Loads the exemplar a curve refers to.
    pub fn exemplar(&self, r: &ExemplarRef) -> Result<Exemplar, DocumentError> {
        match r {
            ExemplarRef::Builtin(name) => builtin(name).map_err(|e| DocumentError::Exemplar(e.to_string())),
            ExemplarRef::Imported(name) => {
                let imported = self.imported_svg(name)?;
                Exemplar::from_svg_str(name.clone(), &imported.svg, &LoadOptions::default())
                    .map_err(|e| DocumentError::Exemplar(e.to_string()))
            }
        }
    }

    /// Imports an SVG exemplar, checking it loads; returns its reference.
    pub fn import(&mut self, file_name: &str, svg: &str) -> Result<ExemplarRef, DocumentError> {
        let base = file_stem(file_name);
        Exemplar::from_svg_str(base.clone(), svg, &LoadOptions::default())
            .map_err(|e| DocumentError::Exemplar(format!("{file_name}: {e}")))?;
        Ok(self.add_imported_svg(&base, svg, vector_brush::BUILTIN_NAMES))
    }

    /// Adds an SVG already checked to load, under `base` or the first free
    /// name after it (free of other imports and of the `builtins` it would
    /// be picked beside); returns its reference.
    pub(crate) fn add_imported_svg(&mut self, base: &str, svg: &str, builtins: &[&str]) -> ExemplarRef {
        let name = unique_name(base, |n| self.imported.iter().any(|e| e.name == n) || builtins.contains(&n));
        self.imported.push(ImportedExemplar { name: name.clone(), svg: svg.to_string() });
        ExemplarRef::Imported(name)
    }

    /// The document as `.ron` text, in the current format.
    pub fn to_ron(&self) -> Result<String, DocumentError> {
        let current = Document { format_version: FORMAT_VERSION, ..self.clone() };
        ron::ser::to_string_pretty(&current, ron::ser::PrettyConfig::default())
            .map_err(|e| DocumentError::Write(e.to_string()))
    }

    /// A document from `.ron` text of any format this version knows.
    pub fn from_ron(text: &str) -> Result<Document, DocumentError> {
        let not_a_project = |e: ron::error::SpannedError| DocumentError::NotAProject(e.to_string());
        let probe: VersionProbe = ron::from_str(text).map_err(not_a_project)?;
        match probe.format_version {
            0 => Ok(ron::from_str::<legacy::DocumentV0>(text).map_err(not_a_project)?.into()),
            found if found > FORMAT_VERSION => Err(DocumentError::TooNew { found }),
            _ => {
                let mut doc: Document = ron::from_str(text).map_err(not_a_project)?;
                doc.format_version = FORMAT_VERSION;
                Ok(doc)
            }
        }
    }
}
