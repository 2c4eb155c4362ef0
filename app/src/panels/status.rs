//! The status bar: progress, the topology counted on the final geometry,
//! time, warnings, and the last message.

use egui::{Color32, RichText};

use tracery_core::Product;

use crate::TraceryApp;
use crate::worker::JobState;

/// Warnings' colour.
pub(crate) const WARNING: Color32 = Color32::from_rgb(200, 140, 0);
/// Errors' colour.
pub(crate) const ERROR: Color32 = Color32::from_rgb(220, 60, 60);
/// Width of the progress bar, points.
const PROGRESS_WIDTH: f32 = 160.0;

/// The status bar, about the selected curve (or the last one drawn).
pub fn status_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    ui.horizontal(|ui| {
        if app.state.workspace == crate::state::Workspace::Model {
            crate::model::model_status_ui(app, ui);
            show_message(app, ui);
            return;
        }
        let focus = app.selected.or_else(|| app.doc.curves.last().map(|c| c.id));
        let shown = focus.is_some_and(|id| {
            job_state_ui(
                ui,
                &format!("Curve {id}"),
                app.worker.state(id),
                &format!("Synthesizing curve {id}…"),
                |product| {
                    let t = &product.topology;
                    let openings = if t.loop_openings > 0 {
                        format!(" + {} loop opening", t.loop_openings)
                    } else {
                        String::new()
                    };
                    let rings = if t.jump_rings > 0 { format!(" + {} jump ring", t.jump_rings) } else { String::new() };
                    let pieces = product.facts.count("pieces").map_or(String::new(), |n| format!(", {n} pieces"));
                    format!("{} component(s), {} hole(s){openings}{rings}{pieces}", t.components, t.holes)
                },
            )
        });
        if !shown {
            ui.label(if app.doc.curves.is_empty() {
                "Draw a curve on the canvas: drag with the left button. End near the start to close a loop."
            } else {
                "Ready"
            });
        }
        show_message(app, ui);
    });
}

/// Where the job of `name` (a curve, the object) stands: a progress bar
/// and `running` while it runs; when done, `summary` of the product with
/// its time and warnings, or the error. Returns whether there was anything to show.
pub(crate) fn job_state_ui<E: std::fmt::Display>(
    ui: &mut egui::Ui,
    name: &str,
    state: Option<&JobState<Product, E>>,
    running: &str,
    summary: impl Fn(&Product) -> String,
) -> bool {
    match state {
        Some(JobState::Running { progress }) => {
            ui.add(egui::ProgressBar::new(*progress).desired_width(PROGRESS_WIDTH).show_percentage());
            ui.label(running);
        }
        Some(JobState::Done(Ok(product))) => {
            ui.label(format!("{name}: {} — {:.0} ms", summary(product), product.timings.total_ms()));
            for w in &product.warnings {
                ui.label(RichText::new(format!("Warning: {w}")).color(WARNING));
            }
        }
        Some(JobState::Done(Err(e))) => {
            ui.label(RichText::new(format!("{name}: {e}")).color(ERROR));
        }
        Some(JobState::Idle) | None => return false,
    }
    true
}

fn show_message(app: &TraceryApp, ui: &mut egui::Ui) {
    if let Some((text, error)) = &app.message {
        ui.separator();
        let color = if *error { ERROR } else { ui.visuals().text_color() };
        ui.label(RichText::new(text).color(color));
    }
}
