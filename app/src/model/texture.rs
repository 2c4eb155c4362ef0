//! Texture over the whole model (mesh quilting): its job, its controls in
//! the model panel, and its line in the status bar, with progress and a
//! way to stop it.

use std::sync::Arc;

use egui::RichText;
use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::mesh_quilt::{
    Direction, GuidanceField, MAX_SINK_MM, QuiltError, SWATCH_NAMES, Settings, Swatch, make_surface_product,
};
use tracery_core::surface::SurfaceMesh;

use crate::TraceryApp;
use crate::modes::same;
use crate::panels::status::job_state_ui;
use crate::worker::{Job, JobState};

/// The texture's slot in its worker, and its id among the object's parts
/// (curve and shade ids count up from 1, so they never reach it).
pub const TEXTURE: u64 = u64::MAX;

/// The model covered with texture grown from a swatch.
// Not `Debug`: the model's BVH has no useful text form.
#[derive(Clone)]
pub struct TextureJob {
    /// The model (shared with the app's cache; compared by identity).
    pub surface: Arc<SurfaceMesh>,
    /// The swatch, at scale 1.
    pub swatch: Arc<Swatch>,
    /// The settings.
    pub settings: Settings,
    /// The curves drawn on the model, as strokes the texture follows when
    /// it runs along curves (empty otherwise, so that drawing does not
    /// restart a texture that ignores them).
    pub strokes_mm: Vec<Vec<[f64; 3]>>,
}

impl PartialEq for TextureJob {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.surface, &other.surface)
            && self.settings == other.settings
            && self.strokes_mm == other.strokes_mm
            && same(&self.swatch, &other.swatch)
    }
}

impl Job for TextureJob {
    type Output = Product;
    type Error = QuiltError;

    fn run(&self, control: &Control) -> Result<Product, QuiltError> {
        // Cheap next to the quilting.
        let field = GuidanceField::of(&self.surface, self.settings.direction, &self.strokes_mm)?;
        make_surface_product(&self.swatch, &self.surface, &field, &self.settings, control)
    }
}

/// Asks for the texture when it is on, and forgets it when it is off (which
/// stops a job that is running); returns whether it is being made.
pub fn submit_texture(app: &mut TraceryApp, now: std::time::Instant) -> bool {
    let texture = &app.doc.model.texture;
    let base = app.doc.model.base.clone();
    match (texture.on, app.caches.model(&app.doc.model, &base), app.caches.swatch(&texture.swatch)) {
        (true, Ok(model), Ok(swatch)) => {
            let strokes_mm = match texture.settings.direction {
                Direction::AlongCurves => app.doc.model.texture_strokes_mm(),
                _ => Vec::new(),
            };
            let job =
                TextureJob { surface: model.surface.clone(), swatch, settings: texture.settings.clone(), strokes_mm };
            app.texture_worker.want(TEXTURE, job, now);
        }
        (true, Ok(_), Err(e)) => {
            app.message = Some((e, true));
            app.texture_worker.retain(&[]);
        }
        _ => app.texture_worker.retain(&[]),
    }
    app.texture_worker.poll(now)
}

/// The texture's controls in the model panel.
pub fn texture_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.label(RichText::new("Texture").strong());
    let mut item = app.doc.model.texture.clone();
    let turned_on = ui
        .checkbox(&mut item.on, "Cover the model with texture")
        .on_hover_text("3D detail grown over the whole model from a small swatch (mesh quilting)")
        .changed()
        && item.on;
    // Editable while off too: choose first, then turn it on.
    ui.horizontal(|ui| {
        let label = ui.label("Swatch");
        let combo = egui::ComboBox::from_id_salt("swatch").selected_text(item.swatch.clone()).show_ui(ui, |ui| {
            for name in SWATCH_NAMES {
                ui.selectable_value(&mut item.swatch, name.to_string(), name.to_string());
            }
        });
        combo.response.labelled_by(label.id);
    });
    let s = &mut item.settings;
    ui.add(egui::Slider::new(&mut s.scale, 0.3..=4.0).logarithmic(true).text("Scale"))
        .on_hover_text("The swatch made this many times larger; smaller is finer and slower");
    ui.horizontal(|ui| {
        let label = ui.label("Runs");
        ui.selectable_value(&mut s.direction, Direction::AroundAxis, "around")
            .on_hover_text("The swatch's rows run around the model's axis, as rings round a vase")
            .labelled_by(label.id);
        ui.selectable_value(&mut s.direction, Direction::AlongAxis, "up")
            .on_hover_text("The swatch's rows run up the model, from its foot to its top");
        ui.selectable_value(&mut s.direction, Direction::AlongCurves, "along curves").on_hover_text(
            "The swatch's rows follow the curves drawn on the model, in the direction each was drawn, \
             blended between them",
        );
    });
    ui.add(egui::Slider::new(&mut s.sink_mm, 0.0..=MAX_SINK_MM).text("Sink (mm)"))
        .on_hover_text("How deep the texture sits in the model, so that the two print as one body");
    ui.horizontal(|ui| {
        let label = ui.label("Seed");
        ui.add(egui::DragValue::new(&mut s.seed)).labelled_by(label.id).on_hover_text("Another seed, another texture");
    });
    if turned_on {
        // United with the model, the texture prints as one body with it.
        app.doc.model.with_model = true;
    }
    if item != app.doc.model.texture {
        app.doc.model.texture = item;
    }
}

/// The texture's line in the status bar, with *Stop* while it is made.
pub fn texture_status_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    if !app.doc.model.texture.on {
        return;
    }
    ui.separator();
    job_state_ui(ui, "Texture", app.texture_worker.state(TEXTURE), "Growing the texture…", |product| {
        let count = |name| product.facts.count(name).unwrap_or(0);
        format!("{} elements, {} faces, {} patches", count("elements"), count("faces"), count("patches"))
    });
    // Stale: waiting to start, or running.
    if app.texture_worker.is_stale(TEXTURE)
        && ui.button("Stop").on_hover_text("Stop growing the texture and turn it off").clicked()
    {
        app.doc.model.texture.on = false;
        app.message = Some(("Texture stopped and turned off; turn it on to grow it again".into(), false));
    }
}

impl TraceryApp {
    /// Where the texture over the model stands.
    pub fn texture_state(&self) -> Option<&JobState<Product, QuiltError>> {
        self.texture_worker.state(TEXTURE)
    }
}
