//! UI snapshot tests: one picture per panel and per mode, rendered by wgpu
//! (Mesa's lavapipe where there is no GPU) and compared with the baselines
//! in `tests/snapshots/` within a small tolerance.
//!
//! After a deliberate change to the UI, update the baselines with
//! `UPDATE_SNAPSHOTS=1 cargo test -p tracery --test snapshots`, look at the
//! new pictures, and commit them.

use std::path::PathBuf;

use egui_kittest::{Harness, SnapshotOptions, SnapshotResults};
use tracery::TraceryApp;
use tracery::dialogs::ScriptedDialogs;
use tracery::modes::{ModeEnv, REGISTRY};
use tracery::panels::{files, preview_3d, side_panel, status, top_bar};
use tracery_core::DVec2;

#[path = "common/drive.rs"]
mod drive;
#[path = "common/ui.rs"]
mod ui;
use drive::rendered_window;
use ui::settle;

/// Per-pixel colour difference tolerated (kittest's default).
const THRESHOLD: f32 = 0.6;
/// Pixels allowed past the threshold: text antialiasing may differ slightly
/// between Mesa versions.
const MAX_FAILED_PIXELS: usize = 120;

fn options() -> SnapshotOptions {
    SnapshotOptions::new()
        .output_path(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/snapshots"))
        .threshold(THRESHOLD)
        .max_failed_pixels(MAX_FAILED_PIXELS)
}

fn app() -> TraceryApp {
    TraceryApp::with(Box::new(ScriptedDialogs::default()), None)
}

/// Renders one panel of a fresh app, sized to its contents; the result
/// fails the test when dropped, unless merged into another.
fn panel_snapshot(
    name: &str,
    size: egui::Vec2,
    mut panel: impl FnMut(&mut TraceryApp, &mut egui::Ui) + 'static,
) -> SnapshotResults {
    let mut harness = Harness::builder()
        .with_size(size)
        .wgpu()
        .build_ui_state(move |ui: &mut egui::Ui, app: &mut TraceryApp| panel(app, ui), app());
    harness.run();
    harness.snapshot_options(name, &options());
    harness.take_snapshot_results()
}

#[test]
fn top_bar() {
    panel_snapshot("top_bar", egui::vec2(900.0, 40.0), top_bar::top_bar_ui);
}

#[test]
fn side_panel() {
    panel_snapshot("side_panel", egui::vec2(280.0, 760.0), side_panel::side_panel_ui);
}

#[test]
fn files_panel() {
    panel_snapshot("files", egui::vec2(280.0, 140.0), files::files_ui);
}

#[test]
fn status_bar() {
    panel_snapshot("status", egui::vec2(900.0, 30.0), status::status_ui);
}

#[test]
fn preview_3d_empty() {
    panel_snapshot("preview_3d", egui::vec2(320.0, 260.0), preview_3d::preview_panel_ui);
}

#[test]
fn model_panel() {
    panel_snapshot("model_panel", egui::vec2(280.0, 760.0), tracery::model::model_panel_ui);
}

#[test]
fn every_mode_settings() {
    // One result for all modes: kittest asks that results of several
    // harnesses in one test be merged.
    let mut results = SnapshotResults::new();
    for mode in REGISTRY {
        let name = format!("mode_{}", mode.name().to_lowercase().replace(' ', "_"));
        let mut settings = mode.default_settings();
        results.extend(panel_snapshot(&name, egui::vec2(280.0, 620.0), move |app, ui| {
            let mut commands = Vec::new();
            let doc = app.doc.clone();
            let mut env = ModeEnv { doc: &doc, caches: app.caches_mut(), commands: &mut commands };
            mode.settings_ui(ui, &mut settings, &mut env);
        }));
    }
}

/// The whole window with a synthesized bracelet: canvas, band overlay,
/// status with the counted topology, and the 3D preview.
#[test]
fn whole_window_with_a_pattern() {
    let mut harness = rendered_window();
    {
        let app = harness.state_mut();
        let ring: Vec<DVec2> = (0..24)
            .map(|k| {
                let a = k as f64 / 24.0 * std::f64::consts::TAU;
                DVec2::new(30.0 * a.cos(), 30.0 * a.sin())
            })
            .collect();
        app.add_curve(ring, true);
        app.set_show_3d(true);
    }
    settle(&mut harness);
    harness.snapshot_options("window", &options());
}
