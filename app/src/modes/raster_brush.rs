//! The raster brush in the app: bitmap exemplars picked from thumbnails or
//! imported, the ribbon's settings, the areas it may not use, and its job.

use std::sync::Arc;

use egui::{Color32, RichText};
use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::curve::{Along, Curve};
use tracery_core::geom::{Region, fill_triangles};
use tracery_core::raster_brush::{BUILTIN_NAMES, MAX_SCALE, RasterError, RasterExemplar, Settings, make_product};

use super::{ModeEnv, ModeJob, ModeUi, OverlayToggles, same};
use crate::canvas::{View, shaded_region};
use crate::command::Command;
use crate::document::{Document, DocumentError, ExemplarRef, ModeSettings, RasterBrushItem};
use crate::panels::exemplar_picker::thumbnail_grid_ui;
use crate::state::Caches;

/// Largest thumbnail, points; each keeps its exemplar's proportions.
const THUMBNAIL: egui::Vec2 = egui::vec2(110.0, 34.0);
/// Room between a thumbnail and its frame, points.
const THUMBNAIL_MARGIN: f32 = 2.0;
/// Where a raster pattern may not go: fold-overs of its ribbon and avoided areas.
pub const INVALID: Color32 = Color32::from_rgba_premultiplied(120, 60, 0, 70);
/// The outline of those areas.
const INVALID_EDGE: Color32 = Color32::from_rgb(235, 130, 20);

/// The raster brush's [`ModeUi`].
pub struct RasterBrushUi;

/// A raster-brush synthesis along one curve.
#[derive(Clone, Debug)]
pub struct RasterBrushJob {
    /// The smoothed curve, mm (shared with the app's cache).
    pub curve: Arc<Curve>,
    /// The exemplar.
    pub exemplar: Arc<RasterExemplar>,
    /// The areas to leave empty, mm (shared with the app's cache).
    pub avoid_mm: Arc<Region>,
    /// The settings.
    pub settings: Settings,
}

impl PartialEq for RasterBrushJob {
    fn eq(&self, other: &Self) -> bool {
        same(&self.curve, &other.curve)
            && self.settings == other.settings
            && same(&self.exemplar, &other.exemplar)
            && same(&self.avoid_mm, &other.avoid_mm)
    }
}

impl RasterBrushJob {
    /// Runs the raster brush.
    pub fn run(&self, control: &Control) -> Result<Product, RasterError> {
        let along = Along::Curve(Curve::clone(&self.curve));
        make_product(&self.exemplar, &along, &self.settings, &self.avoid_mm, control)
    }
}

/// One exemplar's thumbnail, its proportions kept; clicked to choose it.
fn thumbnail_ui(ui: &mut egui::Ui, env: &mut ModeEnv<'_>, r: &ExemplarRef) -> egui::Response {
    let (rect, response) =
        ui.allocate_exact_size(THUMBNAIL + egui::Vec2::splat(2.0 * THUMBNAIL_MARGIN), egui::Sense::click());
    let rect = rect.shrink(THUMBNAIL_MARGIN);
    let Ok(exemplar) = env.caches.raster_exemplar(env.doc, r) else {
        let font = egui::FontId::proportional(14.0);
        ui.painter().text(rect.center(), egui::Align2::CENTER_CENTER, "?", font, Color32::RED);
        return response;
    };
    let (w, h) = (exemplar.width() as f32, exemplar.height() as f32);
    let scale = (THUMBNAIL.x / w).min(THUMBNAIL.y / h);
    let texture = env.caches.texture(ui.ctx(), &exemplar.texture);
    let image = egui::Rect::from_center_size(rect.center(), egui::vec2(w * scale, h * scale));
    let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
    ui.painter().image(texture, image, uv, Color32::WHITE);
    response
}

/// The picker: built-in and imported raster exemplars, and "Import PNG…".
fn raster_picker_ui(ui: &mut egui::Ui, chosen: &mut ExemplarRef, env: &mut ModeEnv<'_>) {
    ui.label(RichText::new("Exemplar").strong());
    let mut refs: Vec<ExemplarRef> = BUILTIN_NAMES.iter().map(|n| ExemplarRef::Builtin(n.to_string())).collect();
    refs.extend(env.doc.imported_raster.iter().map(|e| ExemplarRef::Imported(e.name.clone())));
    thumbnail_grid_ui(ui, "raster exemplars", &refs, chosen, |ui, r| thumbnail_ui(ui, env, r));
    if ui.button(Command::ImportPng.label()).on_hover_text("Or drop a PNG with transparency on the window").clicked() {
        env.commands.push(Command::ImportPng);
    }
}

/// The ribbon's controls.
pub fn ribbon_ui(ui: &mut egui::Ui, s: &mut Settings) {
    ui.add(egui::Slider::new(&mut s.band_mm, 2.0..=40.0).text("Band width (mm)"));
    ui.add(egui::Slider::new(&mut s.step_mm, 0.5..=10.0).text("Step δ (mm)"))
        .on_hover_text("The width of each piece along the curve: smaller follows bends more closely, larger is faster");
    ui.add(egui::Slider::new(&mut s.scale, 0.2..=MAX_SCALE).text("Scale"))
        .on_hover_text("The pattern's height as a fraction of the band");
    ui.checkbox(&mut s.stitching, "Stitch seams")
        .on_hover_text("Bend each piece's pixels to meet the previous piece's edge");
    ui.add(egui::Slider::new(&mut s.variety, 0.0..=2.0).text("Variety"))
        .on_hover_text("Where the pattern jumps in the exemplar changes along the curve; 0 repeats the best jump");
    ui.horizontal(|ui| {
        let label = ui.label("Seed");
        ui.add(egui::DragValue::new(&mut s.seed)).labelled_by(label.id).on_hover_text("Another seed, another pattern");
    });
    ui.add(egui::Slider::new(&mut s.thickness_mm, 0.4..=10.0).text("Thickness (mm)"));
}

impl ModeUi for RasterBrushUi {
    fn name(&self) -> &'static str {
        "Raster brush"
    }

    fn default_settings(&self) -> ModeSettings {
        ModeSettings::RasterBrush(RasterBrushItem::default())
    }

    fn owns(&self, settings: &ModeSettings) -> bool {
        matches!(settings, ModeSettings::RasterBrush(_))
    }

    fn settings_ui(&self, ui: &mut egui::Ui, settings: &mut ModeSettings, env: &mut ModeEnv<'_>) {
        let ModeSettings::RasterBrush(item) = settings else { return };
        raster_picker_ui(ui, &mut item.exemplar, env);
        ui.separator();
        ui.label(RichText::new("Ribbon").strong());
        ribbon_ui(ui, &mut item.settings);
        ui.separator();
        ui.label(RichText::new("Avoided areas").strong());
        ui.label(RichText::new("Paint them with the Avoid tool; patterns leave them empty.").weak());
        if Command::ClearAvoided.button(ui, !env.doc.avoid.is_empty()) {
            env.commands.push(Command::ClearAvoided);
        }
    }

    fn overlays_ui(
        &self,
        painter: &egui::Painter,
        view: &View,
        rect: egui::Rect,
        product: &Product,
        toggles: OverlayToggles,
    ) {
        if toggles.invalid {
            let invalid = &product.overlays.avoided_mm;
            shaded_region(painter, view, rect, invalid, &fill_triangles(invalid), INVALID, INVALID_EDGE);
        }
        super::band_and_seams_ui(painter, view, rect, product, toggles);
    }

    fn job(
        &self,
        curve: &Arc<Curve>,
        settings: &ModeSettings,
        doc: &Document,
        caches: &mut Caches,
    ) -> Result<ModeJob, DocumentError> {
        let ModeSettings::RasterBrush(item) = settings else {
            return Err(DocumentError::Exemplar("not a raster-brush curve".into()));
        };
        let exemplar = caches.raster_exemplar(doc, &item.exemplar)?;
        let avoid_mm = caches.avoided(&doc.avoid).region.clone();
        Ok(ModeJob::RasterBrush(RasterBrushJob {
            curve: curve.clone(),
            exemplar,
            avoid_mm,
            settings: item.settings.clone(),
        }))
    }
}
