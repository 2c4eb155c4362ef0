//! The desktop app, driven like a person would: with egui_kittest.

use egui::accesskit::Role;
use egui::{Key, Modifiers, PointerButton, Pos2};
use egui_kittest::kittest::Queryable;
use tracery::dialogs::FileKind;
use tracery::document::ModeSettings;
use tracery::worker::JobState;
use tracery_core::quality::tightest_turn;

#[path = "common/drive.rs"]
mod drive;
#[path = "common/stl.rs"]
mod stl;
#[path = "common/threemf.rs"]
mod threemf;
#[path = "common/ui.rs"]
mod ui;
use drive::{circle, click_in_side_panel, drag, harness, press};
use ui::settle;

#[test]
fn a_drag_on_the_canvas_yields_a_pattern() {
    let mut harness = harness(vec![]);
    harness.step();
    drag(&mut harness, &circle(Pos2::new(760.0, 400.0), 110.0));
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.doc.curves.len(), 1);
    let curve = &app.doc.curves[0];
    assert!(curve.closed, "a stroke ending at its start closes into a loop");
    let output = app.output(curve.id).expect("a pattern");
    assert_eq!(output.topology.components, 1);
    assert_eq!(output.topology.loop_openings, 1, "the default pattern runs around the loop");
    assert!(!output.fill_mm.is_empty());
    // The status bar tells what was found.
    harness.get_by_label_contains("1 component(s)");
}

#[test]
fn a_stroke_keeps_every_move_when_frames_are_slow() {
    // A busy frame delivers many pointer moves at once, the first of them
    // before egui has recognised a drag: every one of them is the person's
    // stroke. Here the loop's first quarter arrives with the press, and the
    // rest eight moves a frame, the last eight with the release.
    let mut harness = harness(vec![]);
    harness.step();
    let center = Pos2::new(760.0, 400.0);
    let radius = 110.0;
    let points = circle(center, radius);
    harness.hover_at(points[0]);
    harness.step();
    // The harness runs a frame per queued event, so the moves go straight
    // into the next frame's input, as a busy frame would get them.
    let press_event = egui::Event::PointerButton {
        pos: points[0],
        button: PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    };
    harness.input_mut().events.push(press_event);
    harness.input_mut().events.extend(points[1..=16].iter().map(|&p| egui::Event::PointerMoved(p)));
    harness.step();
    for frame in points[17..57].chunks(8) {
        harness.input_mut().events.extend(frame.iter().map(|&p| egui::Event::PointerMoved(p)));
        harness.step();
    }
    // The last eighth comes in the frame the button is released in.
    harness.input_mut().events.extend(points[57..].iter().map(|&p| egui::Event::PointerMoved(p)));
    let release = egui::Event::PointerButton {
        pos: *points.last().unwrap(),
        button: PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    };
    harness.input_mut().events.push(release);
    harness.step();
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.doc.curves.len(), 1);
    let curve = &app.doc.curves[0];
    assert!(curve.closed, "the stroke ends where it began, so it closes");
    // Every control point lies on the drawn circle: none cuts a chord
    // across moves that were dropped. Control points are evenly spaced, so
    // their mean is the circle's centre.
    let count = curve.points.len() as f64;
    let points: Vec<tracery_core::DVec2> = curve.points.iter().map(|&p| p.into()).collect();
    let centre = points.iter().fold(tracery_core::DVec2::ZERO, |sum, &p| sum + p) / count;
    let radii: Vec<f64> = points.iter().map(|p| p.distance(centre)).collect();
    let mean = radii.iter().sum::<f64>() / count;
    let worst = radii.iter().map(|r| (r - mean).abs() / mean).fold(0.0, f64::max);
    assert!(worst < 0.03, "a control point lies {:.1}% of the radius off the drawn circle", worst * 100.0);
}

#[test]
fn moving_a_slider_yields_a_new_result() {
    let mut harness = harness(vec![]);
    harness.step();
    let wave: Vec<Pos2> =
        (0..=40).map(|k| Pos2::new(450.0 + k as f32 * 15.0, 400.0 + 60.0 * (k as f32 / 6.0).sin())).collect();
    drag(&mut harness, &wave);
    settle(&mut harness);
    let id = harness.state().doc.curves[0].id;
    let first = harness.state().output(id).expect("a first pattern").clone();
    let band_before = harness.state().doc.curves[0].mode.band_mm();
    harness.get_by_role_and_label(Role::Slider, "Band width (mm)").focus();
    harness.step();
    for _ in 0..10 {
        harness.key_press(Key::ArrowRight);
        harness.step();
    }
    settle(&mut harness);
    let app = harness.state();
    assert!(app.doc.curves[0].mode.band_mm() > band_before);
    let second = app.output(id).expect("a second pattern");
    assert!(!std::sync::Arc::ptr_eq(&first, second), "the pattern was synthesized again");
    // The exemplar is scaled to the band: a wider band gives more material
    // along the same curve (the outline's height also depends on how the
    // band turns at the wave's crests, so area is the steadier measure).
    let area = |o: &tracery_core::Product| o.region_mm.area();
    assert!(area(second) > area(&first), "a wider band gives a bigger pattern: {} then {}", area(&first), area(second));
}

#[test]
fn a_larger_corner_radius_turns_the_inside_of_a_sharp_corner_wider() {
    let mut harness = harness(vec![]);
    harness.step();
    // A V whose legs meet at about 67°.
    let leg = |from: Pos2, to: Pos2| (0..=20).map(move |k| from + (to - from) * (k as f32 / 20.0));
    let vee: Vec<Pos2> = leg(Pos2::new(560.0, 250.0), Pos2::new(700.0, 560.0))
        .chain(leg(Pos2::new(700.0, 560.0), Pos2::new(840.0, 250.0)).skip(1))
        .collect();
    drag(&mut harness, &vee);
    settle(&mut harness);
    let id = harness.state().doc.curves[0].id;
    let inside_before = {
        let edges = &harness.state().output(id).expect("a first pattern").overlays.band_edges_mm;
        edges.iter().map(|e| tightest_turn(e, false, 1.0)).fold(f64::INFINITY, f64::min)
    };
    harness.get_by_role_and_label(Role::Slider, "Corners (mm)").set_value_accesskit(15.0);
    harness.step();
    settle(&mut harness);
    let app = harness.state();
    let ModeSettings::VectorBrush(item) = &app.doc.curves[0].mode else { panic!("not the vector brush") };
    let asked_mm = item.settings.corner_radius_mm;
    let least_mm = 1.25 * 0.5 * item.settings.band_mm;
    assert!(asked_mm > least_mm + 5.0, "the slider asked for {asked_mm:.2} mm");
    let output = app.output(id).expect("a second pattern");
    assert_eq!(output.topology.components, 1);
    // The band's inner edge turns the corner on the radius less half the
    // band: a quarter of a half band before, far more now.
    let inside_after =
        output.overlays.band_edges_mm.iter().map(|e| tightest_turn(e, false, 1.0)).fold(f64::INFINITY, f64::min);
    let expected_mm = asked_mm - 0.5 * item.settings.band_mm;
    assert!(inside_before < 0.5 * expected_mm, "before: {inside_before:.2} mm");
    assert!(inside_after > 0.8 * expected_mm, "after: {inside_after:.2} mm, asked {asked_mm:.2} mm");
}

#[test]
fn export_writes_a_valid_stl() {
    let path = std::env::temp_dir().join(format!("tracery-app-{}.stl", std::process::id()));
    let _ = std::fs::remove_file(&path);
    let mut harness = harness(vec![(FileKind::ExportStl, path.clone())]);
    harness.step();
    drag(&mut harness, &circle(Pos2::new(700.0, 380.0), 90.0));
    let wave: Vec<Pos2> =
        (0..=30).map(|k| Pos2::new(420.0 + k as f32 * 20.0, 560.0 + 30.0 * (k as f32 / 4.0).sin())).collect();
    drag(&mut harness, &wave);
    settle(&mut harness);
    assert_eq!(harness.state().doc.curves.len(), 2);
    click_in_side_panel(&mut harness, "Export STL…");
    let states: Vec<String> = harness
        .state()
        .doc
        .curves
        .iter()
        .map(|c| {
            format!(
                "{:?}",
                harness.state().job_state(c.id).map(|s| match s {
                    JobState::Done(Err(e)) => e.to_string(),
                    _ => "ok".into(),
                })
            )
        })
        .collect();
    assert!(path.exists(), "no STL written: {:?} {states:?}", harness.state().message);
    let check = stl::check_stl(&path);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    let components: usize =
        harness.state().doc.curves.iter().map(|c| harness.state().output(c.id).unwrap().topology.components).sum();
    assert_eq!(check.shells, components);
    assert_eq!(check.shells, 2, "one part per curve");
    assert!(check.triangles > 100);
    let _ = std::fs::remove_file(&path);
}

#[test]
fn export_writes_a_3mf_with_one_object_per_curve_and_a_cut_svg() {
    let dir = std::env::temp_dir().join(format!("tracery-app-3mf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (three_mf, svg) = (dir.join("pattern.3mf"), dir.join("pattern.svg"));
    let mut harness = harness(vec![(FileKind::Export3mf, three_mf.clone()), (FileKind::ExportSvg, svg.clone())]);
    harness.step();
    drag(&mut harness, &circle(Pos2::new(700.0, 380.0), 90.0));
    let wave: Vec<Pos2> =
        (0..=30).map(|k| Pos2::new(420.0 + k as f32 * 20.0, 560.0 + 30.0 * (k as f32 / 4.0).sin())).collect();
    drag(&mut harness, &wave);
    settle(&mut harness);
    click_in_side_panel(&mut harness, "Export 3MF…");
    let bytes = std::fs::read(&three_mf).unwrap_or_else(|e| panic!("no 3MF ({e}): {:?}", harness.state().message));
    let read = threemf::read_3mf(&bytes);
    assert_eq!(read.unit, "millimeter");
    let names: Vec<&str> = read.objects.iter().map(|o| o.0.as_str()).collect();
    assert_eq!(names, ["Curve 0", "Curve 1"], "named as on screen");
    assert!(read.objects.iter().all(|o| threemf::is_closed(&o.2)));
    if let Some((manifold, objects)) = threemf::prusa_info(&three_mf) {
        assert!(manifold);
        assert_eq!(objects, 2);
    }
    // Cut flavour: only stroked outlines, in mm.
    click_in_side_panel(&mut harness, "cutting");
    click_in_side_panel(&mut harness, "Export SVG…");
    let text = std::fs::read_to_string(&svg).expect("an SVG written");
    assert!(text.contains(r#"fill="none""#) && !text.contains(r#"fill="black""#));
    assert!(text.contains(r#"mm" height="#));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_ring_tool_hangs_a_pendant_from_a_jump_ring_where_clicked() {
    let mut harness = harness(vec![]);
    harness.step();
    drag(&mut harness, &circle(Pos2::new(700.0, 420.0), 60.0));
    settle(&mut harness);
    harness.get_by_label("Ring").click();
    harness.step();
    // Just above the loop's top.
    let above = Pos2::new(700.0, 420.0 - 60.0 - 45.0);
    harness.hover_at(above);
    harness.step();
    press(&harness, above, true);
    harness.step();
    press(&harness, above, false);
    harness.step();
    settle(&mut harness);
    let app = harness.state();
    let curve = &app.doc.curves[0];
    assert_eq!(curve.jump_rings.at.len(), 1, "{:?}", app.message);
    let product = app.output(curve.id).expect("a pattern");
    assert_eq!((product.topology.components, product.topology.jump_rings), (1, 1));
    assert_eq!(product.mesh_mm.as_ref().unwrap().shell_count(), 1);
    harness.get_by_label_contains("+ 1 jump ring");
    // Drawing another curve leaves the pendant's ring alone.
    harness.get_by_label("Draw").click();
    harness.step();
    let wave: Vec<Pos2> = (0..=30).map(|k| Pos2::new(420.0 + k as f32 * 15.0, 560.0)).collect();
    drag(&mut harness, &wave);
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.doc.curves.len(), 2);
    assert_eq!(app.doc.curves[0].jump_rings.at.len(), 1);
    assert_eq!(app.output(app.doc.curves[0].id).unwrap().topology.jump_rings, 1, "the pendant keeps its ring");
    assert!(app.doc.curves[1].jump_rings.at.is_empty());
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    // Undo takes the ring away again.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    assert!(harness.state().doc.curves[0].jump_rings.at.is_empty());
}

#[test]
fn the_gallery_offers_distinct_solutions_and_another_one_steps_through_them() {
    let mut harness = harness(vec![]);
    harness.step();
    let wave: Vec<Pos2> =
        (0..=40).map(|k| Pos2::new(450.0 + k as f32 * 15.0, 380.0 + 50.0 * (k as f32 / 6.0).sin())).collect();
    drag(&mut harness, &wave);
    settle(&mut harness);
    for _ in 0..200 {
        let id = harness.state().doc.curves[0].id;
        if harness.state().gallery(id).is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
        harness.step();
    }
    let id = harness.state().doc.curves[0].id;
    let solutions = harness.state().gallery(id).expect("a gallery").clone();
    let (all, shown) = (&solutions.products, &solutions.shown);
    assert!(shown.len() >= 4, "only {} distinct solutions", shown.len());
    let best = harness.state().output(id).unwrap().clone();
    // Click the third thumbnail shown.
    let k = shown[2];
    // The strip takes its height from what it showed the frame before.
    harness.run_steps(3);
    harness.get_by_label(&format!("Solution {}", k + 1)).click();
    harness.step();
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.doc.curves[0].mode.alternative(), k as u32);
    let picked = app.output(id).unwrap();
    assert_eq!(picked.facts.get("piece_sequence"), all[k].facts.get("piece_sequence"), "the picture is the pattern");
    assert_ne!(picked.facts.get("piece_sequence"), best.facts.get("piece_sequence"));
    // "Another one" goes on to the next distinct solution.
    click_in_side_panel(&mut harness, "Another one");
    assert_eq!(harness.state().doc.curves[0].mode.alternative(), shown[3] as u32);
}

#[test]
fn the_pattern_grows_under_the_pointer_while_the_stroke_is_drawn() {
    let mut harness = harness(vec![]);
    harness.step();
    let wave: Vec<Pos2> =
        (0..=50).map(|k| Pos2::new(420.0 + k as f32 * 10.0, 380.0 + 40.0 * (k as f32 / 7.0).sin())).collect();
    harness.hover_at(wave[0]);
    harness.step();
    press(&harness, wave[0], true);
    harness.step();
    let mut seen = Vec::new();
    for &p in &wave[1..] {
        harness.hover_at(p);
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(5));
        if let Some(live) = harness.state().live_output() {
            seen.push((live.region_mm.bounds().unwrap().width(), live.topology.components));
        }
    }
    // Still drawing: the pattern has kept up with the pointer.
    assert!(seen.len() > 10, "only {} previews while drawing", seen.len());
    assert!(seen.iter().all(|&(_, components)| components == 1));
    assert!(seen.last().unwrap().0 > 2.0 * seen[0].0, "the preview grows with the stroke: {seen:?}");
    press(&harness, *wave.last().unwrap(), false);
    harness.step();
    settle(&mut harness);
    let app = harness.state();
    assert!(app.live_output().is_none(), "the preview goes once the stroke ends");
    let id = app.doc.curves[0].id;
    assert_eq!(app.output(id).expect("the curve's own pattern").topology.components, 1);
}

#[test]
fn a_broken_svg_import_shows_an_error_and_changes_nothing() {
    let path = std::env::temp_dir().join(format!("tracery-broken-{}.svg", std::process::id()));
    std::fs::write(&path, "<svg xmlns='http://www.w3.org/2000/svg'><path d='M0 0 L10").unwrap();
    let mut harness = harness(vec![(FileKind::ImportSvg, path.clone())]);
    harness.step();
    drag(&mut harness, &circle(Pos2::new(700.0, 400.0), 80.0));
    settle(&mut harness);
    let before = harness.state().doc.clone();
    click_in_side_panel(&mut harness, "Import SVG…");
    harness.step();
    let app = harness.state();
    assert_eq!(app.doc, before, "the document is unchanged");
    let (message, error) = app.message.clone().expect("a message");
    assert!(error && message.starts_with("Could not import"), "{message}");
    harness.get_by_label_contains("Could not import");
    let _ = std::fs::remove_file(&path);
}

#[test]
fn undo_restores_a_deleted_curve() {
    let mut harness = harness(vec![]);
    harness.step();
    drag(&mut harness, &circle(Pos2::new(700.0, 400.0), 80.0));
    settle(&mut harness);
    let drawn = harness.state().doc.clone();
    assert_eq!(drawn.curves.len(), 1);
    assert!(harness.state().selected.is_some(), "a new curve is selected");
    harness.key_press(Key::Delete);
    harness.step();
    assert!(harness.state().doc.curves.is_empty());
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    assert_eq!(harness.state().doc, drawn);
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Y);
    harness.step();
    assert!(harness.state().doc.curves.is_empty(), "redo deletes it again");
}
