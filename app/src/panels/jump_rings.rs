//! The jump-ring section: rings for hanging the selected curve's piece.

use egui::RichText;
use tracery_core::print::{JumpRings, RingAt};

use crate::TraceryApp;
use crate::tools::Tool;

fn describe(at: &RingAt) -> String {
    match at {
        RingAt::Start => "at the start".into(),
        RingAt::End => "at the end".into(),
        RingAt::Top => "at the top".into(),
        RingAt::Point { x_mm, y_mm } => format!("at ({x_mm:.1}, {y_mm:.1}) mm"),
        _ => "somewhere".into(),
    }
}

/// The jump-ring section of the side panel (for the selected curve).
pub fn jump_rings_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.label(RichText::new("Jump rings").strong());
    let Some(item) = app.selected.and_then(|id| app.doc.curve(id)) else {
        ui.label(RichText::new("Select a curve to hang it from jump rings").weak());
        return;
    };
    let closed = item.closed;
    let mut rings: JumpRings = item.jump_rings.clone();
    let mut remove = None;
    for (k, at) in rings.at.iter().enumerate() {
        ui.horizontal(|ui| {
            ui.label(describe(at));
            if ui.small_button("Remove").clicked() {
                remove = Some(k);
            }
        });
    }
    if let Some(k) = remove {
        rings.at.remove(k);
    }
    ui.horizontal_wrapped(|ui| {
        ui.label("Add");
        if ui.button("top").on_hover_text("Above the pattern's highest point, for a pendant").clicked() {
            rings.at.push(RingAt::Top);
        }
        for (at, name) in [(RingAt::Start, "start"), (RingAt::End, "end")] {
            let button = ui.add_enabled(!closed, egui::Button::new(name));
            if button.on_disabled_hover_text("A loop has no ends").clicked() {
                rings.at.push(at);
            }
        }
        if ui
            .selectable_label(app.state.tool == Tool::Ring, "at a click…")
            .on_hover_text("Then click on the canvas")
            .clicked()
        {
            app.state.tool = Tool::Ring;
        }
    });
    egui::Grid::new("jump_rings").num_columns(2).show(ui, |ui| {
        let label = ui.label("Hole");
        ui.add(egui::DragValue::new(&mut rings.hole_mm).range(0.4..=20.0).speed(0.05).suffix(" mm"))
            .labelled_by(label.id);
        ui.end_row();
        let label = ui.label("Wall");
        ui.add(egui::DragValue::new(&mut rings.wall_mm).range(0.4..=10.0).speed(0.05).suffix(" mm"))
            .labelled_by(label.id);
        ui.end_row();
    });
    if let Some(item) = app.selected.and_then(|id| app.doc.curve_mut(id))
        && item.jump_rings != rings
    {
        item.jump_rings = rings;
    }
}
