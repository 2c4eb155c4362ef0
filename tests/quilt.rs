//! `tracery quilt` end to end: the STL is checked apart from the mesh code
//! (closed, consistently oriented, its shells counted from the file) and
//! bad input fails with one line and leaves no file.

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
fn list_swatches_prints_every_builtin() {
    let out = tracery().args(["list", "--swatches"]).output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for name in tracery_core::mesh_quilt::SWATCH_NAMES {
        assert!(text.lines().any(|l| l.starts_with(name)), "{name} missing from:\n{text}");
    }
}

#[test]
fn a_plane_of_rivets_is_one_closed_body_per_element() {
    let dir = tempdir("quilt-rivets");
    let stl = dir.join("r.stl");
    let json = report_of(
        "quilt",
        &["--swatch", "rivets", "--base", "plane:50x40", "--scale", "0.8", "--stl", &path(&stl)],
        &dir.join("r.json"),
    );
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    let elements: usize = field(&json, "elements").parse().unwrap();
    assert_eq!(check.shells, elements, "{json}");
    assert_eq!(field(&json, "closed_elements"), field(&json, "elements"), "{json}");
    assert_eq!(field(&json, "self_crossing_elements"), "0", "{json}");
    assert!(elements >= 25, "{json}");
    assert!(json.contains("\"timings_ms\"") && json.contains("\"warnings\""), "{json}");
    // Elements lie on the plane's area, give or take half an element.
    for [x, y, z] in stl_vertices(&stl) {
        assert!((-4.0..=54.0).contains(&x) && (-4.0..=44.0).contains(&y) && z >= -1e-6, "vertex at ({x}, {y}, {z})");
    }
}

#[test]
fn woven_threads_end_flat_at_the_edge_of_the_plane() {
    let dir = tempdir("quilt-weave-edge");
    let stl = dir.join("w.stl");
    let json =
        report_of("quilt", &["--swatch", "weave", "--base", "plane:30x24", "--stl", &path(&stl)], &dir.join("w.json"));
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    assert_eq!(check.shells.to_string(), field(&json, "elements"), "{json}");
    assert!(field(&json, "cut_at_edge").parse::<usize>().unwrap() > 0, "{json}");
    // Threads are cut at the area's sides: nothing overhangs them, and
    // the cut ends reach them.
    let vertices = stl_vertices(&stl);
    for &[x, y, _] in &vertices {
        assert!((-1e-4..=30.0001).contains(&x) && (-1e-4..=24.0001).contains(&y), "vertex at ({x}, {y})");
    }
    for (reach, side) in [
        (vertices.iter().map(|v| v[0]).fold(f64::MAX, f64::min), 0.0),
        (vertices.iter().map(|v| v[0]).fold(f64::MIN, f64::max), 30.0),
        (vertices.iter().map(|v| v[1]).fold(f64::MAX, f64::min), 0.0),
        (vertices.iter().map(|v| v[1]).fold(f64::MIN, f64::max), 24.0),
    ] {
        assert!((reach - side).abs() < 1e-3, "the weave reaches {reach} on the side at {side}");
    }
}

#[test]
fn rivets_united_with_a_model_are_one_body_standing_on_the_bed() {
    let dir = tempdir("quilt-united");
    // The vase at the default scale once failed to unite: a stitched rivet
    // cut at the foot came out pinched, and the union refused it.
    for (base, scale) in [("cone", "1.5"), ("vase", "1")] {
        let stl = dir.join(format!("{base}.stl"));
        let json = report_of(
            "quilt",
            &["--swatch", "rivets", "--base", base, "--scale", scale, "--with-base", "--stl", &path(&stl)],
            &dir.join(format!("{base}.json")),
        );
        let check = check_stl(&stl);
        assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{base}: {check:?}");
        assert_eq!(check.shells, 1, "the {base} and its rivets print as one body: {json}");
        // Rivets round the foot were cut flat: nothing hangs below the bed.
        assert!(field(&json, "cut_at_floor").parse::<usize>().unwrap() > 0, "{json}");
        let lowest = stl_vertices(&stl).iter().map(|v| v[2]).fold(f64::MAX, f64::min);
        assert!(lowest > -1e-4, "{base}: a vertex {lowest} mm below the bed");
        let elements: usize = field(&json, "elements").parse().unwrap();
        assert!(elements > 20, "{json}");
    }
}

#[test]
fn bad_input_fails_with_one_line_and_no_file() {
    let dir = tempdir("quilt-bad");
    let open = dir.join("open.obj");
    std::fs::write(&open, "v 0 0 0\nv 4 0 0\nv 0 4 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n").unwrap();
    let stl = dir.join("out.stl");
    let bad_field = dir.join("field.txt");
    std::fs::write(&bad_field, "# one stroke, one point short\n30,0,5; 30,0\n").unwrap();
    // A model a millimetre across: no element fits on it.
    let speck = dir.join("speck.obj");
    std::fs::write(&speck, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let cases: [(&[&str], &str); 14] = [
        (&["--swatch", "lace", "--base", "plane:40x40"], "no mesh file or built-in swatch"),
        (&["--swatch", "weave", "--base", "plane:40"], "not a base"),
        (&["--swatch", "weave", "--base", "plane:40x40", "--scale", "0"], "scale"),
        (&["--swatch", &path(&open), "--base", "plane:40x40"], "not a closed surface"),
        (&["--swatch", "weave", "--base", "teapot"], "no mesh file or built-in base"),
        (&["--swatch", "weave", "--base", "plane:100000x100000"], "at most"),
        (&["--swatch", "weave", "--base", "plane:40x40", "--with-base"], "no model to unite"),
        (&["--swatch", "weave", "--base", "vase", "--sink-mm", "5"], "sink"),
        (&["--swatch", "weave", "--base", "plane:40x40", "--field", &path(&bad_field)], "for models"),
        (&["--swatch", "weave", "--base", "vase", "--field", &path(&dir.join("none.txt"))], "could not read"),
        (&["--swatch", "weave", "--base", "vase", "--field", &path(&bad_field)], "line 2"),
        (&["--swatch", "weave", "--base", "vase", "--direction", "curves"], "give a field file"),
        (&["--swatch", "weave", "--base", "vase", "--direction", "up", "--field", &path(&bad_field)], "leave out"),
        (&["--swatch", "rivets", "--base", &path(&speck)], "no element of the swatch stays on the model"),
    ];
    for (args, expected) in cases {
        let out = tracery().arg("quilt").args(args).arg("--stl").arg(&stl).output().unwrap();
        assert!(!out.status.success(), "{args:?} succeeded");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(expected), "{args:?}: {err}");
        assert!(!stl.exists(), "{args:?} left a file");
    }
}
