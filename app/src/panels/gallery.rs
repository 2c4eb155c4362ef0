//! The gallery: the selected curve's alternative patterns, computed in the
//! background ([`crate::solutions`]), shown as thumbnails under the canvas.
//! Clicking one uses it.

use egui::{Color32, RichText, Sense, Stroke};

use crate::TraceryApp;
use crate::canvas::fill_fitted;
use crate::worker::JobState;

/// Height of the gallery strip, points.
pub const STRIP_HEIGHT: f32 = 132.0;
/// Thumbnail size, points.
const THUMB: egui::Vec2 = egui::vec2(120.0, 84.0);

/// The gallery strip (for the selected curve).
pub fn gallery_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    let Some(id) = app.selected else { return };
    let Some(item) = app.doc.curve(id) else { return };
    let current = item.mode.alternative() as usize;
    ui.horizontal(|ui| {
        ui.label(RichText::new("Solutions").strong());
        match app.gallery_state(id) {
            Some(JobState::Running { progress }) => {
                ui.add(egui::ProgressBar::new(*progress).desired_width(120.0).show_percentage());
            }
            Some(JobState::Done(Err(e))) => {
                ui.label(RichText::new(e.to_string()).weak());
            }
            _ => {}
        }
    });
    let Some(solutions) = app.gallery(id).cloned() else { return };
    let (all, shown) = (&solutions.products, &solutions.shown);
    let mut picked = None;
    ui.horizontal(|ui| {
        for &k in shown {
            let product = &all[k];
            ui.vertical(|ui| {
                let (rect, response) = ui.allocate_exact_size(THUMB, Sense::click());
                let selected = k == current;
                let name = format!("Solution {}", k + 1);
                response.widget_info(|| egui::WidgetInfo::selected(egui::Role::Button, true, selected, &name));
                let painter = ui.painter_at(rect);
                painter.rect_filled(rect, 4.0, ui.visuals().extreme_bg_color);
                if let Some(bounds) = product.region_mm.bounds() {
                    let ink = ui.visuals().strong_text_color();
                    painter.add(fill_fitted(rect.shrink(6.0), bounds, &product.fill_mm, ink));
                }
                let stroke = if selected {
                    Stroke::new(2.0, ui.visuals().selection.stroke.color)
                } else {
                    Stroke::new(1.0, Color32::from_gray(110))
                };
                painter.rect_stroke(rect, 4.0, stroke, egui::StrokeKind::Inside);
                let label = if k == 0 {
                    "the best".to_string()
                } else {
                    format!("{:.0}% differs", 100.0 * solutions.apart_from_best[k])
                };
                let response = response.on_hover_text(format!(
                    "Solution {}: {} component(s), {} hole(s); click to use it",
                    k + 1,
                    product.topology.components,
                    product.topology.holes
                ));
                if response.clicked() {
                    picked = Some(k);
                }
                ui.label(RichText::new(label).small());
            });
        }
        if shown.len() < all.len() {
            ui.label(
                RichText::new(format!("{} of {} solutions differ for these targets", shown.len(), all.len())).weak(),
            );
        }
    });
    if let Some(k) = picked
        && let Some(item) = app.doc.curve_mut(id)
    {
        item.mode.set_alternative(k as u32);
    }
}
