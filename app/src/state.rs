//! What the app remembers between runs ([`Persisted`]) and what it can
//! always compute again ([`Caches`]); the document is autosaved on its own.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use serde::{Deserialize, Serialize};
use tracery_core::DVec2;
use tracery_core::Product;
use tracery_core::curve::Curve;
use tracery_core::export::SvgOptions;
use tracery_core::geom::{Region, fill_triangles};
use tracery_core::product::Texture;
use tracery_core::raster_brush::RasterExemplar;
use tracery_core::surface::SurfaceMesh;
use tracery_core::vector_brush::{Exemplar, SlicingMode};

use crate::canvas::View;
use crate::document::{
    AvoidStroke, BaseRef, CurveItem, Document, DocumentError, ExemplarRef, ModeSettings, ModelScene, SurfaceCurveItem,
    avoided_region,
};
use crate::tools::Tool;
use crate::view3d::{Orbit, ViewMesh};

/// Remembered between runs through eframe's storage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Persisted {
    /// Pan and zoom of the canvas.
    pub view: View,
    /// The mode and settings new curves take when nothing is selected.
    pub new_curve: ModeSettings,
    /// What a primary drag does.
    pub tool: Tool,
    /// Draw the band's edges.
    pub show_band: bool,
    /// Draw the seams between pieces.
    pub show_seams: bool,
    /// Shade where a raster pattern may not go (fold-overs and avoided areas).
    pub show_invalid: bool,
    /// Width of the avoidance brush, mm.
    pub avoid_width_mm: f64,
    /// Show the 3D preview.
    pub show_3d: bool,
    /// Highlight thin features, narrow gaps and weak bridges on the canvas.
    pub show_print_flaws: bool,
    /// Show the selected curve's alternative solutions under the canvas.
    pub show_gallery: bool,
    /// Export only the selected curve.
    pub export_selected_only: bool,
    /// Where "Quick export" writes, for desktops without file dialogs.
    pub export_folder: PathBuf,
    /// What an exported SVG is for (engrave or cut) and the laser's kerf.
    pub svg: SvgOptions,
    /// The 3D preview's camera.
    pub orbit: Orbit,
    /// Which workspace the window shows: the canvas or the model.
    pub workspace: Workspace,
    /// The model workspace's camera.
    pub model_orbit: Orbit,
    /// The settings new curves on the model take.
    pub new_surface_curve: SurfaceCurveItem,
    /// The project file, once saved or opened.
    pub project_path: Option<PathBuf>,
}

impl Default for Persisted {
    fn default() -> Self {
        Persisted {
            view: View::default(),
            new_curve: ModeSettings::default(),
            tool: Tool::Draw,
            show_band: true,
            show_seams: false,
            show_invalid: true,
            avoid_width_mm: DEFAULT_AVOID_WIDTH_MM,
            show_3d: false,
            show_print_flaws: true,
            show_gallery: true,
            export_selected_only: false,
            export_folder: default_export_folder(),
            svg: SvgOptions::default(),
            orbit: Orbit::default(),
            workspace: Workspace::Canvas,
            model_orbit: Orbit::default(),
            new_surface_curve: SurfaceCurveItem::default(),
            project_path: None,
        }
    }
}

/// What the window's middle shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Workspace {
    /// The flat canvas: curves drawn with the brushes.
    #[default]
    Canvas,
    /// A 3D model: curves picked on its surface.
    Model,
}

/// A model loaded for drawing and picking.
pub struct LoadedModel {
    /// The surface, with its BVH for picking.
    pub surface: Arc<SurfaceMesh>,
    /// Its triangles for the 3D view.
    pub view: Arc<ViewMesh>,
}

/// Width of the avoidance brush until the person changes it, mm.
pub const DEFAULT_AVOID_WIDTH_MM: f64 = 6.0;

fn default_export_folder() -> PathBuf {
    std::env::var_os("HOME").map_or_else(|| PathBuf::from("."), |h| PathBuf::from(h).join("Tracery"))
}

/// A drawing of an exemplar for the side panel: filled triangles per piece,
/// and the cut lines.
pub struct ExemplarPicture {
    /// The exemplar's bounds, exemplar units.
    pub bounds: tracery_core::geom::Rect,
    /// Triangles of each piece, exemplar units.
    pub pieces: Vec<Vec<[tracery_core::DVec2; 3]>>,
    /// Cut positions along `u`.
    pub cuts: Vec<f64>,
}

/// A curve smoothed through its control points, and what it was made from.
struct Smoothed {
    points: Vec<[f64; 2]>,
    closed: bool,
    /// Shared with the jobs made from it, so that asking the worker again
    /// each frame neither copies nor compares the dense polyline.
    curve: Option<Arc<Curve>>,
}

/// Everything derived from the document that is kept to avoid recomputing it.
#[derive(Default)]
pub struct Caches {
    exemplars: HashMap<ExemplarRef, Arc<Exemplar>>,
    pictures: HashMap<(ExemplarRef, SlicingMode), Option<ExemplarPicture>>,
    /// Smoothing runs when a curve changes, not on every frame.
    smoothed: HashMap<u64, Smoothed>,
    raster_exemplars: HashMap<ExemplarRef, Arc<RasterExemplar>>,
    curve_exemplars: HashMap<ExemplarRef, Arc<tracery_core::region_fill::CurveExemplar>>,
    /// Pictures uploaded to the GPU, by the address of their pixels (kept
    /// alive here, so an address is not reused while its entry exists).
    textures: HashMap<usize, (Arc<[u8]>, egui::TextureHandle)>,
    avoided: Avoided,
    /// Products' meshes as the 3D view draws them, by the product's address
    /// (kept alive here, so an address is not reused while its entry exists).
    view_meshes: HashMap<usize, (Arc<Product>, Arc<ViewMesh>)>,
    /// Models by reference, or why they did not load (kept, so a broken
    /// model is not read again every frame).
    models: HashMap<BaseRef, Result<Arc<LoadedModel>, String>>,
    /// Built-in swatches, modelled once.
    swatches: HashMap<String, Arc<tracery_core::mesh_quilt::Swatch>>,
}

/// The avoided area and its triangles, and the strokes they were made from.
#[derive(Default)]
pub struct Avoided {
    strokes: Vec<AvoidStroke>,
    /// The area, mm (shared with the jobs).
    pub region: Arc<Region>,
    /// Its triangles, for drawing.
    pub triangles: Vec<[DVec2; 3]>,
}

/// The value `cache` holds for `r`, loaded and kept the first time.
fn load_once<T>(
    cache: &mut HashMap<ExemplarRef, Arc<T>>,
    r: &ExemplarRef,
    load: impl FnOnce() -> Result<T, DocumentError>,
) -> Result<Arc<T>, DocumentError> {
    if let Some(e) = cache.get(r) {
        return Ok(e.clone());
    }
    let e = Arc::new(load()?);
    cache.insert(r.clone(), e.clone());
    Ok(e)
}

impl Caches {
    /// The exemplar a reference names, loaded once.
    pub fn exemplar(&mut self, doc: &Document, r: &ExemplarRef) -> Result<Arc<Exemplar>, DocumentError> {
        load_once(&mut self.exemplars, r, || doc.exemplar(r))
    }

    /// The picture of an exemplar cut with `slicing`, made once.
    pub fn picture(&mut self, doc: &Document, r: &ExemplarRef, slicing: SlicingMode) -> Option<&ExemplarPicture> {
        let key = (r.clone(), slicing);
        if !self.pictures.contains_key(&key) {
            let picture = self.exemplar(doc, r).ok().and_then(|e| crate::panels::exemplar_picker::picture(&e, slicing));
            self.pictures.insert(key.clone(), picture);
        }
        self.pictures.get(&key).and_then(Option::as_ref)
    }

    /// The raster exemplar a reference names, loaded once.
    pub fn raster_exemplar(&mut self, doc: &Document, r: &ExemplarRef) -> Result<Arc<RasterExemplar>, DocumentError> {
        load_once(&mut self.raster_exemplars, r, || doc.raster_exemplar(r))
    }

    /// The curve exemplar a reference names, loaded once.
    pub fn curve_exemplar(
        &mut self,
        doc: &Document,
        r: &ExemplarRef,
    ) -> Result<Arc<tracery_core::region_fill::CurveExemplar>, DocumentError> {
        load_once(&mut self.curve_exemplars, r, || doc.curve_exemplar(r))
    }

    /// `texture` uploaded for drawing, once for as long as something holds it.
    pub fn texture(&mut self, ctx: &egui::Context, texture: &Texture) -> egui::TextureId {
        // Pictures nothing else holds any more are dropped first.
        self.textures.retain(|_, (pixels, _)| Arc::strong_count(pixels) > 1);
        let key = Arc::as_ptr(&texture.rgba).cast::<u8>() as usize;
        let entry = self.textures.entry(key).or_insert_with(|| {
            let size = [texture.width_px as usize, texture.height_px as usize];
            let image = egui::ColorImage::from_rgba_unmultiplied(size, &texture.rgba);
            let handle = ctx.load_texture(format!("texture-{key:x}"), image, egui::TextureOptions::LINEAR);
            (texture.rgba.clone(), handle)
        });
        entry.1.id()
    }

    /// The 3D view's copy of a product's mesh, made once for as long as
    /// something else holds the product.
    pub fn view_mesh(&mut self, product: &Arc<Product>) -> Option<Arc<ViewMesh>> {
        self.view_meshes.retain(|_, (p, _)| Arc::strong_count(p) > 1);
        let mesh = product.mesh_mm.as_ref()?;
        let key = Arc::as_ptr(product) as usize;
        let entry = self.view_meshes.entry(key).or_insert_with(|| (product.clone(), Arc::new(ViewMesh::new(mesh))));
        Some(entry.1.clone())
    }

    /// The area the avoidance brush covers in `strokes`, made again only when they change.
    pub fn avoided(&mut self, strokes: &[AvoidStroke]) -> &Avoided {
        if self.avoided.strokes != strokes {
            let region = avoided_region(strokes);
            let triangles = fill_triangles(&region);
            self.avoided = Avoided { strokes: strokes.to_vec(), region: Arc::new(region), triangles };
        }
        &self.avoided
    }

    /// The model a base reference names, loaded once.
    pub fn model(&mut self, scene: &ModelScene, base: &BaseRef) -> Result<Arc<LoadedModel>, String> {
        self.models
            .entry(base.clone())
            .or_insert_with(|| {
                let mesh = scene.base_mesh(base).map_err(|e| e.to_string())?;
                let surface = SurfaceMesh::new(mesh).map_err(|e| format!("{}: {e}", base.name()))?;
                // Drawn as the surface has it (after any repair), so picks land where they show.
                let view = Arc::new(ViewMesh::new(surface.mesh()));
                Ok(Arc::new(LoadedModel { surface: Arc::new(surface), view }))
            })
            .clone()
    }

    /// The built-in swatch named `name`, modelled once.
    pub fn swatch(&mut self, name: &str) -> Result<Arc<tracery_core::mesh_quilt::Swatch>, String> {
        use tracery_core::mesh_quilt::{SWATCH_NAMES, builtin_swatch};
        if let Some(swatch) = self.swatches.get(name) {
            return Ok(swatch.clone());
        }
        let swatch = Arc::new(
            builtin_swatch(name)
                .ok_or_else(|| format!("no built-in swatch '{name}' (built-ins: {})", SWATCH_NAMES.join(", ")))?,
        );
        self.swatches.insert(name.to_string(), swatch.clone());
        Ok(swatch)
    }

    /// Forgets a model (it was refused, and its name may be given to another).
    pub fn forget_model(&mut self, base: &BaseRef) {
        self.models.remove(base);
    }

    /// Forgets imported exemplars (the document changed under them).
    pub fn forget_imported(&mut self) {
        self.models.retain(|r, _| matches!(r, BaseRef::Builtin(_)));
        self.exemplars.retain(|r, _| matches!(r, ExemplarRef::Builtin(_)));
        self.raster_exemplars.retain(|r, _| matches!(r, ExemplarRef::Builtin(_)));
        self.curve_exemplars.retain(|r, _| matches!(r, ExemplarRef::Builtin(_)));
        self.pictures.retain(|(r, _), _| matches!(r, ExemplarRef::Builtin(_)));
    }

    /// Brings the smoothed curves up to date with the document.
    pub fn refresh_smoothed(&mut self, curves: &[CurveItem]) {
        self.smoothed.retain(|id, _| curves.iter().any(|c| c.id == *id));
        for item in curves {
            let fresh = self.smoothed.get(&item.id).is_some_and(|s| s.points == item.points && s.closed == item.closed);
            if !fresh {
                let smoothed =
                    Smoothed { points: item.points.clone(), closed: item.closed, curve: item.curve().map(Arc::new) };
                self.smoothed.insert(item.id, smoothed);
            }
        }
    }

    /// The smoothed curve of item `id`, if it is long enough to be one.
    pub fn smoothed(&self, id: u64) -> Option<&Arc<Curve>> {
        self.smoothed.get(&id).and_then(|s| s.curve.as_ref())
    }
}
