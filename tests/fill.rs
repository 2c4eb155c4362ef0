//! `tracery fill` end to end: regions filled with curve textures. The STL
//! is checked apart from the mesh code (closed, consistently oriented, its
//! shells counted from the file), every vertex must lie in the region and
//! out of its holes, the SVG must hold stroked paths, and bad input fails
//! with one line and leaves no file.

#[path = "common/cli.rs"]
mod cli;
#[path = "common/stl.rs"]
mod stl;
use cli::{field, report_of, tempdir, tracery};
use stl::{check_stl, stl_vertices};

fn path(p: &std::path::Path) -> String {
    p.display().to_string()
}

#[test]
fn list_curves_prints_every_builtin() {
    let out = tracery().args(["list", "--curves"]).output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for name in tracery_core::region_fill::BUILTIN_CURVES {
        assert!(text.lines().any(|l| l.starts_with(name)), "{name} missing from:\n{text}");
    }
}

#[test]
fn a_circle_of_crackle_is_a_sound_solid_inside_the_circle_with_stroked_paths() {
    let dir = tempdir("fill-circle");
    let (stl, svg) = (dir.join("c.stl"), dir.join("c.svg"));
    let radius = 22.0;
    let json = report_of(
        "fill",
        &["--exemplar", "crackle", "--region", "circle:22", "--stl", &path(&stl), "--svg", &path(&svg)],
        &dir.join("c.json"),
    );
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    let components: usize = field(&json, "components").parse().unwrap();
    assert_eq!(check.shells, components, "the report's components are the STL's bodies: {json}");
    // Crackle is a web of cells: in a circle it holds together in few
    // pieces, with many closed cells (holes).
    let holes: usize = field(&json, "holes").parse().unwrap();
    assert!(components <= 3 && holes >= 8, "{components} components, {holes} holes");
    for [x, y, _] in stl_vertices(&stl) {
        assert!(x.hypot(y) <= radius + 1e-3, "vertex at ({x}, {y}) outside the circle");
    }
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.matches("<path").count() >= 10, "{text}");
    assert!(text.contains("stroke-width=\"0.800\"") && text.contains("stroke-linecap=\"round\""));
    assert!(!text.contains("evenodd"), "strokes, not filled outlines");
}

#[test]
fn a_drawn_region_with_a_hole_and_a_frame_prints_as_one_piece() {
    let dir = tempdir("fill-hole");
    let region = dir.join("region.svg");
    // A 60 mm square with a 20 mm square hole, in a file sized in mm.
    std::fs::write(
        &region,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="60mm" viewBox="0 0 60 60">
  <path d="M0,0 H60 V60 H0 Z M20,20 V40 H40 V20 Z" fill-rule="evenodd"/></svg>"#,
    )
    .unwrap();
    let stl = dir.join("f.stl");
    let spec = format!("svg:{}", path(&region));
    let json = report_of(
        "fill",
        &["--exemplar", "waves", "--region", &spec, "--frame", "2", "--one-piece", "--stl", &path(&stl)],
        &dir.join("f.json"),
    );
    assert_eq!(field(&json, "one_piece"), "joined", "{json}");
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges, check.shells), (0, 0, 1), "{check:?}");
    // SVG y points down: the square spans y -60..0 once flipped.
    for [x, y, _] in stl_vertices(&stl) {
        assert!((-1e-3..=60.0 + 1e-3).contains(&x) && (-60.0 - 1e-3..=1e-3).contains(&y), "({x}, {y})");
        let in_hole = x > 20.0 + 1e-3 && x < 40.0 - 1e-3 && -y > 20.0 + 1e-3 && -y < 40.0 - 1e-3;
        assert!(!in_hole, "vertex at ({x}, {y}) inside the hole");
    }
}

#[test]
fn berries_print_their_elements_whole_and_draw_them_filled() {
    let dir = tempdir("fill-berries");
    let (stl, svg) = (dir.join("b.stl"), dir.join("b.svg"));
    let json = report_of(
        "fill",
        &["--exemplar", "berries", "--region", "rect:50x35", "--stl", &path(&stl), "--svg", &path(&svg)],
        &dir.join("b.json"),
    );
    let elements: usize = field(&json, "elements").parse().unwrap();
    // The exemplar has 20 in 40 x 40 mm; 50 x 35 mm less its edge holds more than 10.
    assert!(elements >= 10, "{json}");
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    assert_eq!(check.shells.to_string(), field(&json, "components"), "{json}");
    // The SVG strokes the paths and fills the elements, one path each.
    let text = std::fs::read_to_string(&svg).unwrap();
    let (strokes, filled) = text.split_once(r#"<g id="elements""#).expect("an elements group");
    assert_eq!(filled.matches("<path").count(), elements);
    assert!(strokes.matches("<path").count() >= 10 && strokes.contains(r#"fill="none""#));
}

#[test]
fn bad_input_fails_with_one_line_and_no_file() {
    let dir = tempdir("fill-bad");
    let bow_tie = dir.join("bow.svg");
    std::fs::write(
        &bow_tie,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 50 50"><path d="M0,0 L50,50 L50,0 L0,50 Z"/></svg>"#,
    )
    .unwrap();
    let empty = dir.join("empty.svg");
    std::fs::write(&empty, r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 50 50"></svg>"#).unwrap();
    // One ring 300 mm across: a 40 mm region falls inside it, with nothing to copy.
    let ring = dir.join("ring.svg");
    std::fs::write(
        &ring,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="320mm" height="320mm" viewBox="0 0 320 320"><circle cx="160" cy="160" r="150" fill="none" stroke="black"/></svg>"#,
    )
    .unwrap();
    // One L-shaped band, a picture frame's corner: a single line.
    let corner = dir.join("corner.svg");
    std::fs::write(
        &corner,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200"><path d="M0,200 L0,0 L200,0 L200,10 L10,10 L10,200 Z"/></svg>"#,
    )
    .unwrap();
    let stl = dir.join("out.stl");
    let cases: [(&[&str], &str); 9] = [
        (&["--exemplar", "waves", "--region", "circle:3"], "too small"),
        (&["--exemplar", "waves", "--region", "hexagon:3"], "not a region"),
        (&["--exemplar", "waves", "--region", &format!("svg:{}", path(&bow_tie))], "crosses itself"),
        (&["--exemplar", &path(&empty), "--region", "rect:40x40"], "no stroked path"),
        (&["--exemplar", "waves", "--region", "rect:40x40", "--stroke-width", "-1"], "stroke width"),
        (&["--exemplar", "waves", "--region", "rect:40x40", "--exemplar-scale", "0"], "exemplar scale"),
        // Waves shrunk to under a millimetre: finer than any sample spacing.
        (&["--exemplar", "waves", "--region", "rect:40x40", "--exemplar-scale", "0.02"], "nothing of the exemplar"),
        (&["--exemplar", &path(&ring), "--region", "rect:40x40"], "far larger than the 40 x 40 mm region"),
        (&["--exemplar", &path(&corner), "--region", "rect:60x40", "--exemplar-scale", "0.3"], "only 1 line"),
    ];
    for (args, expected) in cases {
        let out = tracery().arg("fill").args(args).arg("--stl").arg(&stl).output().unwrap();
        assert!(!out.status.success(), "{args:?} succeeded");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(expected), "{args:?}: {err}");
        assert!(!stl.exists(), "{args:?} left a file");
    }
}
