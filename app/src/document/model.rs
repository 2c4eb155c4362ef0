//! The model workspace's part of the document: the 3D model patterns are
//! drawn on (a built-in base or an imported mesh, embedded), and the curves
//! picked on its surface, each with the vector brush's settings and the
//! surface's ([`SurfaceSettings`], the struct `tracery surface` uses).

use base64::Engine as _;
use serde::{Deserialize, Serialize};
use tracery_core::export::write_stl;
use tracery_core::mesh::{Mesh, read_stl};
use tracery_core::surface::{BASE_NAMES, MIN_POINTS, ShadeSettings, SurfaceSettings, builtin_base, object_holds_model};
use tracery_core::vector_brush;

use super::{DocumentError, ExemplarRef, file_stem, unique_name};

/// The model a curve is drawn on.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum BaseRef {
    /// A built-in base, by name (see `tracery list --bases`).
    Builtin(String),
    /// An imported model, by its name in [`ModelScene::imported`].
    Imported(String),
}

impl BaseRef {
    /// The name shown to people.
    pub fn name(&self) -> &str {
        match self {
            BaseRef::Builtin(n) | BaseRef::Imported(n) => n,
        }
    }
}

impl Default for BaseRef {
    fn default() -> Self {
        BaseRef::Builtin("vase".into())
    }
}

/// An imported model, embedded as a binary STL so that the project opens anywhere.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImportedModel {
    /// Name (from the file name), unique among imported models.
    pub name: String,
    /// The mesh as binary STL, base64.
    pub stl_base64: String,
}

/// A curve picked on the model's surface, and how its pattern is made.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SurfaceCurveItem {
    /// Stable id (for results and selection), shared with the canvas's curves.
    pub id: u64,
    /// The exemplar.
    pub exemplar: ExemplarRef,
    /// The vector brush's settings.
    pub settings: vector_brush::Settings,
    /// The picked points, whether the curve closes, twist and what is made.
    pub surface: SurfaceSettings,
    /// Whether the curve only guides the texture's rows (when they run
    /// along curves) and carries no pattern of its own: no job, no part in
    /// the object.
    pub guide: bool,
}

impl SurfaceCurveItem {
    /// The picked points in order, back to the first when the curve is
    /// closed.
    pub fn path_mm(&self) -> Vec<[f64; 3]> {
        let points = &self.surface.points_mm;
        let back = points.first().copied().filter(|_| self.surface.closed && points.len() > 1);
        points.iter().copied().chain(back).collect()
    }
}

impl Default for SurfaceCurveItem {
    fn default() -> Self {
        SurfaceCurveItem {
            id: 0,
            exemplar: ExemplarRef::Builtin("chain".into()),
            settings: vector_brush::Settings::default(),
            surface: SurfaceSettings::default(),
            guide: false,
        }
    }
}

/// A lamp shade standing on the model's axis (the `z` axis), lifted to
/// `lift_mm`: with a model as its foot, a lamp in one object.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ShadeItem {
    /// Stable id, shared with the curves.
    pub id: u64,
    /// The exemplar of its rows.
    pub exemplar: ExemplarRef,
    /// The vector brush's settings, for each row.
    pub settings: vector_brush::Settings,
    /// The shade's shape, rims and rows (the struct `tracery shade` uses).
    pub shade: ShadeSettings,
    /// Height of the shade's bottom rim above the model's `z = 0`, mm.
    pub lift_mm: f64,
}

impl Default for ShadeItem {
    fn default() -> Self {
        let mut settings = vector_brush::Settings::default();
        settings.band_mm = 12.0;
        ShadeItem {
            id: 0,
            exemplar: ExemplarRef::Builtin("lace".into()),
            settings,
            shade: ShadeSettings::default(),
            lift_mm: 0.0,
        }
    }
}

/// 3D texture grown over the whole model from a mesh swatch (mesh
/// quilting), with the settings `tracery quilt` uses.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct TextureItem {
    /// Whether the model is covered; off keeps the choices for later.
    pub on: bool,
    /// The built-in swatch, by name (see `tracery list --swatches`).
    pub swatch: String,
    /// Scale, seed, sink and the rest.
    pub settings: tracery_core::mesh_quilt::Settings,
}

impl Default for TextureItem {
    fn default() -> Self {
        TextureItem { on: false, swatch: "rivets".into(), settings: tracery_core::mesh_quilt::Settings::default() }
    }
}

/// The model workspace: a model, the curves drawn on it and the shades over it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ModelScene {
    /// The model the curves lie on.
    pub base: BaseRef,
    /// Imported models.
    pub imported: Vec<ImportedModel>,
    /// Curves on the model, in drawing order.
    pub curves: Vec<SurfaceCurveItem>,
    /// Lamp shades on the model's axis.
    pub shades: Vec<ShadeItem>,
    /// Whether the model is part of the exported object even where no
    /// curve is embossed on it (a lamp's foot).
    pub with_model: bool,
    /// Texture over the whole model.
    pub texture: TextureItem,
}

impl ModelScene {
    /// Whether the object holds the model: asked for, or needed by an
    /// embossed or carved curve. A pattern curve is then embossed
    /// ([`SurfaceSettings::in_object`]).
    pub fn holds_model(&self) -> bool {
        object_holds_model(self.drawn_curves().map(|c| c.surface.output), self.with_model)
    }
}

impl ModelScene {
    /// The mesh a base reference names.
    pub fn base_mesh(&self, base: &BaseRef) -> Result<Mesh, DocumentError> {
        match base {
            BaseRef::Builtin(name) => builtin_base(name).ok_or_else(|| {
                DocumentError::Model(format!("no built-in model '{name}' (built-ins: {})", BASE_NAMES.join(", ")))
            }),
            BaseRef::Imported(name) => {
                let model = self
                    .imported
                    .iter()
                    .find(|m| &m.name == name)
                    .ok_or_else(|| DocumentError::Model(format!("the imported model '{name}' is missing")))?;
                let bytes = base64::engine::general_purpose::STANDARD
                    .decode(&model.stl_base64)
                    .map_err(|e| DocumentError::Model(format!("the imported model '{name}' is damaged: {e}")))?;
                read_stl(&bytes, name).map_err(|e| DocumentError::Model(e.to_string()))
            }
        }
    }

    /// Embeds a model read from `file_name`; returns its reference.
    pub fn import(&mut self, file_name: &str, mesh: &Mesh) -> Result<BaseRef, DocumentError> {
        let mut bytes = Vec::new();
        write_stl(mesh, &mut bytes).map_err(|e| DocumentError::Model(e.to_string()))?;
        let base = file_stem(file_name);
        let name = unique_name(&base, |n| self.imported.iter().any(|m| m.name == n) || BASE_NAMES.contains(&n));
        let stl_base64 = base64::engine::general_purpose::STANDARD.encode(bytes);
        self.imported.push(ImportedModel { name: name.clone(), stl_base64 });
        Ok(BaseRef::Imported(name))
    }

    /// The curves that carry a pattern and have points enough for one:
    /// those that have a job, and a part in the object. Guides are not
    /// among them.
    pub fn drawn_curves(&self) -> impl Iterator<Item = &SurfaceCurveItem> + Clone {
        self.curves.iter().filter(|c| !c.guide && c.surface.points_mm.len() >= MIN_POINTS)
    }

    /// The strokes a texture running along curves follows: every curve
    /// with points enough, guide or pattern, in drawing order; a closed one
    /// returns to its first point.
    pub fn texture_strokes_mm(&self) -> Vec<Vec<[f64; 3]>> {
        let long_enough = self.curves.iter().filter(|c| c.surface.points_mm.len() >= MIN_POINTS);
        long_enough.map(SurfaceCurveItem::path_mm).collect()
    }

    /// The curve with `id`.
    pub fn curve(&self, id: u64) -> Option<&SurfaceCurveItem> {
        self.curves.iter().find(|c| c.id == id)
    }

    /// The curve with `id`, mutable.
    pub fn curve_mut(&mut self, id: u64) -> Option<&mut SurfaceCurveItem> {
        self.curves.iter_mut().find(|c| c.id == id)
    }

    /// The shade with `id`.
    pub fn shade(&self, id: u64) -> Option<&ShadeItem> {
        self.shades.iter().find(|c| c.id == id)
    }

    /// The shade with `id`, mutable.
    pub fn shade_mut(&mut self, id: u64) -> Option<&mut ShadeItem> {
        self.shades.iter_mut().find(|c| c.id == id)
    }
}
