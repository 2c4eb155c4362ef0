//! Region fill in the app: a closed curve whose inside fills with a curve
//! texture, the curve exemplar picked from thumbnails, and the pen strokes
//! drawn inside it (which the fill grows around) gathered for its job.

use std::sync::Arc;

use egui::{Color32, RichText};
use tracery_core::DVec2;
use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::curve::Curve;
use tracery_core::geom::{Rect, Region, fill_triangles};
use tracery_core::region_fill::{
    BUILTIN_CURVES, CurveExemplar, CurvePath, Drawn, FillError, Settings, make_product_around, print_drawn,
    region_from_outlines,
};

use super::{ModeEnv, ModeJob, ModeUi, same};
use crate::canvas::{View, fill, polyline};
use crate::command::Command;
use crate::document::{Document, DocumentError, ExemplarRef, ModeSettings, RegionFillItem, inside};
use crate::panels::exemplar_picker::thumbnail_grid_ui;
use crate::state::Caches;

/// Thumbnail size, points.
const THUMBNAIL: egui::Vec2 = egui::vec2(110.0, 44.0);

/// Region fill's [`ModeUi`].
pub struct RegionFillUi;

/// A region fill: the outline, the exemplar, and the pen strokes drawn inside.
#[derive(Clone, Debug)]
pub struct RegionFillJob {
    /// The region's outline, mm (shared with the app's cache).
    pub outline: Arc<Curve>,
    /// The curve exemplar.
    pub exemplar: Arc<CurveExemplar>,
    /// Pen strokes and filled shapes inside the region, mm.
    pub drawn: Arc<Drawn>,
    /// The settings.
    pub settings: Settings,
    /// Whether the region is filled around the strokes, or only they print.
    pub fill_automatically: bool,
}

impl PartialEq for RegionFillJob {
    fn eq(&self, other: &Self) -> bool {
        same(&self.outline, &other.outline)
            && same(&self.exemplar, &other.exemplar)
            && same(&self.drawn, &other.drawn)
            && self.settings == other.settings
            && self.fill_automatically == other.fill_automatically
    }
}

impl RegionFillJob {
    /// The region inside the outline, mm.
    pub fn region(&self) -> Result<Region, FillError> {
        region_from_outlines(&[self.outline.points().to_vec()])
    }

    /// Fills the region, or prints the strokes alone.
    pub fn run(&self, control: &Control) -> Result<Product, FillError> {
        let region = self.region()?;
        if self.fill_automatically {
            make_product_around(&self.exemplar, &region, &self.drawn, &self.settings, control)
        } else {
            print_drawn(&region, &self.drawn, &self.settings, control)
        }
    }
}

/// What was drawn with the pen in the fill with smoothed outline
/// `outline`, mm: strokes as smoothed paths, and filled shapes.
pub fn drawn_in(outline: &[DVec2], doc: &Document, caches: &Caches) -> Drawn {
    let mut drawn = Drawn::default();
    for c in &doc.curves {
        let ModeSettings::Pen(pen) = &c.mode else { continue };
        let Some(curve) = caches.smoothed(c.id).filter(|curve| inside(outline, curve.points())) else { continue };
        if pen.fills(curve.is_closed()) {
            // A shape that does not close on itself has nothing to fill.
            if let Ok(shape) = region_from_outlines(&[curve.points().to_vec()]) {
                drawn.shapes.extend(shape.polygons);
            }
        } else {
            drawn.paths.push(CurvePath { points_mm: curve.points().to_vec(), closed: curve.is_closed() });
        }
    }
    drawn
}

/// One curve exemplar's thumbnail; clicked to choose it.
fn thumbnail_ui(ui: &mut egui::Ui, env: &mut ModeEnv<'_>, r: &ExemplarRef) -> egui::Response {
    let (response, painter) = ui.allocate_painter(THUMBNAIL, egui::Sense::click());
    let rect = response.rect.shrink(3.0);
    let ink = if ui.visuals().dark_mode { Color32::from_gray(220) } else { Color32::from_gray(30) };
    let Some(bounds) = env
        .caches
        .curve_exemplar(env.doc, r)
        .ok()
        .and_then(|e| Rect::from_points(e.paths.iter().flat_map(|p| p.points_mm.iter().copied())).map(|b| (e, b)))
    else {
        painter.text(rect.center(), egui::Align2::CENTER_CENTER, "?", egui::FontId::proportional(14.0), Color32::RED);
        return response;
    };
    let (exemplar, b) = bounds;
    let scale = (rect.width() / b.width() as f32).min(rect.height() / b.height() as f32);
    let view = View { center_mm: [b.center().x, b.center().y], points_per_mm: scale };
    for path in &exemplar.paths {
        painter.add(polyline(&view, rect, &path.points_mm, path.closed, egui::Stroke::new(1.0, ink)));
    }
    // Filled shapes (the berries) filled, as the fill draws its elements.
    let shapes = Region::new(exemplar.shapes.iter().map(|s| s.polygon.clone()).collect());
    if !shapes.is_empty() {
        painter.add(fill(&view, rect, &fill_triangles(&shapes), ink));
    }
    response.on_hover_text(r.name())
}

impl ModeUi for RegionFillUi {
    fn name(&self) -> &'static str {
        "Region fill"
    }

    fn default_settings(&self) -> ModeSettings {
        ModeSettings::RegionFill(RegionFillItem::default())
    }

    fn owns(&self, settings: &ModeSettings) -> bool {
        matches!(settings, ModeSettings::RegionFill(_))
    }

    fn settings_ui(&self, ui: &mut egui::Ui, settings: &mut ModeSettings, env: &mut ModeEnv<'_>) {
        let ModeSettings::RegionFill(item) = settings else { return };
        ui.label(RichText::new("Curve exemplar").strong());
        let mut refs: Vec<ExemplarRef> = BUILTIN_CURVES.iter().map(|n| ExemplarRef::Builtin(n.to_string())).collect();
        // Imported drawings that read as curves (an SVG imported for the
        // vector brush may not).
        let imported: Vec<ExemplarRef> =
            env.doc.imported.iter().map(|e| ExemplarRef::Imported(e.name.clone())).collect();
        refs.extend(imported.into_iter().filter(|r| env.caches.curve_exemplar(env.doc, r).is_ok()));
        thumbnail_grid_ui(ui, "curve exemplars", &refs, &mut item.exemplar, |ui, r| thumbnail_ui(ui, env, r));
        if ui
            .button(Command::ImportSvg.label())
            .on_hover_text("Your own drawing's strokes: or drop an SVG file on the window")
            .clicked()
        {
            env.commands.push(Command::ImportSvg);
        }
        ui.label(RichText::new("Draw a closed outline with the Draw tool; its inside fills.").weak());
        ui.separator();
        let s = &mut item.settings;
        ui.checkbox(&mut item.fill_automatically, "Fill automatically")
            .on_hover_text("Off: only your pen strokes print, and autocomplete suggests more as you draw them");
        ui.add(egui::Slider::new(&mut s.exemplar_scale, 0.05..=4.0).logarithmic(true).text("Exemplar scale"))
            .on_hover_text("Draws the exemplar larger or smaller before the fill learns from it");
        ui.add(egui::Slider::new(&mut s.delta_mm, 0.8..=4.0).text("Spacing δ (mm)"))
            .on_hover_text("Samples along the curves: smaller follows the exemplar more closely, larger is faster");
        ui.add(egui::Slider::new(&mut s.stroke_width_mm, 0.3..=3.0).text("Stroke width (mm)"));
        ui.add(egui::Slider::new(&mut s.frame_mm, 0.0..=5.0).text("Frame (mm)"))
            .on_hover_text("A border along the outline, united with the strokes");
        ui.add(egui::Slider::new(&mut s.thickness_mm, 0.4..=10.0).text("Thickness (mm)"));
        ui.checkbox(&mut s.one_piece, "One piece").on_hover_text("Join every stroke to the rest with bridges");
        ui.horizontal(|ui| {
            let label = ui.label("Seed");
            ui.add(egui::DragValue::new(&mut s.seed)).labelled_by(label.id).on_hover_text("Another seed, another fill");
        });
    }

    fn job(
        &self,
        curve: &Arc<Curve>,
        settings: &ModeSettings,
        doc: &Document,
        caches: &mut Caches,
    ) -> Result<ModeJob, DocumentError> {
        let ModeSettings::RegionFill(item) = settings else {
            return Err(DocumentError::Exemplar("not a region fill".into()));
        };
        let exemplar = caches.curve_exemplar(doc, &item.exemplar)?;
        let drawn = Arc::new(drawn_in(curve.points(), doc, caches));
        Ok(ModeJob::RegionFill(RegionFillJob {
            outline: curve.clone(),
            exemplar,
            drawn,
            settings: item.settings.clone(),
            fill_automatically: item.fill_automatically,
        }))
    }
}
