//! The model workspace's side panel (the model, the curves on it, and the
//! selected curve's settings) and its status line.

use egui::RichText;
use tracery_core::mesh_quilt::Direction;
use tracery_core::surface::{BASE_NAMES, SurfaceOutput};
use tracery_core::vector_brush::Settings;

use crate::TraceryApp;
use crate::command::Command;
use crate::document::{BaseRef, ExemplarRef, ModeSettings, SurfaceCurveItem, VectorBrushItem};
use crate::model::ASSEMBLY;
use crate::model::shade_panel::{shade_settings_ui, shades_list_ui};
use crate::modes::vector_brush::VectorBrushUi;
use crate::modes::{ModeEnv, ModeUi};
use crate::panels::status::{ERROR, WARNING, job_state_ui};
use crate::worker::JobState;

/// The side panel of the model workspace.
pub fn model_panel_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.label(RichText::new("Model").strong());
    let mut base = app.doc.model.base.clone();
    ui.horizontal(|ui| {
        let label = ui.label("Shape");
        let combo =
            egui::ComboBox::from_id_salt("model base").selected_text(base.name().to_string()).show_ui(ui, |ui| {
                for name in BASE_NAMES {
                    ui.selectable_value(&mut base, BaseRef::Builtin(name.to_string()), name);
                }
                for m in &app.doc.model.imported {
                    ui.selectable_value(&mut base, BaseRef::Imported(m.name.clone()), &m.name);
                }
            });
        combo.response.labelled_by(label.id);
        if Command::ImportModel.button(ui, true) {
            app.queue(Command::ImportModel);
        }
    });
    ui.checkbox(&mut app.doc.model.with_model, "Print the model too").on_hover_text(
        "The model is part of the exported object, as a lamp's foot, even where no curve is embossed on it",
    );
    if base != app.doc.model.base {
        // Curves keep their points: they snap onto the new model.
        app.doc.model.base = base;
    }
    ui.separator();
    super::texture::texture_ui(app, ui);
    ui.separator();
    ui.label(RichText::new("Curves on the model").strong());
    let mut clicked = None;
    for item in &app.doc.model.curves {
        let n = item.surface.points_mm.len();
        let guide = if item.guide { ", a guide" } else { "" };
        let text = format!("Curve {} — {n} point{}{guide}", item.id, if n == 1 { "" } else { "s" });
        if ui.selectable_label(app.selected_surface == Some(item.id), text).clicked() {
            clicked = Some(item.id);
        }
    }
    if let Some(id) = clicked {
        app.selected_surface = Some(id);
    }
    ui.horizontal(|ui| {
        if ui.button("New curve").on_hover_text("The next click on the model starts a new curve").clicked() {
            app.selected_surface = None;
        }
        let selected = app.selected_surface;
        let has_points =
            selected.and_then(|id| app.doc.model.curve(id)).is_some_and(|c| !c.surface.points_mm.is_empty());
        if ui.add_enabled(has_points, egui::Button::new("Remove last point")).clicked()
            && let Some(item) = selected.and_then(|id| app.doc.model.curve_mut(id))
        {
            item.surface.points_mm.pop();
        }
        if Command::Delete.button(ui, selected.is_some()) {
            app.queue(Command::Delete);
        }
    });
    ui.label(
        RichText::new(match app.selected_surface.filter(|id| app.doc.model.curve(*id).is_some()) {
            Some(id) => format!("Click on the model to add points to Curve {id}"),
            None => "Click on the model to start a curve".to_string(),
        })
        .weak(),
    );
    ui.separator();
    shades_list_ui(app, ui);
    ui.separator();
    if let Some(id) = app.selected_surface.filter(|id| app.doc.model.shade(*id).is_some()) {
        shade_settings_ui(app, ui, id);
        return;
    }
    let mut item = match app.selected_surface.and_then(|id| app.doc.model.curve(id)) {
        Some(item) => item.clone(),
        None => app.state.new_surface_curve.clone(),
    };
    ui.label(
        RichText::new(match app.selected_surface {
            Some(id) => format!("Curve {id}"),
            None => "New curves".to_string(),
        })
        .strong(),
    );
    surface_settings_ui(ui, &mut item);
    // A guide's pattern settings are kept, for when it carries one again.
    if !item.guide {
        brush_ui(app, ui, &mut item.exemplar, &mut item.settings);
    }
    match app.selected_surface.and_then(|id| app.doc.model.curve_mut(id)) {
        Some(stored) if *stored != item => *stored = item,
        Some(_) => {}
        None if app.state.new_surface_curve != item => app.state.new_surface_curve = item,
        None => {}
    }
}

/// The vector brush's own exemplar and pattern controls, for a curve or a
/// shade's rows.
pub(super) fn brush_ui(app: &mut TraceryApp, ui: &mut egui::Ui, exemplar: &mut ExemplarRef, settings: &mut Settings) {
    let mut mode =
        ModeSettings::VectorBrush(VectorBrushItem { exemplar: exemplar.clone(), settings: settings.clone() });
    let mut commands = Vec::new();
    let mut env = ModeEnv { doc: &app.doc, caches: &mut app.caches, commands: &mut commands };
    VectorBrushUi.settings_ui(ui, &mut mode, &mut env);
    if let ModeSettings::VectorBrush(v) = mode {
        *exemplar = v.exemplar;
        *settings = v.settings;
    }
    // "Another one" picks the next alternative of a canvas curve; here it
    // is the seed that changes the pattern.
    for command in commands {
        match command {
            Command::AnotherOne => settings.seed = settings.seed.wrapping_add(1),
            other => app.queue(other),
        }
    }
}

/// What a curve makes: one of the surface's outputs, or nothing but a
/// guide for the texture.
#[derive(Clone, Copy, PartialEq)]
enum Make {
    Output(SurfaceOutput),
    Guide,
}

/// What is made, and how the band lies on the surface.
fn surface_settings_ui(ui: &mut egui::Ui, item: &mut SurfaceCurveItem) {
    let s = &mut item.surface;
    ui.checkbox(&mut s.closed, "Closed curve (a ring back to the first point)");
    let mut make = if item.guide { Make::Guide } else { Make::Output(s.output) };
    ui.horizontal(|ui| {
        let label = ui.label("Make");
        ui.selectable_value(&mut make, Make::Output(SurfaceOutput::Pattern), "pattern")
            .on_hover_text(
                "The pattern alone, a shell lying on the model; \
                 sunk into it like emboss when the object holds the model (a texture, another embossed curve)",
            )
            .labelled_by(label.id);
        ui.selectable_value(&mut make, Make::Output(SurfaceOutput::Emboss), "emboss")
            .on_hover_text("The pattern united with the model into one solid");
        ui.selectable_value(&mut make, Make::Output(SurfaceOutput::Carve), "carve")
            .on_hover_text("The pattern cut out of the model hollowed to a shell");
        ui.selectable_value(&mut make, Make::Guide, "guide")
            .on_hover_text("No pattern: the curve only guides the texture's rows, when they run along curves");
    });
    match make {
        Make::Guide => item.guide = true,
        Make::Output(output) => {
            item.guide = false;
            s.output = output;
        }
    }
    if item.guide {
        return;
    }
    if s.output == SurfaceOutput::Carve {
        ui.add(egui::Slider::new(&mut s.wall_mm, 0.8..=6.0).text("Wall (mm)"));
    }
    ui.add(egui::Slider::new(&mut s.twist_deg, -90.0..=90.0).text("Twist (°)"))
        .on_hover_text("Turns the band about the curve; 0 lies on the surface");
}

/// The status line of the model workspace, about the selected curve (or the last one).
pub fn model_status_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    part_status_ui(app, ui);
    super::texture::texture_status_ui(app, ui);
    object_status_ui(app, ui);
}

/// The selected curve's or shade's status (or the last curve's).
fn part_status_ui(app: &TraceryApp, ui: &mut egui::Ui) {
    let focus = app.selected_surface.or_else(|| app.doc.model.curves.last().map(|c| c.id));
    if let Some(id) = focus.filter(|id| app.doc.model.shade(*id).is_some()) {
        let running = format!("Making shade {id}…");
        job_state_ui(ui, &format!("Shade {id}"), app.shade_worker.state(id), &running, |product| {
            let t = &product.topology;
            let rows = product.facts.count("rows").unwrap_or(0);
            let triangles = product.mesh_mm.as_ref().map_or(0, |m| m.triangles.len());
            format!("{rows} rows, {} component(s), {} hole(s), {triangles} triangles", t.components, t.holes)
        });
        return;
    }
    let Some(item) = focus.and_then(|id| app.doc.model.curve(id)) else {
        ui.label(format!(
            "Click on the {} to pick the points of a curve; the pattern follows it",
            app.doc.model.base.name()
        ));
        return;
    };
    let id = item.id;
    if item.surface.points_mm.len() < tracery_core::surface::MIN_POINTS {
        ui.label(format!("Curve {id}: pick at least two points on the model"));
        return;
    }
    if item.guide {
        let texture = &app.doc.model.texture;
        ui.label(if texture.on && texture.settings.direction == Direction::AlongCurves {
            format!("Curve {id} guides the texture's rows")
        } else {
            format!("Curve {id} is a guide: the texture follows it when its rows run along curves")
        });
        return;
    }
    let running = format!("Synthesizing curve {id} on the model…");
    let shown = job_state_ui(ui, &format!("Curve {id}"), app.surface_worker.state(id), &running, |product| {
        let t = &product.topology;
        let triangles = product.mesh_mm.as_ref().map_or(0, |m| m.triangles.len());
        format!("{} component(s), {} hole(s), {triangles} triangles", t.components, t.holes)
    });
    if !shown {
        ui.label("Ready");
    }
}

/// Where the object made of every curve and shade (and the model) stands,
/// with only the warnings the combining itself gave: each part's are on its own line.
fn object_status_ui(app: &TraceryApp, ui: &mut egui::Ui) {
    let holds_model = app.doc.model.holds_model();
    let curves = app.doc.model.drawn_curves().count();
    let parts = curves + app.doc.model.shades.len() + usize::from(app.doc.model.texture.on);
    if parts < 2 && !holds_model {
        return;
    }
    ui.separator();
    match (app.model_object(), app.assembly_worker.state(ASSEMBLY)) {
        (Some(object), _) => {
            let bodies = object.facts.count("shells").unwrap_or(0);
            let triangles = object.mesh_mm.as_ref().map_or(0, |m| m.triangles.len());
            let ms: f64 = ["hollow", "unite", "carve"].iter().filter_map(|s| object.timings.stage_ms(s)).sum();
            ui.label(format!("Object: {bodies} body(ies), {triangles} triangles — combined in {ms:.0} ms"));
            let curves = app.doc.model.curves.iter().filter_map(|c| app.surface_worker.output(c.id));
            let shades = app.doc.model.shades.iter().filter_map(|c| app.shade_worker.output(c.id));
            let texture = app.doc.model.texture.on.then(|| app.texture_worker.output(super::TEXTURE)).flatten();
            let of_parts: Vec<_> = curves.chain(shades).chain(texture).collect();
            for w in object.warnings.iter().filter(|w| !of_parts.iter().any(|p| p.warnings.contains(w))) {
                ui.label(RichText::new(format!("Warning: {w}")).color(WARNING));
            }
        }
        (None, Some(JobState::Done(Err(e)))) if !app.assembly_worker.is_stale(ASSEMBLY) => {
            ui.label(RichText::new(format!("Object: {e}")).color(ERROR));
        }
        // Parts still being made show their own progress; the object waits for them.
        _ if parts > 0 && app.assembly_worker.is_stale(ASSEMBLY) => {
            ui.spinner();
            ui.label("Combining the curves with the model…");
        }
        _ => {}
    }
}
