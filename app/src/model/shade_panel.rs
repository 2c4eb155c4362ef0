//! Lamp shades in the model workspace: the list, *Add shade* (standing on
//! the model's top, so that the model is its foot), and the selected
//! shade's shape and place.

use egui::RichText;
use tracery_core::surface::{Shade, SurfaceMesh};

use crate::TraceryApp;
use crate::document::ShadeItem;

/// How far a new shade's bottom rim reaches down into the model's top, and
/// inside its edge, mm: the two then overlap, so the lamp is one body.
const FOOT_OVERLAP_MM: f64 = 1.0;

/// Smallest radius a new shade gets where the model ends in a point, mm.
const MIN_NEW_RADIUS_MM: f64 = 10.0;

/// A new shade's top radius over its bottom radius: a tulip over the foot.
const NEW_FLARE: f64 = 2.5;

/// A new shade's height, mm.
const NEW_HEIGHT_MM: f64 = 50.0;

/// A new shade standing on the top of `model`: its bottom rim sunk into the
/// model's top rim, widening upward.
pub fn shade_on_top(model: &SurfaceMesh) -> ShadeItem {
    let top_mm = model.positions().iter().map(|p| p.z).fold(f64::MIN, f64::max);
    // The model's radius at its top, from the vertices within a hair of it.
    let top_radius_mm = model
        .positions()
        .iter()
        .filter(|p| p.z > top_mm - 1e-3 * model.size_mm())
        .map(|p| p.truncate().length())
        .fold(0.0, f64::max);
    let bottom = (top_radius_mm - FOOT_OVERLAP_MM).max(MIN_NEW_RADIUS_MM);
    let mut item = ShadeItem::default();
    item.shade.shade = Shade::cone(bottom, bottom * NEW_FLARE, NEW_HEIGHT_MM).unwrap_or_default();
    item.lift_mm = top_mm - FOOT_OVERLAP_MM;
    item
}

/// The list of shades and *Add shade*.
pub fn shades_list_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.label(RichText::new("Shades").strong());
    let mut clicked = None;
    for item in &app.doc.model.shades {
        let s = &item.shade.shade;
        // Plain characters: the UI font has no arrow.
        let text = format!(
            "Shade {} — r {:.0} to {:.0}, {:.0} mm high",
            item.id, s.bottom_radius_mm, s.top_radius_mm, s.height_mm
        );
        if ui.selectable_label(app.selected_surface == Some(item.id), text).clicked() {
            clicked = Some(item.id);
        }
    }
    if let Some(id) = clicked {
        app.selected_surface = Some(id);
    }
    let add = ui.button("Add shade").on_hover_text("A lamp shade standing on the model's top: the model is its foot");
    if add.clicked() {
        let base = app.doc.model.base.clone();
        let item = match app.caches.model(&app.doc.model, &base) {
            Ok(model) => shade_on_top(&model.surface),
            Err(_) => ShadeItem::default(),
        };
        let id = app.doc.add_shade(item);
        // Standing on the model, the shade needs it as its foot.
        app.doc.model.with_model = true;
        app.selected_surface = Some(id);
        app.message = Some((format!("Shade {id} added on the {}", base.name()), false));
    }
}

/// The shape and place of the shade with `id`, then its rows' brush.
pub fn shade_settings_ui(app: &mut TraceryApp, ui: &mut egui::Ui, id: u64) {
    let Some(mut item) = app.doc.model.shade(id).cloned() else { return };
    ui.label(RichText::new(format!("Shade {id}")).strong());
    let shade = &mut item.shade;
    let s = &mut shade.shade;
    let radius = 5.0..=200.0;
    ui.add(egui::Slider::new(&mut s.bottom_radius_mm, radius.clone()).text("Bottom radius (mm)"));
    ui.add(egui::Slider::new(&mut s.top_radius_mm, radius).text("Top radius (mm)"));
    ui.add(egui::Slider::new(&mut s.height_mm, 10.0..=300.0).text("Height (mm)"));
    ui.add(egui::Slider::new(&mut shade.rim_mm, 0.0..=10.0).text("Rims (mm)"))
        .on_hover_text("Solid rings at the top and the bottom; 0 for none");
    ui.add(egui::Slider::new(&mut item.lift_mm, -50.0..=300.0).text("Lift (mm)"))
        .on_hover_text("Height of the bottom rim above the model's base");
    super::panel::brush_ui(app, ui, &mut item.exemplar, &mut item.settings);
    if let Some(stored) = app.doc.model.shade_mut(id)
        && *stored != item
    {
        *stored = item;
    }
}
