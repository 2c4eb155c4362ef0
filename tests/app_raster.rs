//! The raster brush in the desktop app, driven like a person would: pick the
//! mode, draw, paint an area to avoid, undo, import PNG exemplars.

use egui::{Key, Modifiers, Pos2};
use egui_kittest::kittest::Queryable;
use tracery::dialogs::FileKind;
use tracery::document::{ExemplarRef, ModeSettings};
use tracery_core::DVec2;

#[path = "common/cli.rs"]
mod cli;
#[path = "common/drive.rs"]
mod drive;
use cli::tempdir;
#[path = "common/stl.rs"]
mod stl;
#[path = "common/ui.rs"]
mod ui;
use drive::{click_in_side_panel, drag, harness};
use stl::check_stl;
use ui::settle;

/// Switches the controls to the raster brush through the mode picker.
fn choose_raster_mode(harness: &mut egui_kittest::Harness<'static, tracery::TraceryApp>) {
    harness.get_by_label("Mode").click();
    harness.run_steps(2);
    harness.get_by_label("Raster brush").click();
    harness.run_steps(2);
    assert!(matches!(harness.state().settings(), ModeSettings::RasterBrush(_)));
}

/// A wave across the canvas, screen points.
fn wave() -> Vec<Pos2> {
    (0..=48)
        .map(|k| {
            let t = k as f32 / 48.0;
            Pos2::new(450.0 + 560.0 * t, 400.0 + 80.0 * (t * std::f32::consts::TAU).sin())
        })
        .collect()
}

/// Whether `p` is inside `region` (even-odd over every ring), written here
/// apart from the geometry code.
fn inside(region: &tracery_core::geom::Region, p: DVec2) -> bool {
    let mut crossings = 0;
    for ring in region.polygons.iter().flat_map(|poly| std::iter::once(&poly.outer).chain(&poly.holes)) {
        for (k, a) in ring.iter().enumerate() {
            let b = ring[(k + 1) % ring.len()];
            if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
                crossings += 1;
            }
        }
    }
    crossings % 2 == 1
}

fn segment_distance(q: DVec2, a: DVec2, b: DVec2) -> f64 {
    let t = ((q - a).dot(b - a) / (b - a).length_squared().max(1e-12)).clamp(0.0, 1.0);
    (a + (b - a) * t).distance(q)
}

#[test]
fn a_raster_curve_shows_its_picture_and_leaves_painted_areas_empty() {
    let dir = tempdir("app-raster");
    let mut harness =
        harness(vec![(FileKind::ExportStl, dir.join("whole.stl")), (FileKind::ExportStl, dir.join("cut.stl"))]);
    harness.step();
    choose_raster_mode(&mut harness);
    drag(&mut harness, &wave());
    settle(&mut harness);
    let id = harness.state().doc.curves[0].id;
    let product = harness.state().output(id).expect("a raster pattern").clone();
    let textured = product.textured_mm.as_ref().expect("textured triangles for the canvas");
    assert!(textured.texture.is_some() && textured.triangles.len() > 1000);
    assert_eq!(product.topology.components, 1);
    harness.get_by_label_contains("1 component(s)");
    // One result, so no gallery computes it a second time.
    assert!(harness.state().gallery_state(id).is_none());
    assert!(harness.query_by_label("Solution 1").is_none(), "no gallery thumbnails");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::E);
    harness.step();
    let whole = check_stl(&dir.join("whole.stl"));
    assert_eq!((whole.shells, whole.open_edges, whole.misoriented_edges), (1, 0, 0), "one closed body");
    assert!(whole.triangles > 100);

    // Paint across the middle of the wave with the avoidance brush.
    harness.get_by_label("Avoid").click();
    harness.step();
    let across: Vec<Pos2> = (0..=10).map(|k| Pos2::new(730.0, 330.0 + 14.0 * k as f32)).collect();
    drag(&mut harness, &across);
    settle(&mut harness);
    let doc = harness.state().doc.clone();
    assert_eq!(doc.avoid.len(), 1, "one stroke painted");
    let stroke = &doc.avoid[0];
    let product = harness.state().output(id).unwrap().clone();
    assert_eq!(product.topology.components, 2, "the pattern breaks where it must stay empty");
    // No part of the pattern lies within the painted stroke: points on a
    // grid inside the brush's reach, checked against the traced outline.
    let points: Vec<DVec2> = stroke.points.iter().map(|p| DVec2::new(p[0], p[1])).collect();
    let reach = |q: DVec2| points.windows(2).map(|w| segment_distance(q, w[0], w[1])).fold(f64::MAX, f64::min);
    let (lo, hi) = points.iter().fold((DVec2::MAX, DVec2::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let mut checked = 0;
    for i in 0..=60 {
        for j in 0..=60 {
            let q = lo - DVec2::splat(stroke.width_mm)
                + (hi - lo + DVec2::splat(2.0 * stroke.width_mm)) * DVec2::new(f64::from(i), f64::from(j)) / 60.0;
            if reach(q) < 0.5 * stroke.width_mm - 0.05 {
                checked += 1;
                assert!(!inside(&product.region_mm, q), "pattern at {q} inside the avoided stroke");
            }
        }
    }
    assert!(checked > 200, "{checked} points checked");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::E);
    harness.step();
    let cut = check_stl(&dir.join("cut.stl"));
    assert_eq!((cut.shells, cut.open_edges, cut.misoriented_edges), (2, 0, 0), "two closed bodies");

    // Undo takes the stroke back, and the pattern joins again.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    settle(&mut harness);
    assert!(harness.state().doc.avoid.is_empty());
    assert_eq!(harness.state().output(id).unwrap().topology.components, 1);
}

/// A file dropped on the window, as the desktop hands it over.
#[derive(Debug)]
struct Dropped(std::path::PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &std::path::Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

#[test]
fn png_exemplars_import_by_dialog_and_by_drop_and_bad_ones_change_nothing() {
    let dir = tempdir("app-png");
    let bar = image::RgbaImage::from_fn(80, 30, |x, y| {
        image::Rgba([if x % 10 < 5 { 200 } else { 90 }, 60, 40, if (8..22).contains(&y) { 255 } else { 0 }])
    });
    let good = dir.join("bar.png");
    bar.save(&good).unwrap();
    let rgb = dir.join("flat.png");
    image::RgbImage::from_pixel(40, 20, image::Rgb([1, 2, 3])).save(&rgb).unwrap();
    let mut harness = harness(vec![(FileKind::ImportPng, rgb.clone()), (FileKind::ImportPng, good.clone())]);
    harness.step();
    choose_raster_mode(&mut harness);

    // A picture without transparency is refused, and nothing changes.
    let before = harness.state().doc.clone();
    click_in_side_panel(&mut harness, "Import PNG…");
    let (message, error) = harness.state().message.clone().expect("a message");
    assert!(error && message.contains("no transparency"), "{message}");
    assert_eq!(harness.state().doc, before);

    // A good one by the dialog becomes the exemplar, shown among the thumbnails.
    click_in_side_panel(&mut harness, "Import PNG…");
    let ModeSettings::RasterBrush(item) = harness.state().settings().clone() else { panic!("not raster") };
    assert_eq!(item.exemplar, ExemplarRef::Imported("bar".into()));
    harness.run_steps(2);
    harness.get_by_label("bar");
    drag(&mut harness, &wave());
    settle(&mut harness);
    let id = harness.state().doc.curves[0].id;
    assert_eq!(harness.state().output(id).expect("a pattern from the import").topology.components, 1);

    // The same file dropped on the window comes in again under a new name.
    harness.input_mut().dropped_files.push(std::sync::Arc::new(Dropped(good.clone())));
    harness.step();
    let names: Vec<&str> = harness.state().doc.imported_raster.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["bar", "bar 2"]);
    // Undo forgets the second import.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    assert_eq!(harness.state().doc.imported_raster.len(), 1);
}
