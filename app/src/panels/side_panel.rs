//! The side panel: tools, the mode and its settings, files.

use egui::RichText;

use crate::TraceryApp;
use crate::modes::{ModeEnv, REGISTRY, mode_ui};
use crate::tools::Tool;

/// The side panel.
pub fn side_panel_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.horizontal(|ui| {
        for tool in Tool::ALL {
            ui.selectable_value(&mut app.state.tool, tool, tool.label());
        }
    });
    if app.state.tool == Tool::Avoid {
        ui.add(egui::Slider::new(&mut app.state.avoid_width_mm, 1.0..=40.0).text("Brush width (mm)"))
            .on_hover_text("Paint areas that raster patterns leave empty; undo takes a stroke back");
    }
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
