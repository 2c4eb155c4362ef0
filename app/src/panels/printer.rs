//! The printer section: the document's nozzle and layer height, thickening,
//! the weak-bridge limit, and what the check found for the selected curve.

use egui::RichText;
use tracery_core::print::PrintSettings;

use crate::TraceryApp;

/// The printer section of the side panel.
pub fn printer_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.label(RichText::new("Printer").strong());
    let mut print: PrintSettings = app.doc.print;
    egui::Grid::new("printer").num_columns(2).show(ui, |ui| {
        let label = ui.label("Nozzle");
        ui.add(egui::DragValue::new(&mut print.nozzle_mm).range(0.1..=2.0).speed(0.01).suffix(" mm"))
            .labelled_by(label.id)
            .on_hover_text("Features thinner and gaps narrower than the nozzle are highlighted");
        ui.end_row();
        let label = ui.label("Layer height");
        let top = print.nozzle_mm.max(0.01);
        ui.add(egui::DragValue::new(&mut print.layer_height_mm).range(0.01..=top).speed(0.01).suffix(" mm"))
            .labelled_by(label.id);
        ui.end_row();
        let label = ui.label("Weak bridge below");
        ui.add(egui::DragValue::new(&mut print.bridge_nozzles).range(0.0..=10.0).speed(0.05).suffix(" × nozzle"))
            .labelled_by(label.id)
            .on_hover_text("Material across a seam between two pieces narrower than this is flagged");
        ui.end_row();
    });
    ui.checkbox(&mut print.thicken, "Thicken thin features")
        .on_hover_text("Grows every feature thinner than the nozzle to its width; the topology is counted again");
    if print != app.doc.print {
        app.doc.print = print;
    }
    ui.checkbox(&mut app.state.show_print_flaws, "Highlight flaws");
    let found = app
        .selected
        .or(app.doc.curves.last().map(|c| c.id))
        .and_then(|id| app.output(id))
        .and_then(|p| p.printability.clone());
    if let Some(found) = found {
        let mm = |x: Option<f64>| x.map_or_else(|| "none".to_string(), |w| format!("{w:.2} mm"));
        ui.label(format!(
            "Thinnest feature under the nozzle: {} ({})",
            mm(found.thinnest_feature_mm),
            found.thin_features.len()
        ));
        ui.label(format!(
            "Narrowest gap under the nozzle: {} ({})",
            mm(found.narrowest_gap_mm),
            found.narrow_gaps.len()
        ));
        ui.label(format!("Weak bridges: {}", found.weak_bridges.len()));
    }
}
