//! The top bar: the app's name, view toggles and the project's file name.

use egui::RichText;

use crate::TraceryApp;
use crate::state::Workspace;

/// The top bar.
pub fn top_bar_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.horizontal(|ui| {
        ui.heading("Tracery");
        ui.label(RichText::new("pattern brush").weak());
        ui.separator();
        ui.selectable_value(&mut app.state.workspace, Workspace::Canvas, "Canvas")
            .on_hover_text("Draw curves on a flat canvas");
        ui.selectable_value(&mut app.state.workspace, Workspace::Model, "3D model")
            .on_hover_text("Pick curves on a 3D model: a vase, an egg, a lamp, or a model of your own");
        ui.separator();
        if app.state.workspace == Workspace::Model {
            show_project(app, ui);
            return;
        }
        ui.checkbox(&mut app.state.show_band, "Band outline");
        ui.checkbox(&mut app.state.show_seams, "Piece seams");
        ui.checkbox(&mut app.state.show_invalid, "Invalid areas")
            .on_hover_text("Where a raster pattern may not go: fold-overs of its ribbon and avoided areas");
        ui.checkbox(&mut app.state.show_3d, "3D preview");
        ui.checkbox(&mut app.state.show_gallery, "Solutions");
        show_project(app, ui);
    });
}

fn show_project(app: &TraceryApp, ui: &mut egui::Ui) {
    if let Some(p) = &app.state.project_path {
        ui.separator();
        ui.label(RichText::new(p.display().to_string()).weak());
    }
}
