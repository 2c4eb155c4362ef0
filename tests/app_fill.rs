//! Region fill in the desktop app, driven as a person would: pick the mode,
//! draw an outline, draw pen strokes in it, take or refuse autocomplete's
//! and clone's suggestions with the mouse and keys, undo, export.

use egui::{Key, Modifiers, Pos2};
use egui_kittest::kittest::Queryable;
use tracery::dialogs::FileKind;
use tracery::document::ModeSettings;
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
use drive::{circle, click_in_side_panel, drag, harness};
use stl::check_stl;
use ui::settle;

type App = egui_kittest::Harness<'static, tracery::TraceryApp>;

/// The canvas's centre on screen, where the view's origin is.
const CENTRE: Pos2 = Pos2::new(775.0, 410.0);

fn pens(harness: &App) -> usize {
    harness.state().doc.curves.iter().filter(|c| matches!(c.mode, ModeSettings::Pen(_))).count()
}

/// A wavy pen stroke across the fill, screen points.
fn stroke(from: Pos2, length: f32) -> Vec<Pos2> {
    (0..=30)
        .map(|k| {
            let t = k as f32 / 30.0;
            from + egui::vec2(length * t, 12.0 * (t * std::f32::consts::TAU).sin())
        })
        .collect()
}

/// Whether `p` is inside the closed polyline `ring` (even-odd), written here apart from the geometry code.
fn inside(ring: &[DVec2], p: DVec2) -> bool {
    let mut crossings = 0;
    for (k, a) in ring.iter().enumerate() {
        let b = ring[(k + 1) % ring.len()];
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            crossings += 1;
        }
    }
    crossings % 2 == 1
}

/// Chooses the mode *Region fill* for what is drawn next.
fn choose_region_fill(harness: &mut App) {
    harness.get_by_label("Mode").click();
    harness.run_steps(2);
    harness.get_by_label("Region fill").click();
    harness.run_steps(2);
    assert!(matches!(harness.state().settings(), ModeSettings::RegionFill(_)));
}

/// Chooses *Region fill* with the berries for what is drawn next.
fn choose_berries(harness: &mut App) {
    choose_region_fill(harness);
    // The thumbnail and the name under it both read "berries": the name.
    harness.query_all_by_label("berries").last().expect("the berries' name").scroll_to_me();
    harness.run_steps(3);
    harness.query_all_by_label("berries").last().expect("the berries' name").click();
    harness.step();
}

/// Draws a region fill's outline and waits for it; returns the fill's id.
fn draw_fill(harness: &mut App) -> u64 {
    choose_region_fill(harness);
    draw_outline(harness)
}

/// Draws the outline of a fill of the chosen kind and waits for it; returns its id.
fn draw_outline(harness: &mut App) -> u64 {
    drag(harness, &circle(CENTRE, 110.0));
    settle(harness);
    let fill = &harness.state().doc.curves[0];
    assert!(fill.closed, "a region's outline is a loop");
    fill.id
}

/// Steps until the predictions are made; returns them.
fn wait_for_predictions(harness: &mut App) -> Vec<Vec<DVec2>> {
    settle(harness);
    let prediction = harness.state().predicted().expect("predictions on screen");
    prediction.paths.iter().map(|p| p.points_mm.clone()).collect()
}

#[test]
fn a_drawn_region_fills_and_prints_as_one_sound_solid() {
    let dir = tempdir("app-fill");
    let mut harness = harness(vec![(FileKind::ExportStl, dir.join("fill.stl"))]);
    harness.step();
    let id = draw_fill(&mut harness);
    let product = harness.state().output(id).expect("a fill").clone();
    assert!(product.paths_mm.len() > 5, "the region is filled with paths");
    let outline = harness.state().doc.curve(id).unwrap().control_points();
    // Every path point is inside the outline drawn (its control polygon, with a 2 mm allowance for smoothing).
    let bounds_r = outline.iter().map(|p| p.length()).fold(0.0, f64::max);
    for p in product.paths_mm.iter().flat_map(|p| &p.points_mm) {
        assert!(p.length() <= bounds_r + 2.0, "a path leaves the region at {p:?}");
    }
    harness.key_press_modifiers(Modifiers::COMMAND, Key::E);
    harness.run_steps(2);
    let stl = check_stl(&dir.join("fill.stl"));
    assert_eq!(stl.shells, product.topology.components, "the STL's bodies are the fill's components");
}

#[test]
fn autocomplete_suggests_paths_that_are_accepted_picked_or_refused() {
    let mut harness = harness(Vec::new());
    harness.step();
    let fill = draw_fill(&mut harness);
    click_in_side_panel(&mut harness, "Fill automatically");
    settle(&mut harness);
    let ModeSettings::RegionFill(item) = &harness.state().doc.curve(fill).unwrap().mode else { panic!("not a fill") };
    assert!(!item.fill_automatically);
    // The tools are at the top of the side panel, which may have scrolled.
    click_in_side_panel(&mut harness, "Pen");

    // A stroke: suggestions appear around it, inside the fill.
    drag(&mut harness, &stroke(CENTRE + egui::vec2(-60.0, 20.0), 120.0));
    assert_eq!(pens(&harness), 1);
    let outline = harness.state().doc.curve(fill).unwrap().control_points();
    let suggested = wait_for_predictions(&mut harness);
    assert!(!suggested.is_empty(), "autocomplete suggests paths");
    for p in suggested.iter().flatten() {
        // The control polygon lies just inside the smoothed outline; 1 mm of allowance.
        let nearest_out = outline.iter().map(|q| q.distance(*p)).fold(f64::MAX, f64::min);
        assert!(inside(&outline, *p) || nearest_out < 3.0, "a suggestion leaves the fill at {p:?}");
    }
    harness.get_by_label_contains("suggested path(s)");

    // Escape refuses them: nothing is added.
    harness.key_press(Key::Escape);
    harness.run_steps(2);
    assert!(harness.state().predicted().is_none());
    assert_eq!(pens(&harness), 1);

    // Another stroke; a click on one suggestion picks it, A accepts it alone.
    drag(&mut harness, &stroke(CENTRE + egui::vec2(-60.0, -30.0), 120.0));
    let suggested = wait_for_predictions(&mut harness);
    let (view, rect) = harness.state().canvas_view().expect("the canvas is laid out");
    let longest = suggested.iter().max_by(|a, b| a.len().cmp(&b.len())).unwrap();
    let on_path = longest[longest.len() / 2];
    harness.hover_at(view.to_screen(rect, on_path));
    harness.step();
    drive::press(&harness, view.to_screen(rect, on_path), true);
    harness.step();
    drive::press(&harness, view.to_screen(rect, on_path), false);
    harness.run_steps(2);
    harness.get_by_label_contains("1 picked");
    harness.key_press(Key::A);
    harness.run_steps(2);
    assert_eq!(pens(&harness), 3, "two strokes drawn and one suggestion accepted");

    // A third stroke; Enter accepts every suggestion, and undo takes them back at once.
    drag(&mut harness, &stroke(CENTRE + egui::vec2(-40.0, 60.0), 80.0));
    let suggested = wait_for_predictions(&mut harness);
    harness.key_press(Key::Enter);
    harness.run_steps(2);
    let accepted = pens(&harness) - 4;
    assert!(accepted >= 1 && accepted <= suggested.len());
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run_steps(2);
    assert_eq!(pens(&harness), 4, "undo takes the accepted suggestions back");
    // Accepted strokes print with the fill: its solid holds them.
    settle(&mut harness);
    let product = harness.state().output(fill).expect("the fill's print").clone();
    assert!(product.mesh_mm.is_some() && product.topology.components >= 1);
}

#[test]
fn clone_copies_what_was_drawn_in_a_source_to_a_target() {
    let mut harness = harness(Vec::new());
    harness.step();
    let fill = draw_fill(&mut harness);
    click_in_side_panel(&mut harness, "Fill automatically");
    // The tools are at the top of the side panel, which may have scrolled.
    click_in_side_panel(&mut harness, "Pen");
    for k in 0..4 {
        drag(&mut harness, &stroke(CENTRE + egui::vec2(-90.0, -70.0 + 14.0 * k as f32), 70.0));
        harness.key_press(Key::Escape);
        harness.run_steps(2);
    }
    assert_eq!(pens(&harness), 4);
    click_in_side_panel(&mut harness, "Clone");
    // The source around the strokes, then the target to their right.
    drag(&mut harness, &[CENTRE + egui::vec2(-95.0, -85.0), CENTRE + egui::vec2(-15.0, -10.0)]);
    assert!(harness.state().predicted().is_none());
    drag(&mut harness, &[CENTRE + egui::vec2(5.0, -85.0), CENTRE + egui::vec2(85.0, -10.0)]);
    let suggested = wait_for_predictions(&mut harness);
    assert!(!suggested.is_empty(), "the clone suggests paths");
    // They lie in the target.
    let (view, rect) = harness.state().canvas_view().expect("the canvas is laid out");
    let (left, right) = (
        view.from_screen(rect, CENTRE + egui::vec2(5.0, 0.0)).x,
        view.from_screen(rect, CENTRE + egui::vec2(85.0, 0.0)).x,
    );
    for p in suggested.iter().flatten() {
        assert!(p.x > left - 0.1 && p.x < right + 0.1, "a cloned path outside the target at {p:?}");
    }
    harness.get_by_label("Accept all").click();
    harness.run_steps(2);
    assert!(pens(&harness) > 4);
    assert!(harness.state().doc.curve(fill).is_some());
}

/// The share of `paths`' length in segments within 20° of horizontal.
fn horizontal_share(paths: &[Vec<DVec2>]) -> f64 {
    let (mut level, mut all) = (0.0, 0.0);
    for w in paths.iter().flat_map(|p| p.windows(2)) {
        let d = w[1] - w[0];
        all += d.length();
        if d.y.abs() <= d.x.abs() * 20f64.to_radians().tan() {
            level += d.length();
        }
    }
    level / all
}

#[test]
fn a_curve_exemplar_imported_in_region_fill_is_what_the_fill_is_made_of() {
    let dir = tempdir("app-fill-import");
    // Rows of gentle waves, 40 mm wide: nothing like any built-in.
    let rows: String = (0..8)
        .map(|k| {
            let y = 3.0 + 4.5 * k as f64;
            format!("<path d='M 0 {y} C 10 {a} 20 {b} 40 {y}' fill='none' stroke='black'/>", a = y - 1.0, b = y + 1.0)
        })
        .collect();
    let svg =
        format!("<svg xmlns='http://www.w3.org/2000/svg' width='40mm' height='38mm' viewBox='0 0 40 38'>{rows}</svg>");
    std::fs::write(dir.join("rows.svg"), svg).unwrap();
    std::fs::write(dir.join("words.svg"), "<svg xmlns='http://www.w3.org/2000/svg'><text>no strokes</text></svg>")
        .unwrap();
    let mut harness =
        harness(vec![(FileKind::ImportSvg, dir.join("words.svg")), (FileKind::ImportSvg, dir.join("rows.svg"))]);
    harness.step();
    choose_region_fill(&mut harness);

    // A drawing without strokes is refused, and nothing changes.
    click_in_side_panel(&mut harness, "Import SVG…");
    harness.run_steps(2);
    assert!(harness.state().doc.imported.is_empty());
    harness.get_by_label_contains("Could not import");

    // The rows are imported as a curve exemplar and chosen.
    click_in_side_panel(&mut harness, "Import SVG…");
    harness.run_steps(2);
    let ModeSettings::RegionFill(item) = harness.state().settings() else { panic!("the controls left region fill") };
    assert_eq!(item.exemplar.name(), "rows");
    assert!(harness.query_all_by_label("rows").count() >= 1, "the picker shows the imported rows");

    // A fill drawn now is made of rows: its paths run level, where the
    // built-in exemplars run every way.
    let fill = draw_outline(&mut harness);
    let product = harness.state().output(fill).expect("a fill").clone();
    let paths: Vec<Vec<DVec2>> = product.paths_mm.iter().map(|p| p.points_mm.clone()).collect();
    assert!(paths.len() >= 4, "the fill has paths");
    let share = horizontal_share(&paths);
    assert!(share > 0.8, "only {share:.2} of the fill runs level like the rows");
}

#[test]
fn berries_chosen_in_the_app_fill_with_whole_elements_inside_the_outline() {
    let mut harness = harness(Vec::new());
    harness.step();
    choose_berries(&mut harness);
    let ModeSettings::RegionFill(item) = harness.state().settings() else { panic!("the controls left region fill") };
    assert_eq!(item.exemplar.name(), "berries");
    let id = draw_outline(&mut harness);
    let product = harness.state().output(id).expect("a fill").clone();
    let elements = &product.filled_mm.polygons;
    assert!(elements.len() >= 5, "only {} elements", elements.len());
    assert_eq!(product.facts.count("elements"), Some(elements.len()));
    // Whole, and inside the outline drawn (its control polygon, with the
    // same 2 mm allowance the paths get for smoothing the outline).
    let outline = harness.state().doc.curve(id).unwrap().control_points();
    let reach = outline.iter().map(|p| p.length()).fold(0.0, f64::max) + 2.0;
    for shape in elements {
        assert!(shape.outer.iter().all(|p| p.length() <= reach), "an element leaves the region");
        let centre = shape.outer.iter().copied().sum::<DVec2>() / shape.outer.len() as f64;
        assert!(inside(&shape.outer, centre), "an element is not a filled shape round its centre");
    }
}

/// The filled pen shapes of the document: their control polygons, mm.
fn filled_shapes(harness: &App) -> Vec<Vec<DVec2>> {
    let app = harness.state();
    app.doc
        .curves
        .iter()
        .filter(|c| matches!(&c.mode, ModeSettings::Pen(pen) if pen.filled) && c.closed)
        .map(|c| c.control_points())
        .collect()
}

/// Whether two outlines share area: a point of either inside the other.
fn overlap(a: &[DVec2], b: &[DVec2]) -> bool {
    a.iter().any(|p| inside(b, *p)) || b.iter().any(|p| inside(a, *p))
}

#[test]
fn berries_suggested_are_accepted_as_filled_shapes_that_print_and_clone() {
    let mut harness = harness(Vec::new());
    harness.step();
    choose_berries(&mut harness);
    let fill = draw_outline(&mut harness);
    click_in_side_panel(&mut harness, "Fill automatically");
    click_in_side_panel(&mut harness, "Pen");

    // A stalk drawn: berries are suggested beside the paths.
    drag(&mut harness, &stroke(CENTRE + egui::vec2(-70.0, 40.0), 140.0));
    settle(&mut harness);
    let suggested = harness.state().predicted().expect("predictions on screen").clone();
    assert!(!suggested.elements.is_empty(), "no berries suggested: {} paths", suggested.paths.len());
    harness.get_by_label_contains("element(s)");
    // Enter takes them all: each berry a filled pen shape, in one step of undo.
    let before = harness.state().doc.curves.len();
    harness.key_press(Key::Enter);
    harness.run_steps(2);
    let shapes = filled_shapes(&harness);
    assert_eq!(shapes.len(), suggested.elements.len(), "{:?}", harness.state().message);
    assert_eq!(harness.state().doc.curves.len(), before + suggested.paths.len() + suggested.elements.len());
    // They print with the fill (only what was drawn prints, the fill being off).
    settle(&mut harness);
    let print = harness.state().output(fill).expect("the fill's print").clone();
    for shape in &shapes {
        let centre = shape.iter().copied().sum::<DVec2>() / shape.len() as f64;
        assert!(print.region_mm.contains(centre), "an accepted berry at {centre:?} does not print");
    }

    // Another stalk above: new berries keep off the accepted ones.
    drag(&mut harness, &stroke(CENTRE + egui::vec2(-70.0, -10.0), 140.0));
    settle(&mut harness);
    let again = harness.state().predicted().expect("predictions on screen").clone();
    for e in &again.elements {
        assert!(!shapes.iter().any(|s| overlap(&e.outer, s)), "a suggested berry lies on an accepted one");
    }
    harness.key_press(Key::Escape);
    harness.run_steps(2);

    // Clone: the berries in a source rectangle come back in the target.
    click_in_side_panel(&mut harness, "Clone");
    drag(&mut harness, &[CENTRE + egui::vec2(-80.0, 10.0), CENTRE + egui::vec2(0.0, 80.0)]);
    drag(&mut harness, &[CENTRE + egui::vec2(-60.0, -95.0), CENTRE + egui::vec2(20.0, -25.0)]);
    settle(&mut harness);
    let cloned = harness.state().predicted().expect("the clone's suggestions").clone();
    assert!(!cloned.elements.is_empty(), "the clone suggests no berry: {} paths", cloned.paths.len());
    let (view, rect) = harness.state().canvas_view().expect("the canvas is laid out");
    let target = tracery_core::geom::Rect::new(
        view.from_screen(rect, CENTRE + egui::vec2(-60.0, -25.0)),
        view.from_screen(rect, CENTRE + egui::vec2(20.0, -95.0)),
    );
    for e in &cloned.elements {
        assert!(e.outer.iter().all(|p| p.cmpge(target.min - 0.1).all() && p.cmple(target.max + 0.1).all()));
    }
    // Undo takes the accepted berries back at once.
    for _ in 0..2 {
        harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        harness.run_steps(2);
    }
    assert!(filled_shapes(&harness).is_empty(), "undo leaves {} berries", filled_shapes(&harness).len());
}
