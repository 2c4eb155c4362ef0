//! Regenerates `screenshots/` from the real UI, rendered by wgpu (on Mesa's
//! lavapipe where there is no GPU):
//!
//! `cargo test -p tracery --test screenshots -- --ignored`

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::path::Path;
use tracery::TraceryApp;
use tracery::dialogs::ScriptedDialogs;
use tracery::document::{Count, ExemplarRef, PatternSettings};
use tracery_core::DVec2;

#[path = "common/ui.rs"]
mod ui;
use ui::settle;

fn save(harness: &mut Harness<'static, TraceryApp>, name: &str) {
    let image = harness.render().expect("rendering through wgpu");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../screenshots");
    std::fs::create_dir_all(&dir).unwrap();
    image.save(dir.join(name)).unwrap();
}

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_screenshots() {
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .wgpu()
        .build_eframe(|_| TraceryApp::with(Box::new(ScriptedDialogs::default()), None));
    {
        let app = harness.state_mut();
        let bracelet: Vec<DVec2> = (0..24)
            .map(|k| {
                let a = k as f64 / 24.0 * std::f64::consts::TAU;
                DVec2::new(-40.0 + 30.0 * a.cos(), 8.0 + 30.0 * a.sin())
            })
            .collect();
        let lace = PatternSettings { variety: 0.4, ..PatternSettings::default() };
        let id = app.doc.add_curve(bracelet, true, lace);
        let border: Vec<DVec2> =
            (0..=20).map(|k| DVec2::new(5.0 + k as f64 * 4.5, -20.0 + 12.0 * (k as f64 / 3.0).sin())).collect();
        let vine = PatternSettings {
            exemplar: ExemplarRef::Builtin("vine".into()),
            holes: Count::Zero,
            closed_pattern: false,
            band_mm: 12.0,
            ..PatternSettings::default()
        };
        app.doc.add_curve(border, false, vine);
        app.selected = Some(id);
    }
    settle(&mut harness);
    save(&mut harness, "canvas.png");
    harness.get_by_label("3D preview").click();
    harness.get_by_label("Piece seams").click();
    settle(&mut harness);
    save(&mut harness, "preview-3d.png");
}
