//! Driving the whole app as a person would: a window, drags on the canvas,
//! clicks in the side panel.
#![allow(dead_code)]

use std::path::PathBuf;

use egui::{Event, Modifiers, PointerButton, Pos2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use tracery::TraceryApp;
use tracery::dialogs::{FileKind, ScriptedDialogs};

/// The app in a 1280 x 800 window, its file dialogs answering from `answers`.
pub fn harness(answers: Vec<(FileKind, PathBuf)>) -> Harness<'static, TraceryApp> {
    Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_eframe(move |_| TraceryApp::with(Box::new(ScriptedDialogs { answers }), None))
}

/// The app in a 1280 x 800 window rendered through wgpu (lavapipe where
/// there is no GPU), for pictures of the whole window; dialogs answer nothing.
pub fn rendered_window() -> Harness<'static, TraceryApp> {
    Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .wgpu()
        .build_eframe(|_| TraceryApp::with(Box::new(ScriptedDialogs::default()), None))
}

/// Presses or releases the primary button at `pos`.
pub fn press(harness: &Harness<'static, TraceryApp>, pos: Pos2, pressed: bool) {
    harness.event(Event::PointerButton { pos, button: PointerButton::Primary, pressed, modifiers: Modifiers::NONE });
}

/// Drags along `points` with the primary button, one frame per point.
pub fn drag(harness: &mut Harness<'static, TraceryApp>, points: &[Pos2]) {
    harness.hover_at(points[0]);
    harness.step();
    press(harness, points[0], true);
    harness.step();
    for &p in &points[1..] {
        harness.hover_at(p);
        harness.step();
    }
    press(harness, *points.last().unwrap(), false);
    harness.step();
}

/// Scrolls the side panel to the widget labelled `label`, then clicks it.
pub fn click_in_side_panel(harness: &mut Harness<'static, TraceryApp>, label: &str) {
    harness.get_by_label(label).scroll_to_me();
    harness.run_steps(3);
    harness.get_by_label(label).click();
    harness.step();
}

/// A loop drawn on the canvas: a circle of `radius` points around `center`.
pub fn circle(center: Pos2, radius: f32) -> Vec<Pos2> {
    (0..=64)
        .map(|k| {
            let a = k as f32 / 64.0 * std::f32::consts::TAU;
            center + egui::vec2(radius * a.cos(), radius * a.sin())
        })
        .collect()
}
