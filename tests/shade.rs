//! `tracery shade` end to end: lamp shades on a cylinder and a cone. The STL
//! is checked apart from the mesh code (closed, consistently oriented, one
//! shell, so the seam all around is welded), every vertex must lie on the
//! shade's surface or its thickness, and bad shapes fail with one line.

#[path = "common/cli.rs"]
mod cli;
#[path = "common/stl.rs"]
mod stl;
#[path = "common/threemf.rs"]
mod threemf;
use cli::{field, report_of, tempdir, tracery};
use stl::{check_stl, stl_vertices};

#[test]
fn a_cylinder_shade_is_one_closed_body_on_the_surface() {
    let dir = tempdir("shade-cylinder");
    let (stl, three_mf, svg) = (dir.join("s.stl"), dir.join("s.3mf"), dir.join("s.svg"));
    let path = |p: &std::path::Path| p.display().to_string();
    let (radius, height, thickness) = (30.0, 40.0, 1.5);
    let json = report_of(
        "shade",
        &[
            "--exemplar",
            "chain",
            "--cylinder",
            "30,40",
            "--thickness",
            "1.5",
            "--stl",
            &path(&stl),
            "--3mf",
            &path(&three_mf),
            "--svg",
            &path(&svg),
        ],
        &dir.join("s.json"),
    );
    assert_eq!(field(&json, "components"), "1", "{json}");
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges, check.shells), (0, 0, 1), "{check:?}");
    // On the surface, outward by the thickness, between the rims' edges.
    let slack = 1e-3;
    let (mut lowest, mut highest) = (f64::MAX, f64::MIN);
    for [x, y, z] in stl_vertices(&stl) {
        let r = x.hypot(y);
        assert!(r > radius - slack && r < radius + thickness + slack, "vertex at radius {r}");
        (lowest, highest) = (lowest.min(z), highest.max(z));
    }
    assert!(lowest.abs() < slack && (highest - height).abs() < slack, "z from {lowest} to {highest}");
    let read = threemf::read_3mf(&std::fs::read(&three_mf).unwrap());
    assert!(read.objects.len() == 1 && threemf::is_closed(&read.objects[0].2));
    assert_eq!(read.objects[0].2.len(), check.triangles, "the same solid as the STL");
    if let Some((manifold, objects)) = threemf::prusa_info(&three_mf) {
        assert!(manifold && objects == 1);
    }
    // The development is the surface unrolled: as wide as the girth, within
    // the page's margin of a millimetre on each side.
    let text = std::fs::read_to_string(&svg).unwrap();
    let width: f64 = text.split("width=\"").nth(1).unwrap().split("mm").next().unwrap().parse().unwrap();
    let girth = std::f64::consts::TAU * radius;
    assert!((width - 2.0 - girth).abs() < 0.01, "development {width} mm wide, girth {girth} mm");
}

#[test]
fn a_cone_shade_with_rows_that_must_be_laid_closer_is_one_body() {
    // The vine's rows touch only here and there: laid 1 mm apart they fall
    // into pieces, so the shade lays them closer until they hold.
    let dir = tempdir("shade-cone");
    let stl = dir.join("c.stl");
    let json = report_of(
        "shade",
        &["--exemplar", "vine", "--cone", "45,30,40", "--stl", &stl.display().to_string()],
        &dir.join("c.json"),
    );
    assert_eq!(field(&json, "components"), "1", "{json}");
    assert!(field(&json, "row_overlap_mm").parse::<f64>().unwrap() > 1.0, "{json}");
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges, check.shells), (0, 0, 1), "{check:?}");
    // Every vertex lies on the cone, or outward of it by at most the thickness.
    let slant = 40f64.hypot(15.0);
    for [x, y, z] in stl_vertices(&stl) {
        let on_cone = 45.0 - 15.0 * z / 40.0;
        let outward = (x.hypot(y) - on_cone) * 40.0 / slant;
        assert!((-1e-3..2.0 + 1e-3).contains(&outward), "vertex {outward} mm off the cone");
    }
}

#[test]
fn bad_shades_fail_with_one_line_and_no_file() {
    let dir = tempdir("shade-bad");
    let stl = dir.join("bad.stl");
    for (args, says) in [
        (vec!["--cylinder", "40"], "--cylinder must be R,H"),
        (vec!["--cone", "40,-2,60"], "top radius must be a positive number"),
        (vec!["--cylinder", "40,5"], "leave no room"),
        (vec![], "give the shade's shape"),
        (vec!["--cylinder", "40,60", "--along", "line:10"], "not --along"),
        (vec!["--cylinder", "40,60", "--band", "1", "--row-overlap", "2"], "cannot overlap"),
        (vec!["--cylinder", "5000,60"], "over the 1000 mm"),
    ] {
        let out = tracery().args(["shade", "--exemplar", "lace", "--stl"]).arg(&stl).args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} succeeded");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
        assert!(!stl.exists(), "{args:?} left a file");
    }
}
