//! Regenerates `screenshots/` from the real UI, rendered by wgpu (on Mesa's
//! lavapipe where there is no GPU):
//!
//! `cargo test -p tracery --test screenshots -- --ignored`

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::path::Path;
use tracery::TraceryApp;
use tracery::document::{ExemplarRef, ModeSettings, SurfaceCurveItem, VectorBrushItem};
use tracery_core::DVec2;
use tracery_core::surface::{SurfaceMesh, SurfaceOutput, builtin_base};
use tracery_core::vector_brush::Target;

#[path = "common/drive.rs"]
mod drive;
#[path = "common/ui.rs"]
mod ui;
use drive::rendered_window;
use ui::{settle, settle_model};

fn save(harness: &mut Harness<'static, TraceryApp>, name: &str) {
    let image = harness.render().expect("rendering through wgpu");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../screenshots");
    std::fs::create_dir_all(&dir).unwrap();
    image.save(dir.join(name)).unwrap();
}

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_screenshots() {
    let mut harness = rendered_window();
    {
        let app = harness.state_mut();
        let bracelet: Vec<DVec2> = (0..24)
            .map(|k| {
                let a = k as f64 / 24.0 * std::f64::consts::TAU;
                DVec2::new(-40.0 + 30.0 * a.cos(), 8.0 + 30.0 * a.sin())
            })
            .collect();
        let mut lace = VectorBrushItem::default();
        lace.settings.variety = 0.4;
        let lace = ModeSettings::VectorBrush(lace);
        let id = app.doc.add_curve(bracelet, true, lace);
        let border: Vec<DVec2> =
            (0..=20).map(|k| DVec2::new(5.0 + k as f64 * 4.5, -20.0 + 12.0 * (k as f64 / 3.0).sin())).collect();
        let mut vine = VectorBrushItem { exemplar: ExemplarRef::Builtin("vine".into()), ..Default::default() };
        vine.settings.holes = Target::Exactly(0);
        vine.settings.closed_pattern = false;
        vine.settings.band_mm = 12.0;
        let vine = ModeSettings::VectorBrush(vine);
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

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_raster_screenshot() {
    use tracery::document::{AvoidStroke, RasterBrushItem};
    let mut harness = rendered_window();
    {
        let app = harness.state_mut();
        let raster = |name: &str| {
            ModeSettings::RasterBrush(RasterBrushItem {
                exemplar: ExemplarRef::Builtin(name.into()),
                ..RasterBrushItem::default()
            })
        };
        // A heart of chain, a rope wave and a vine border broken where the avoidance brush painted.
        let heart: Vec<DVec2> = (0..32)
            .map(|k| {
                let t = k as f64 / 32.0 * std::f64::consts::TAU;
                let (x, y) = (16.0 * t.sin().powi(3), 13.0 * t.cos() - 5.0 * (2.0 * t).cos() - 2.0 * (3.0 * t).cos());
                DVec2::new(-55.0 + 1.8 * x, 5.0 + 1.8 * y)
            })
            .collect();
        let id = app.doc.add_curve(heart, true, raster("chain"));
        let wave: Vec<DVec2> =
            (0..=16).map(|k| DVec2::new(5.0 + k as f64 * 5.0, 25.0 + 10.0 * (k as f64 / 2.5).sin())).collect();
        app.doc.add_curve(wave, false, raster("rope"));
        let border: Vec<DVec2> =
            (0..=16).map(|k| DVec2::new(5.0 + k as f64 * 5.0, -20.0 + 6.0 * (k as f64 / 2.0).cos())).collect();
        app.doc.add_curve(border, false, raster("vine"));
        app.doc.avoid.push(AvoidStroke { points: vec![[42.0, -32.0], [46.0, -8.0]], width_mm: 7.0 });
        app.selected = Some(id);
    }
    settle(&mut harness);
    save(&mut harness, "raster-brush.png");
}

/// Adds a closed curve of chain through six points round `model` at
/// `(radius, z)` mm, moved onto its surface as picked points would be;
/// returns its id.
fn add_chain_ring(
    app: &mut TraceryApp,
    model: &SurfaceMesh,
    (radius_mm, z_mm): (f64, f64),
    band_mm: f64,
    output: SurfaceOutput,
) -> u64 {
    let mut chain = SurfaceCurveItem::default();
    chain.settings.band_mm = band_mm;
    chain.surface.points_mm = (0..6)
        .map(|k| {
            let a = k as f64 / 6.0 * std::f64::consts::TAU;
            model.closest_point([radius_mm * a.cos(), radius_mm * a.sin(), z_mm]).position_mm.to_array()
        })
        .collect();
    chain.surface.closed = true;
    chain.surface.output = output;
    // A new curve starts with no points; the ring's are put back.
    let id = app.doc.add_surface_curve(&chain);
    app.doc.model.curve_mut(id).unwrap().surface = chain.surface;
    id
}

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_model_screenshot() {
    let mut harness = rendered_window();
    harness.get_by_label("3D model").click();
    harness.run_steps(2);
    {
        let app = harness.state_mut();
        // A ring of chain around the vase's belly, and a vine across its
        // shoulder, as points picked while turning the model would give:
        // on its surface.
        let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap();
        let on_vase = |p: [f64; 3]| vase.closest_point(p).position_mm.to_array();
        let id = add_chain_ring(app, &vase, (30.0, 28.0), 9.0, SurfaceOutput::Pattern);
        let mut vine = SurfaceCurveItem { exemplar: ExemplarRef::Builtin("vine".into()), ..Default::default() };
        vine.settings.holes = Target::Exactly(0);
        vine.settings.band_mm = 10.0;
        vine.surface.points_mm =
            [[18.0, -12.0, 44.0], [0.0, -22.0, 50.0], [-18.0, -12.0, 56.0]].into_iter().map(on_vase).collect();
        let v = app.doc.add_surface_curve(&vine);
        app.doc.model.curve_mut(v).unwrap().surface = vine.surface.clone();
        app.selected_surface = Some(id);
    }
    settle_model(&mut harness);
    save(&mut harness, "model.png");
}

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_lamp_screenshot() {
    let mut harness = rendered_window();
    harness.get_by_label("3D model").click();
    harness.run_steps(2);
    harness.state_mut().doc.model.base = tracery::document::BaseRef::Builtin("cone".into());
    harness.run_steps(2);
    drive::click_in_side_panel(&mut harness, "Add shade");
    {
        let app = harness.state_mut();
        // A ring of chain embossed round the foot, as points picked round it.
        let cone = SurfaceMesh::new(builtin_base("cone").unwrap()).unwrap();
        add_chain_ring(app, &cone, (25.0, 16.0), 8.0, SurfaceOutput::Emboss);
        app.selected_surface = None;
    }
    settle_model(&mut harness);
    save(&mut harness, "lamp.png");
}

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_texture_screenshot() {
    let mut harness = rendered_window();
    harness.get_by_label("3D model").click();
    harness.run_steps(2);
    drive::click_in_side_panel(&mut harness, "Cover the model with texture");
    settle_model(&mut harness);
    save(&mut harness, "texture.png");
}

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_texture_guide_screenshot() {
    let mut harness = rendered_window();
    harness.get_by_label("3D model").click();
    harness.run_steps(2);
    {
        let app = harness.state_mut();
        let texture = &mut app.doc.model.texture;
        texture.on = true;
        texture.swatch = "scales".into();
        texture.settings.direction = tracery_core::mesh_quilt::Direction::AlongCurves;
        app.doc.model.with_model = true;
        // A guide rising round the vase's front: the scales' rows follow it.
        let id = app.doc.add_surface_curve(&SurfaceCurveItem { guide: true, ..Default::default() });
        let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap();
        let points: Vec<[f64; 3]> = (0..7)
            .map(|k| {
                let a = (-150.0 + 20.0 * k as f64).to_radians();
                let z = 12.0 + 5.0 * k as f64;
                vase.closest_point([40.0 * a.cos(), 40.0 * a.sin(), z]).position_mm.to_array()
            })
            .collect();
        app.doc.model.curve_mut(id).unwrap().surface.points_mm = points;
        app.selected_surface = None;
    }
    settle_model(&mut harness);
    save(&mut harness, "texture-guide.png");
}

#[test]
#[ignore = "writes screenshots/; run on purpose"]
fn regenerate_berries_screenshot() {
    let mut harness = rendered_window();
    harness.step();
    harness.get_by_label("Mode").click();
    harness.run_steps(2);
    harness.get_by_label("Region fill").click();
    harness.run_steps(2);
    // The thumbnail and the name under it both read "berries": the name.
    harness.query_all_by_label("berries").last().expect("the berries' name").scroll_to_me();
    harness.run_steps(3);
    harness.query_all_by_label("berries").last().expect("the berries' name").click();
    harness.step();
    drive::drag(&mut harness, &drive::circle(egui::pos2(775.0, 410.0), 150.0));
    settle(&mut harness);
    save(&mut harness, "fill-berries.png");
    // Drawn by hand: a stalk, with berries and stalks suggested round it,
    // some accepted; then another stalk's suggestions, ghosted.
    drive::click_in_side_panel(&mut harness, "Fill automatically");
    drive::click_in_side_panel(&mut harness, "Pen");
    let wave = |from: egui::Pos2, length: f32| -> Vec<egui::Pos2> {
        (0..=30)
            .map(|k| {
                let t = k as f32 / 30.0;
                from + egui::vec2(length * t, 12.0 * (t * std::f32::consts::TAU).sin())
            })
            .collect()
    };
    drive::drag(&mut harness, &wave(egui::pos2(680.0, 470.0), 190.0));
    settle(&mut harness);
    harness.key_press(egui::Key::Enter);
    harness.run_steps(2);
    drive::drag(&mut harness, &wave(egui::pos2(680.0, 380.0), 190.0));
    settle(&mut harness);
    // Closer, to see the berries.
    harness.hover_at(egui::pos2(775.0, 420.0));
    harness.event(egui::Event::Zoom(2.2));
    harness.run_steps(2);
    save(&mut harness, "fill-berries-autocomplete.png");
}
