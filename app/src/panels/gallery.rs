//! The gallery: the selected curve's alternative patterns, computed in the
//! background, shown as thumbnails under the canvas. Clicking one uses it.
//!
//! Two alternatives are told apart by [`distinctness`]: the share of the
//! pattern's length where they show different shapes (a loop's rotated copy
//! counts as the same). Alternatives less than [`SAME_BELOW`] apart from one
//! shown before them are not shown again.

use egui::{Color32, RichText, Sense, Stroke};
use tracery_core::Product;
use tracery_core::product::Fact;
use tracery_core::quality::distinctness;

use crate::TraceryApp;
use crate::canvas::fill_fitted;
use crate::worker::JobState;

/// Alternatives differing over less than this share of their length are the same pattern.
pub const SAME_BELOW: f64 = 0.05;
/// Height of the gallery strip, points.
pub const STRIP_HEIGHT: f32 = 132.0;
/// Thumbnail size, points.
const THUMB: egui::Vec2 = egui::vec2(120.0, 84.0);

/// A product's pieces as (shape class, 1): pieces count alike.
fn shapes(product: &Product) -> Vec<(usize, f64)> {
    match product.facts.get("shape_sequence") {
        Some(Fact::Indices(v)) => v.iter().map(|&c| (c, 1.0)).collect(),
        _ => Vec::new(),
    }
}

/// How far apart two alternatives are (0 to 1).
pub fn apart(a: &Product, b: &Product, closed: bool) -> f64 {
    distinctness(&shapes(a), &shapes(b), closed)
}

/// Which alternatives to show: each one that differs from all shown before it.
pub fn distinct(all: &[Product], closed: bool) -> Vec<usize> {
    let mut shown: Vec<usize> = Vec::new();
    for (k, p) in all.iter().enumerate() {
        if shown.iter().all(|&j| apart(&all[j], p, closed) >= SAME_BELOW) {
            shown.push(k);
        }
    }
    shown
}

/// The gallery strip (for the selected curve).
pub fn gallery_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    let Some(id) = app.selected else { return };
    let Some(item) = app.doc.curve(id) else { return };
    let closed = item.closed;
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
    let Some(all) = app.gallery(id).cloned() else { return };
    let shown = distinct(&all, closed);
    let mut picked = None;
    ui.horizontal(|ui| {
        for &k in &shown {
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
                    format!("{:.0}% differs", 100.0 * apart(&all[0], product, closed))
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
