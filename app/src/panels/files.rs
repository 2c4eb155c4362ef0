//! The files section: open, save, export, quick export, undo and delete.

use std::path::PathBuf;

use egui::RichText;

use crate::TraceryApp;
use crate::command::Command;

/// Width of the export folder field, points.
const FOLDER_FIELD_WIDTH: f32 = 150.0;

/// The files section of the side panel.
pub fn files_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.label(RichText::new("Files").strong());
    ui.horizontal_wrapped(|ui| {
        for command in [Command::Open, Command::SaveAs, Command::ExportStl, Command::ExportSvg] {
            if command.button(ui, true) {
                app.queue(command);
            }
        }
    });
    ui.checkbox(&mut app.state.export_selected_only, "Export the selected curve only");
    ui.horizontal(|ui| {
        if ui
            .button(Command::QuickExport.label())
            .on_hover_text("Writes STL and SVG into the folder below, without a dialog")
            .clicked()
        {
            app.queue(Command::QuickExport);
        }
        let mut folder = app.state.export_folder.display().to_string();
        let label = ui.label("to");
        let field = egui::TextEdit::singleline(&mut folder).desired_width(FOLDER_FIELD_WIDTH);
        if ui.add(field).labelled_by(label.id).changed() {
            app.state.export_folder = PathBuf::from(folder);
        }
    });
    ui.horizontal(|ui| {
        let enabled = [app.history.can_undo(), app.history.can_redo(), app.selected.is_some()];
        for (command, enabled) in [Command::Undo, Command::Redo, Command::Delete].into_iter().zip(enabled) {
            if command.button(ui, enabled) {
                app.queue(command);
            }
        }
    });
}
