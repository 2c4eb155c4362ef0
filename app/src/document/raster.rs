//! What the raster brush adds to a document: its curves' choices, PNG
//! exemplars embedded as base64 text (so a project opens anywhere), and the
//! areas painted with the avoidance brush.

use std::sync::Arc;

use base64::Engine as _;
use base64::engine::general_purpose::STANDARD as BASE64;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use tracery_core::DVec2;
use tracery_core::geom::{Region, brush_stroke, union};
use tracery_core::raster_brush::{self, RasterExemplar};

use super::{Document, DocumentError, ExemplarRef, file_stem, unique_name};

/// The raster exemplar a new raster curve starts with.
pub const DEFAULT_RASTER_EXEMPLAR: &str = "rope";

/// A raster-brush curve's choices: its exemplar and the mode's settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RasterBrushItem {
    /// The exemplar: a built-in raster exemplar, or one in [`Document::imported_raster`].
    pub exemplar: ExemplarRef,
    /// The settings, the same struct the command line uses.
    pub settings: raster_brush::Settings,
}

impl Default for RasterBrushItem {
    fn default() -> Self {
        RasterBrushItem {
            exemplar: ExemplarRef::Builtin(DEFAULT_RASTER_EXEMPLAR.into()),
            settings: raster_brush::Settings::default(),
        }
    }
}

/// A PNG exemplar imported into the document.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImportedRaster {
    /// Name (from the file name), unique among raster exemplars.
    pub name: String,
    /// The PNG file's bytes, written as base64 text. Shared: the app copies
    /// the document every frame and keeps copies for undo, and a shared
    /// picture costs neither a copy nor a byte-by-byte comparison there.
    #[serde(serialize_with = "to_base64", deserialize_with = "from_base64")]
    pub png: Arc<[u8]>,
}

fn to_base64<S: Serializer>(bytes: &[u8], s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&BASE64.encode(bytes))
}

fn from_base64<'de, D: Deserializer<'de>>(d: D) -> Result<Arc<[u8]>, D::Error> {
    let text = String::deserialize(d)?;
    BASE64.decode(text.as_bytes()).map(Arc::from).map_err(serde::de::Error::custom)
}

/// One stroke of the avoidance brush: patterns leave the area it covers empty.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AvoidStroke {
    /// The brush's path, mm, `y` up.
    pub points: Vec<[f64; 2]>,
    /// The brush's width, mm.
    pub width_mm: f64,
}

impl AvoidStroke {
    /// The area the stroke covers, mm.
    pub fn region(&self) -> Region {
        let points: Vec<DVec2> = self.points.iter().map(|p| DVec2::new(p[0], p[1])).collect();
        brush_stroke(&points, self.width_mm, false)
    }
}

/// The area all `strokes` cover together, mm.
pub fn avoided_region(strokes: &[AvoidStroke]) -> Region {
    let regions: Vec<Region> = strokes.iter().map(AvoidStroke::region).collect();
    union(&regions.iter().collect::<Vec<_>>())
}

impl Document {
    /// Loads the raster exemplar a curve refers to.
    pub fn raster_exemplar(&self, r: &ExemplarRef) -> Result<RasterExemplar, DocumentError> {
        match r {
            ExemplarRef::Builtin(name) => raster_brush::builtin(name).ok_or_else(|| {
                let known = raster_brush::BUILTIN_NAMES.join(", ");
                DocumentError::Exemplar(format!("there is no built-in raster exemplar '{name}' (known: {known})"))
            }),
            ExemplarRef::Imported(name) => {
                let imported = self
                    .imported_raster
                    .iter()
                    .find(|e| &e.name == name)
                    .ok_or_else(|| DocumentError::MissingExemplar(name.clone()))?;
                RasterExemplar::from_png(name, &imported.png).map_err(|e| DocumentError::Exemplar(e.to_string()))
            }
        }
    }

    /// Imports a PNG exemplar, checking it loads; returns its reference.
    pub fn import_png(&mut self, file_name: &str, png: &[u8]) -> Result<ExemplarRef, DocumentError> {
        let base = file_stem(file_name);
        RasterExemplar::from_png(&base, png).map_err(|e| DocumentError::Exemplar(format!("{file_name}: {e}")))?;
        let name = unique_name(&base, |n| {
            self.imported_raster.iter().any(|e| e.name == n) || raster_brush::BUILTIN_NAMES.contains(&n)
        });
        self.imported_raster.push(ImportedRaster { name: name.clone(), png: Arc::from(png) });
        Ok(ExemplarRef::Imported(name))
    }
}
