//! The top bar: the app's name, view toggles and the project's file name.

use egui::RichText;

use crate::TraceryApp;

/// The top bar.
pub fn top_bar_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.horizontal(|ui| {
        ui.heading("Tracery");
        ui.label(RichText::new("pattern brush").weak());
        ui.separator();
        ui.checkbox(&mut app.state.show_band, "Band outline");
        ui.checkbox(&mut app.state.show_seams, "Piece seams");
        ui.checkbox(&mut app.state.show_invalid, "Invalid areas")
            .on_hover_text("Where a raster pattern may not go: fold-overs of its ribbon and avoided areas");
        ui.checkbox(&mut app.state.show_3d, "3D preview");
        ui.checkbox(&mut app.state.show_gallery, "Solutions");
        if let Some(p) = &app.state.project_path {
            ui.separator();
            ui.label(RichText::new(p.display().to_string()).weak());
        }
    });
}
