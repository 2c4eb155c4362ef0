//! The side panel: tools, the mode and its settings, files.

use egui::RichText;

use crate::TraceryApp;
use crate::command::Command;
use crate::modes::{ModeEnv, REGISTRY, mode_ui};
use crate::predictions::PredictionKind;
use crate::tools::Tool;

/// The side panel.
pub fn side_panel_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.horizontal_wrapped(|ui| {
        for tool in Tool::ALL {
            ui.selectable_value(&mut app.state.tool, tool, tool.label());
        }
    });
    if app.state.tool == Tool::Avoid {
        ui.add(egui::Slider::new(&mut app.state.avoid_width_mm, 1.0..=40.0).text("Brush width (mm)"))
            .on_hover_text("Paint areas that raster patterns leave empty; undo takes a stroke back");
    }
    match app.state.tool {
        Tool::Pen => {
            ui.label(
                RichText::new(
                    "Draw in a region fill; with Fill automatically off, autocomplete continues your strokes.",
                )
                .weak(),
            );
        }
        Tool::Clone => {
            let step = if app.clone_source.is_none() {
                "Drag the source rectangle in a region fill."
            } else {
                "Drag or click where the copy goes."
            };
            ui.label(RichText::new(step).weak());
            if app.clone_source.is_some() && ui.button("New source").clicked() {
                app.clone_source = None;
            }
        }
        _ => {}
    }
    predictions_ui(app, ui);
    ui.separator();
    let editing = match app.selected {
        Some(id) => format!("Curve {id}"),
        None => "New curves".to_string(),
    };
    let mut settings = app.settings().clone();
    ui.label(RichText::new(editing).strong());
    ui.horizontal(|ui| {
        let label = ui.label("Mode");
        let current = mode_ui(&settings);
        let combo = egui::ComboBox::from_id_salt("mode").selected_text(current.name()).show_ui(ui, |ui| {
            for mode in REGISTRY {
                if ui.selectable_label(mode.owns(&settings), mode.name()).clicked() && !mode.owns(&settings) {
                    settings = mode.default_settings();
                }
            }
        });
        combo.response.labelled_by(label.id);
    });
    let mut commands = Vec::new();
    let mut env = ModeEnv { doc: &app.doc, caches: &mut app.caches, commands: &mut commands };
    mode_ui(&settings).settings_ui(ui, &mut settings, &mut env);
    // Edited on a copy: the document stays borrowable while the controls run.
    if settings != *app.settings() {
        *app.settings_mut() = settings;
    }
    for command in commands {
        app.queue(command);
    }
    ui.separator();
    super::jump_rings::jump_rings_ui(app, ui);
    ui.separator();
    super::printer::printer_ui(app, ui);
    ui.separator();
    super::files::files_ui(app, ui);
}

/// The predictions waiting for an answer: how many, and accept or reject.
fn predictions_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    let Some(predictions) = &app.predictions else { return };
    let what = match predictions.kind {
        PredictionKind::Autocomplete => "Autocomplete",
        PredictionKind::Clone => "Clone",
    };
    let picked = predictions.picked.len();
    ui.separator();
    ui.label(RichText::new(what).strong());
    let ready = app.predicted().map(|p| (p.paths.len(), p.elements.len()));
    match (ready, app.predictor.state(crate::predictions::PREDICTION_ID)) {
        (Some((n, 0)), _) => {
            ui.label(format!("{n} suggested path(s), {picked} picked; click a path to pick it"));
        }
        (Some((n, e)), _) => {
            ui.label(format!("{n} suggested path(s) and {e} element(s), {picked} picked; click one to pick it"));
        }
        (None, Some(crate::worker::JobState::Done(Err(e)))) => {
            ui.colored_label(ui.visuals().error_fg_color, e.to_string());
        }
        _ => {
            ui.horizontal(|ui| {
                ui.spinner();
                ui.label("Suggesting…");
            });
        }
    }
    ui.horizontal(|ui| {
        if Command::AcceptPredictions.button(ui, ready.is_some()) {
            app.queue(Command::AcceptPredictions);
        }
        if Command::AcceptPicked.button(ui, ready.is_some() && picked > 0) {
            app.queue(Command::AcceptPicked);
        }
        if ui.button(Command::RejectPredictions.label()).on_hover_text("Esc").clicked() {
            app.queue(Command::RejectPredictions);
        }
    });
}
