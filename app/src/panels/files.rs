//! The files section: open, save, export, quick export, undo and delete.

use std::path::PathBuf;

use egui::RichText;
use tracery_core::export::{SvgFlavour, SvgOptions};

use crate::TraceryApp;
use crate::command::Command;

/// Width of the export folder field, points.
const FOLDER_FIELD_WIDTH: f32 = 150.0;

/// The files section of the side panel.
pub fn files_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.label(RichText::new("Files").strong());
    ui.horizontal_wrapped(|ui| {
        for command in [Command::Open, Command::SaveAs, Command::ExportStl, Command::Export3mf, Command::ExportSvg] {
            if command.button(ui, true) {
                app.queue(command);
            }
        }
    });
    match app.state.workspace {
        crate::state::Workspace::Canvas => {
            ui.checkbox(&mut app.state.export_selected_only, "Export the selected curve only");
        }
        crate::state::Workspace::Model => {
            ui.label("Exports one object: every curve and shade, with the model where it is part of it");
        }
    }
    svg_options_ui(ui, &mut app.state.svg);
    ui.horizontal(|ui| {
        if ui
            .button(Command::QuickExport.label())
            .on_hover_text("Writes STL, 3MF and SVG into the folder below, without a dialog")
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

/// The SVG's purpose (engrave or cut) and the laser's kerf.
fn svg_options_ui(ui: &mut egui::Ui, options: &mut SvgOptions) {
    ui.horizontal(|ui| {
        ui.label("SVG for");
        for (flavour, name, hint) in [
            (SvgFlavour::Engrave, "engraving", "Filled shapes"),
            (SvgFlavour::Cut, "cutting", "Hairline outlines in red, holes before the outline around them"),
        ] {
            let selected = options.flavour == flavour;
            let response = ui.selectable_label(selected, name).on_hover_text(hint);
            if response.clicked() {
                options.flavour = flavour;
            }
        }
    });
    if options.flavour == SvgFlavour::Cut {
        ui.horizontal(|ui| {
            let label = ui.label("Kerf");
            let field = egui::DragValue::new(&mut options.kerf_mm).range(0.0..=2.0).speed(0.01).suffix(" mm");
            ui.add(field).labelled_by(label.id).on_hover_text("Outlines move out and holes move in by half the kerf");
        });
    }
}
