//! The model workspace, driven as a person would: points clicked on a
//! built-in vase become a curve on its surface, the pattern follows it,
//! undo takes a point back, and the export is a sound solid.

use std::time::{Duration, Instant};

use egui::Pos2;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use tracery::TraceryApp;
use tracery::dialogs::FileKind;
use tracery::worker::JobState;
use tracery_core::control::Control;
use tracery_core::mesh_quilt::{GuidanceField, builtin_swatch, make_surface_product};
use tracery_core::surface::{SurfaceMesh, SurfaceOutput, builtin_base};

#[path = "common/distance.rs"]
mod distance;
#[path = "common/drive.rs"]
mod drive;
#[path = "common/stl.rs"]
mod stl;
#[path = "common/threemf.rs"]
mod threemf;
#[path = "common/ui.rs"]
mod ui;
use drive::{click_in_side_panel, harness, press};
use ui::settle_model;

fn click(harness: &mut Harness<'static, TraceryApp>, at: Pos2) {
    harness.hover_at(at);
    harness.step();
    press(harness, at, true);
    harness.step();
    press(harness, at, false);
    harness.step();
}

#[test]
fn points_clicked_on_the_vase_carry_a_pattern_that_exports_as_one_solid() {
    let path = std::env::temp_dir().join(format!("tracery-model-{}.stl", std::process::id()));
    let _ = std::fs::remove_file(&path);
    let mut harness = harness(vec![(FileKind::ExportStl, path.clone())]);
    harness.step();
    harness.get_by_label("3D model").click();
    harness.run_steps(2);
    // Across the front of the vase, in the middle of the view.
    let centre = harness.get_by_label("3D view").rect().center();
    for dx in [-60.0, 0.0, 60.0] {
        click(&mut harness, centre + egui::vec2(dx, 10.0));
    }
    let app = harness.state();
    assert_eq!(app.doc.model.curves.len(), 1, "the clicks start one curve: {:?}", app.message);
    let item = app.doc.model.curves[0].clone();
    assert_eq!(item.surface.points_mm.len(), 3, "every click on the vase picks a point");
    // Each picked point lies on the vase, by a brute-force distance to its triangles.
    let vase = builtin_base("vase").unwrap();
    let size_mm = SurfaceMesh::new(vase.clone()).unwrap().size_mm();
    for p in &item.surface.points_mm {
        let d = distance::to_mesh(&vase.vertices, &vase.triangles, *p);
        assert!(d < 1e-6 * size_mm, "a picked point is {d} mm off the vase");
    }
    settle_model(&mut harness);
    let app = harness.state();
    let product = match app.surface_job_state(item.id) {
        Some(JobState::Done(Ok(p))) => p.clone(),
        other => panic!("no pattern on the vase: {:?}", other.map(|s| matches!(s, JobState::Running { .. }))),
    };
    let mesh = product.mesh_mm.as_ref().expect("a pattern on a surface is a solid");
    assert_eq!(mesh.shell_count(), product.topology.components, "the counted topology is the solid's");
    assert_eq!(product.topology.components, 1, "the default target is one piece");

    // Undo takes the last point back.
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    harness.run_steps(2);
    assert_eq!(harness.state().doc.model.curves[0].surface.points_mm.len(), 2, "undo removes the last point");
    settle_model(&mut harness);

    click_in_side_panel(&mut harness, "Export STL…");
    assert!(path.exists(), "no STL written: {:?}", harness.state().message);
    let check = stl::check_stl(&path);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    assert_eq!(check.shells, 1, "{check:?}");
    let _ = std::fs::remove_file(&path);
}

#[test]
fn curves_on_the_model_come_back_after_a_restart() {
    let dir = std::env::temp_dir().join(format!("tracery-autosave-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let path = dir.join("autosave.ron");
    let mut first = TraceryApp::with(Box::new(tracery::dialogs::ScriptedDialogs::default()), Some(path.clone()));
    let template = tracery::document::SurfaceCurveItem::default();
    let id = first.doc.add_surface_curve(&template);
    first.doc.model.curve_mut(id).unwrap().surface.points_mm = vec![[30.0, 0.0, 25.0], [0.0, 30.0, 25.0]];
    // The autosave runs on the frame loop, at most every two seconds.
    let mut harness = Harness::builder().with_size(egui::vec2(1280.0, 800.0)).build_eframe(move |_| first);
    let deadline = Instant::now() + Duration::from_secs(10);
    while !path.exists() && Instant::now() < deadline {
        harness.step();
        std::thread::sleep(Duration::from_millis(100));
    }
    assert!(path.exists(), "the model's curve was never autosaved");
    let mut second = TraceryApp::with(Box::new(tracery::dialogs::ScriptedDialogs::default()), Some(path));
    second.restore_autosave();
    assert_eq!(second.doc.model.curves.len(), 1, "a drawing only on the model is restored: {:?}", second.message);
    assert_eq!(second.doc.model.curves[0].surface.points_mm.len(), 2);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_broken_model_is_refused_with_its_reason_and_changes_nothing() {
    let path = std::env::temp_dir().join(format!("tracery-broken-{}.stl", std::process::id()));
    std::fs::write(&path, b"solid nothing\nfacet normal 0 0\n").unwrap();
    let mut harness = harness(vec![(FileKind::ImportModel, path.clone())]);
    harness.step();
    let before = harness.state().doc.clone();
    harness.state_mut().queue(tracery::command::Command::ImportModel);
    harness.run_steps(2);
    let app = harness.state();
    assert_eq!(app.doc, before, "a refused model leaves the document as it was");
    let (text, error) = app.message.clone().expect("the refusal is shown");
    assert!(error && text.contains("tracery-broken"), "the message names the file: {text}");
    let _ = std::fs::remove_file(&path);
}

#[test]
fn a_model_that_is_not_a_surface_is_refused_and_its_name_stays_free() {
    use tracery_core::export::write_stl;
    use tracery_core::mesh::Mesh;
    let path = std::env::temp_dir().join(format!("tracery-fan-{}.stl", std::process::id()));
    // Three triangles on one edge: a valid STL, but not a surface.
    let fan = Mesh {
        vertices: vec![[0.0, 0.0, 0.0], [10.0, 0.0, 0.0], [5.0, 8.0, 0.0], [5.0, -8.0, 0.0], [5.0, 0.0, 8.0]],
        triangles: vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]],
    };
    let write = |mesh: &Mesh| {
        let mut bytes = Vec::new();
        write_stl(mesh, &mut bytes).unwrap();
        std::fs::write(&path, bytes).unwrap();
    };
    write(&fan);
    let mut harness = harness(vec![(FileKind::ImportModel, path.clone()), (FileKind::ImportModel, path.clone())]);
    harness.step();
    let before = harness.state().doc.clone();
    harness.state_mut().queue(tracery::command::Command::ImportModel);
    harness.run_steps(2);
    let (text, error) = harness.state().message.clone().expect("the refusal is shown");
    assert!(error && text.contains("not a surface"), "the message gives the reason: {text}");
    assert_eq!(harness.state().doc, before, "a refused model leaves the document as it was");
    // The same file, mended, imports under the same name.
    write(&builtin_base("egg").unwrap());
    harness.state_mut().queue(tracery::command::Command::ImportModel);
    harness.run_steps(2);
    let (text, error) = harness.state().message.clone().expect("the import is reported");
    assert!(!error, "the mended model imports: {text}");
    assert_eq!(harness.state().doc.model.imported.len(), 1);
    let _ = std::fs::remove_file(&path);
}

/// A folder for an export test's files, and the app answering its STL and
/// 3MF dialogs (twice each) with files there, showing the model workspace.
fn model_export(
    name: &str,
) -> (std::path::PathBuf, std::path::PathBuf, std::path::PathBuf, Harness<'static, TraceryApp>) {
    let dir = std::env::temp_dir().join(format!("tracery-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let (stl_path, three_mf) = (dir.join(format!("{name}.stl")), dir.join(format!("{name}.3mf")));
    // Answered twice, for tests that export before and after a change.
    let answers = [(FileKind::ExportStl, stl_path.clone()), (FileKind::Export3mf, three_mf.clone())];
    let mut harness = harness(answers.iter().chain(&answers).cloned().collect());
    harness.step();
    harness.get_by_label("3D model").click();
    harness.run_steps(2);
    (dir, stl_path, three_mf, harness)
}

/// Exports the object as STL and as 3MF, and checks that both are one
/// closed body (PrusaSlicer, where installed, calls it manifold); returns the STL's mesh.
fn export_one_body(
    harness: &mut Harness<'static, TraceryApp>,
    stl_path: &std::path::Path,
    three_mf: &std::path::Path,
) -> tracery_core::mesh::Mesh {
    click_in_side_panel(harness, "Export STL…");
    assert!(stl_path.exists(), "no STL written: {:?}", harness.state().message);
    let check = stl::check_stl(stl_path);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    assert_eq!(check.shells, 1, "the object is one body: {check:?}");
    click_in_side_panel(harness, "Export 3MF…");
    assert!(three_mf.exists(), "no 3MF written: {:?}", harness.state().message);
    let read = threemf::read_3mf(&std::fs::read(three_mf).unwrap());
    assert_eq!(read.objects.len(), 1, "the 3MF holds one object");
    assert!(threemf::is_closed(&read.objects[0].2), "the 3MF's object is closed");
    if let Some((manifold, objects)) = threemf::prusa_info(three_mf) {
        assert!(manifold && objects == 1, "PrusaSlicer: manifold {manifold}, {objects} object(s)");
    }
    tracery_core::mesh::read_stl(&std::fs::read(stl_path).unwrap(), "test").unwrap()
}

#[test]
fn two_embossed_curves_export_as_one_object_holding_the_vase_once() {
    let (dir, stl_path, three_mf, mut harness) = model_export("object");
    let ring = |z: f64| vec![[30.0, 0.0, z], [0.0, 30.0, z], [-30.0, 0.0, z], [0.0, -30.0, z]];
    let app = harness.state_mut();
    let template = tracery::document::SurfaceCurveItem::default();
    for z in [18.0, 32.0] {
        let id = app.doc.add_surface_curve(&template);
        let item = app.doc.model.curve_mut(id).unwrap();
        item.surface.points_mm = ring(z);
        item.surface.closed = true;
        item.surface.output = SurfaceOutput::Emboss;
        item.settings.band_mm = 7.0;
    }
    settle_model(&mut harness);
    let object = export_one_body(&mut harness, &stl_path, &three_mf);
    // The vase is in it once: the object's volume is the vase's and the two
    // reliefs', far from two vases.
    let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap().mesh().signed_volume();
    let relief = object.signed_volume() - vase;
    assert!(relief > 200.0 && relief < 0.2 * vase, "{relief:.0} mm³ beyond the vase's {vase:.0}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_shade_added_on_the_cone_makes_a_lamp_in_one_body() {
    let (dir, stl_path, three_mf, mut harness) = model_export("lamp");
    harness.state_mut().doc.model.base = tracery::document::BaseRef::Builtin("cone".into());
    harness.run_steps(2);
    click_in_side_panel(&mut harness, "Add shade");
    let app = harness.state();
    assert_eq!(app.doc.model.shades.len(), 1, "{:?}", app.message);
    assert!(app.doc.model.with_model, "a shade on the model takes the model as its foot");
    settle_model(&mut harness);
    let object = export_one_body(&mut harness, &stl_path, &three_mf);
    // The cone is in it whole, and the shade rises above it.
    let cone = SurfaceMesh::new(builtin_base("cone").unwrap()).unwrap();
    let top = object.vertices.iter().map(|v| v[2]).fold(f64::MIN, f64::max);
    assert!(top > 100.0, "the shade's top is at {top} mm");
    assert!(object.signed_volume() > cone.mesh().signed_volume() + 1000.0);
    // Undo takes the shade back.
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    harness.run_steps(2);
    assert!(harness.state().doc.model.shades.is_empty(), "undo removes the shade");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn texture_turned_on_covers_the_cone_and_prints_with_it_as_one_body() {
    let (dir, stl_path, three_mf, mut harness) = model_export("texture");
    harness.state_mut().doc.model.base = tracery::document::BaseRef::Builtin("cone".into());
    harness.run_steps(2);
    click_in_side_panel(&mut harness, "Cover the model with texture");
    let app = harness.state();
    assert!(app.doc.model.texture.on, "{:?}", app.message);
    assert!(app.doc.model.with_model, "texture on the model is printed with it");
    assert_eq!(app.doc.model.texture.swatch, "rivets");
    settle_model(&mut harness);
    let app = harness.state();
    let Some(JobState::Done(Ok(texture))) = app.texture_state() else {
        panic!("no texture: {:?}", app.texture_state().map(|_| ()));
    };
    let rivets = texture.facts.count("elements").unwrap();
    assert!(rivets > 30, "only {rivets} rivets on the cone");
    let object = export_one_body(&mut harness, &stl_path, &three_mf);
    // The cone is in it whole, with the rivets standing out of it: each
    // rivet adds at least a little volume.
    let cone = SurfaceMesh::new(builtin_base("cone").unwrap()).unwrap().mesh().signed_volume();
    let added = object.signed_volume() - cone;
    assert!(added > 2.0 * rivets as f64, "{added:.0} mm³ of texture for {rivets} rivets");
    // It still stands on the bed: nothing below the cone's foot.
    let lowest = object.vertices.iter().map(|v| v[2]).fold(f64::MAX, f64::min);
    assert!(lowest > -1e-6, "the object reaches {lowest} mm below the bed");
    // Undo turns the texture off again.
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    harness.run_steps(2);
    assert!(!harness.state().doc.model.texture.on, "undo turns the texture off");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn texture_and_a_pattern_curve_on_the_vase_print_as_one_body() {
    // Scales over the vase, and a chain rising round it as a pattern: the
    // chain is embossed since the object holds the vase (laid exactly on
    // it, the union came out pinched and the object was refused), and the
    // air a scale seals over the chain is filled (it was a second body).
    let (dir, stl_path, three_mf, mut harness) = model_export("texture-chain");
    click_in_side_panel(&mut harness, "Cover the model with texture");
    let app = harness.state_mut();
    app.doc.model.texture.swatch = "scales".into();
    let id = app.doc.add_surface_curve(&tracery::document::SurfaceCurveItem::default());
    let item = app.doc.model.curve_mut(id).unwrap();
    item.surface.points_mm = vec![[28.0, 0.0, 15.0], [0.0, 28.0, 25.0], [-25.0, 0.0, 35.0], [0.0, -22.0, 42.0]];
    assert_eq!(item.surface.output, SurfaceOutput::Pattern);
    item.settings.band_mm = 7.0;
    settle_model(&mut harness);
    let object = export_one_body(&mut harness, &stl_path, &three_mf);
    let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap().mesh().signed_volume();
    assert!(object.signed_volume() > vase + 500.0, "{:.0} mm³ against the vase's {vase:.0}", object.signed_volume());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn texture_along_a_curve_drawn_on_the_model_follows_it() {
    let (dir, stl_path, three_mf, mut harness) = model_export("texture-curves");
    harness.state_mut().doc.model.base = tracery::document::BaseRef::Builtin("cone".into());
    harness.run_steps(2);
    click_in_side_panel(&mut harness, "along curves");
    click_in_side_panel(&mut harness, "Cover the model with texture");
    settle_model(&mut harness);
    // Nothing drawn yet: the texture says what it lacks.
    match harness.state().texture_state() {
        Some(JobState::Done(Err(e))) => assert!(e.to_string().contains("no curve"), "{e}"),
        other => panic!("a texture along no curve: {:?}", other.map(|_| ())),
    }
    // A curve up the front of the cone, drawn from its foot.
    let centre = harness.get_by_label("3D view").rect().center();
    for dy in [40.0, 0.0, -40.0] {
        click(&mut harness, centre + egui::vec2(0.0, dy));
    }
    settle_model(&mut harness);
    let app = harness.state();
    assert_eq!(app.doc.model.curves.len(), 1, "{:?}", app.message);
    let strokes = vec![app.doc.model.curves[0].surface.points_mm.clone()];
    assert_eq!(strokes[0].len(), 3, "every click on the cone picks a point");
    let Some(JobState::Done(Ok(texture))) = app.texture_state() else {
        panic!("no texture along the curve: {:?}", app.texture_state().map(|_| ()));
    };
    // The same texture made directly, its field interpolated from the
    // picked points: the app passed the curve on, and nothing else.
    let surface = SurfaceMesh::new(builtin_base("cone").unwrap()).unwrap();
    let field = GuidanceField::from_strokes(&surface, &strokes).unwrap();
    let swatch = builtin_swatch(&app.doc.model.texture.swatch).unwrap();
    let expected =
        make_surface_product(&swatch, &surface, &field, &app.doc.model.texture.settings, &Control::default()).unwrap();
    assert!(texture.facts.count("elements").unwrap() > 20, "{:?}", texture.facts);
    assert_eq!(texture.mesh_mm, expected.mesh_mm, "the texture follows the drawn curve");
    // Around the axis it differs.
    let around = GuidanceField::around_axis(&surface);
    let other =
        make_surface_product(&swatch, &surface, &around, &app.doc.model.texture.settings, &Control::default()).unwrap();
    assert_ne!(texture.mesh_mm, other.mesh_mm, "a curve up the cone turns the texture");
    // The curve carries a chain too; made a guide, it turns the texture
    // the same and carries nothing: the object loses the chain's volume.
    let id = app.doc.model.curves[0].id;
    assert!(matches!(app.surface_job_state(id), Some(JobState::Done(Ok(_)))), "the curve's chain");
    let with_chain = export_one_body(&mut harness, &stl_path, &three_mf);
    click_in_side_panel(&mut harness, "guide");
    settle_model(&mut harness);
    let app = harness.state();
    assert!(app.doc.model.curves[0].guide, "{:?}", app.message);
    assert!(app.surface_job_state(id).is_none(), "a guide has no pattern of its own");
    match app.texture_state() {
        Some(JobState::Done(Ok(guided))) => assert_eq!(guided.mesh_mm, expected.mesh_mm, "the guide turns the texture"),
        other => panic!("no texture along the guide: {:?}", other.map(|_| ())),
    }
    harness.get_by_label(&format!("Curve {id} guides the texture's rows"));
    let _ = (std::fs::remove_file(&stl_path), std::fs::remove_file(&three_mf));
    let guided = export_one_body(&mut harness, &stl_path, &three_mf);
    let chain = with_chain.signed_volume() - guided.signed_volume();
    assert!(chain > 30.0, "the chain's {chain:.0} mm³ left the object");
    // Undo gives the chain back.
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    harness.run_steps(2);
    assert!(!harness.state().doc.model.curves[0].guide, "undo makes the curve carry its pattern again");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn growing_texture_shows_progress_and_stops_when_asked() {
    let (dir, _, _, mut harness) = model_export("texture-stop");
    {
        // A fine weave over the vase takes long enough to be stopped.
        let texture = &mut harness.state_mut().doc.model.texture;
        texture.swatch = "weave".into();
        texture.settings.scale = 0.5;
    }
    click_in_side_panel(&mut harness, "Cover the model with texture");
    let deadline = Instant::now() + Duration::from_secs(30);
    while !matches!(harness.state().texture_state(), Some(JobState::Running { .. })) && Instant::now() < deadline {
        harness.step();
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(matches!(harness.state().texture_state(), Some(JobState::Running { .. })), "the texture never started");
    harness.run_steps(2);
    // The status bar says what is running, beside its progress bar.
    harness.get_by_label("Growing the texture…");
    harness.get_by_label("Stop").click();
    harness.run_steps(2);
    let app = harness.state();
    assert!(!app.doc.model.texture.on, "Stop turns the texture off");
    assert!(!app.busy(), "nothing is left running");
    assert!(app.texture_state().is_none(), "the job is dropped, not left to finish");
    assert_eq!(app.doc.model.texture.swatch, "weave", "the choices are kept for later");
    let _ = std::fs::remove_dir_all(&dir);
}
