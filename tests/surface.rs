//! `tracery surface` end to end: patterns along curves picked on built-in
//! bases and on a mesh file. The STL is checked apart from the mesh code
//! (closed, consistently oriented, its shells and handles counted against
//! the planned topology), every vertex must sit on the base's surface or
//! within the thickness above it (distances from parry's closest point,
//! not from the code that laid the band), and bad input fails with one line.

#[path = "common/cli.rs"]
mod cli;
#[path = "common/stl.rs"]
mod stl;
use cli::{field, report_of, tempdir, tracery};
use stl::{check_stl, stl_vertices};
use tracery_core::surface::{SurfaceMesh, builtin_base};

/// Checks the shell at `stl` against the report and the base it lies on.
fn check_shell(stl: &std::path::Path, json: &str, base: &str, thickness_mm: f64) {
    let check = check_stl(stl);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    let components: i64 = field(json, "components").parse().unwrap();
    let holes: i64 = field(json, "holes").parse().unwrap();
    let openings: i64 = field(json, "loop_openings").parse().unwrap();
    assert_eq!(check.shells as i64, components, "{check:?} {json}");
    // Each hole of the pattern, and the ring a closed curve makes, is a handle.
    assert_eq!(check.euler, 2 * components - 2 * (holes + openings), "{check:?} {json}");
    let surface = SurfaceMesh::new(builtin_base(base).unwrap()).unwrap();
    // f32 rounding in the file, and the band bent between mesh edges.
    let slack = 0.02;
    for v in stl_vertices(stl) {
        let on = surface.closest_point(v).position_mm;
        let off = ((on.x - v[0]).powi(2) + (on.y - v[1]).powi(2) + (on.z - v[2]).powi(2)).sqrt();
        assert!(off <= thickness_mm + slack, "vertex {v:?} is {off} mm from the {base}");
    }
}

#[test]
fn a_ring_around_the_vase_is_one_closed_shell_on_it() {
    let dir = tempdir("surface-vase");
    let (stl, three_mf) = (dir.join("v.stl"), dir.join("v.3mf"));
    let path = |p: &std::path::Path| p.display().to_string();
    let json = report_of(
        "surface",
        &[
            "--exemplar",
            "chain",
            "--mesh",
            "vase",
            "--points",
            "30,0,25;0,30,25;-30,0,25;0,-30,25",
            "--closed",
            "--band",
            "8",
            "--thickness",
            "1.5",
            "--stl",
            &path(&stl),
            "--3mf",
            &path(&three_mf),
        ],
        &dir.join("v.json"),
    );
    assert_eq!(field(&json, "components"), "1", "{json}");
    assert_eq!(field(&json, "loop_openings"), "1", "{json}");
    check_shell(&stl, &json, "vase", 1.5);
    // A ring at 25 mm: the curve stayed near that height all around.
    let zs: Vec<f64> = stl_vertices(&stl).iter().map(|v| v[2]).collect();
    let (low, high) = zs.iter().fold((f64::MAX, f64::MIN), |(l, h), &z| (l.min(z), h.max(z)));
    assert!(low > 15.0 && high < 35.0, "the band spans z {low}..{high}");
    assert!(three_mf.exists());
}

#[test]
fn an_open_curve_keeps_its_targets_on_the_cone() {
    let dir = tempdir("surface-open");
    let stl = dir.join("cone.stl");
    let json = report_of(
        "surface",
        &[
            "--exemplar",
            "chain",
            "--mesh",
            "cone",
            "--points",
            "25,0,15;0,-22,25;-20,0,35",
            "--band",
            "8",
            "--holes",
            "8",
            "--stl",
            &stl.display().to_string(),
        ],
        &dir.join("cone.json"),
    );
    assert_eq!(field(&json, "components"), "1", "{json}");
    assert_eq!(field(&json, "holes"), "8", "{json}");
    check_shell(&stl, &json, "cone", 2.0);
}

#[test]
fn a_mesh_file_is_read_and_points_off_it_are_snapped_and_reported() {
    let dir = tempdir("surface-file");
    let base = dir.join("cylinder.stl");
    let mut bytes = Vec::new();
    tracery_core::export::write_stl(&builtin_base("cylinder").unwrap(), &mut bytes).unwrap();
    std::fs::write(&base, bytes).unwrap();
    let stl = dir.join("out.stl");
    let json = report_of(
        "surface",
        &[
            "--exemplar",
            "chain",
            "--mesh",
            &base.display().to_string(),
            "--points",
            "28,0,20;0,-28,30",
            "--band",
            "6",
            "--stl",
            &stl.display().to_string(),
        ],
        &dir.join("out.json"),
    );
    assert!(json.contains("points off the surface were moved onto it (at most 3.00 mm"), "{json}");
    assert!(json.contains(r#""points_moved_mm": "3.000,3.000""#), "{json}");
    check_shell(&stl, &json, "cylinder", 2.0);
}

#[test]
fn an_embossed_ring_and_the_vase_are_one_watertight_body() {
    let dir = tempdir("surface-emboss");
    let stl = dir.join("e.stl");
    let args = ["--exemplar", "chain", "--mesh", "vase", "--points", "30,0,25;0,30,25;-30,0,25;0,-30,25", "--closed"];
    let path = stl.display().to_string();
    let json = report_of(
        "surface",
        &[&args[..], &["--band", "8", "--mode", "emboss", "--stl", &path]].concat(),
        &dir.join("e.json"),
    );
    let check = check_stl(&stl);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    assert_eq!(check.shells, 1, "{check:?}");
    // The band is welded to the vase along all of its underside: its holes
    // are pockets and its ring goes round nothing, so the body is a ball.
    assert_eq!(check.euler, 2, "{check:?} {json}");
    assert!(field(&json, "holes").parse::<usize>().unwrap() > 0, "{json}");
    // Every vertex is on the vase, or on the band within its thickness above it.
    let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap();
    let volume = |m: &tracery_core::mesh::Mesh| m.signed_volume();
    let points = stl_vertices(&stl);
    let mut above = 0;
    for v in &points {
        let on = vase.closest_point(*v).position_mm;
        let off = ((on.x - v[0]).powi(2) + (on.y - v[1]).powi(2) + (on.z - v[2]).powi(2)).sqrt();
        assert!(off <= 2.0 + 0.02, "vertex {v:?} is {off} mm from the vase");
        above += usize::from(off > 1.0);
    }
    assert!(above > 1000, "only {above} vertices stand out of the vase");
    // The same band as a pattern alone: the embossed body holds the vase and
    // most of the band (all but what sank into the vase).
    let alone = dir.join("p.stl");
    let alone_path = alone.display().to_string();
    report_of("surface", &[&args[..], &["--band", "8", "--stl", &alone_path]].concat(), &dir.join("p.json"));
    let read = |p: &std::path::Path| tracery_core::mesh::read_stl(&std::fs::read(p).unwrap(), "test").unwrap();
    let (body, band) = (volume(&read(&stl)), volume(&read(&alone)));
    let base = volume(vase.mesh());
    assert!(body > base + 0.8 * band && body < base + band, "body {body:.0} mm³, vase {base:.0}, band {band:.0}");
}

#[test]
fn two_embossed_rings_are_one_body_holding_the_vase_once() {
    let dir = tempdir("surface-two");
    let ring = |z: f64| format!("30,0,{z};0,30,{z};-30,0,{z};0,-30,{z}");
    let (low, high) = (ring(18.0), ring(32.0));
    let common = ["--exemplar", "chain", "--mesh", "vase", "--closed", "--band", "7", "--mode", "emboss"];
    let read = |p: &std::path::Path| tracery_core::mesh::read_stl(&std::fs::read(p).unwrap(), "test").unwrap();
    let made = |name: &str, curves: &[&str]| {
        let stl = dir.join(format!("{name}.stl"));
        let mut args: Vec<String> = common.iter().map(|s| s.to_string()).collect();
        for points in curves {
            args.extend(["--points".to_string(), points.to_string()]);
        }
        args.extend(["--stl".to_string(), stl.display().to_string()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let json = report_of("surface", &args, &dir.join(format!("{name}.json")));
        (stl, json)
    };
    let (both, json) = made("both", &[&low, &high]);
    let check = check_stl(&both);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    assert_eq!(check.shells, 1, "{check:?} {json}");
    assert_eq!(check.euler, 2, "{check:?} {json}");
    assert_eq!(field(&json, "parts"), "2", "{json}");
    // The vase once, and each ring's relief on it: the volume of both rings
    // embossed is that of each embossed alone, less the vase counted twice.
    let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap().mesh().signed_volume();
    let alone: Vec<f64> = [("low", &low), ("high", &high)]
        .iter()
        .map(|(name, points)| read(&made(name, &[points.as_str()]).0).signed_volume() - vase)
        .collect();
    assert!(alone.iter().all(|&relief| relief > 100.0), "{alone:?}");
    let relief = read(&both).signed_volume() - vase;
    // The second ring gets the next seed, so its chain differs a little from the one made alone.
    let expected = alone[0] + alone[1];
    assert!((relief - expected).abs() < 0.1 * expected, "both: {relief:.0} mm³ of relief, alone: {alone:?}");
}

#[test]
fn a_pattern_without_holes_carved_out_of_the_egg_leaves_one_open_shell() {
    let dir = tempdir("surface-carve");
    let args = ["--exemplar", "vine", "--mesh", "egg", "--points", "21,0,20;15,-15,30;0,-19,40", "--band", "8"];
    let (carved, alone) = (dir.join("c.stl"), dir.join("p.stl"));
    let path = |p: &std::path::Path| p.display().to_string();
    let json = report_of(
        "surface",
        &[&args[..], &["--holes", "0", "--mode", "carve", "--wall", "2", "--stl", &path(&carved)]].concat(),
        &dir.join("c.json"),
    );
    report_of("surface", &[&args[..], &["--holes", "0", "--stl", &path(&alone)]].concat(), &dir.join("p.json"));
    let check = check_stl(&carved);
    assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{check:?}");
    // The egg's outside and inside, joined through the opening the vine
    // leaves: one shell, a ball with no handle.
    assert_eq!(check.shells, 1, "{check:?} {json}");
    assert_eq!(check.euler, 2, "{check:?} {json}");
    assert!(!json.contains("separate pieces"), "{json}");
    // Every vertex lies in the wall: on the egg or at most 2 mm inside it.
    let egg = SurfaceMesh::new(builtin_base("egg").unwrap()).unwrap();
    for v in stl_vertices(&carved) {
        let on = egg.closest_point(v).position_mm;
        let off = ((on.x - v[0]).powi(2) + (on.y - v[1]).powi(2) + (on.z - v[2]).powi(2)).sqrt();
        assert!(off <= 2.0 + 0.02, "vertex {v:?} is {off} mm from the egg");
    }
    // What was cut away is about the vine's own volume (as thick as the wall).
    let read = |p: &std::path::Path| tracery_core::mesh::read_stl(&std::fs::read(p).unwrap(), "test").unwrap();
    let full = tracery_core::surface::hollow(&egg, 2.0).unwrap().signed_volume();
    let (cut, vine) = (full - read(&carved).signed_volume(), read(&alone).signed_volume());
    assert!((cut - vine).abs() < 0.25 * vine, "cut away {cut:.0} mm³, the vine is {vine:.0} mm³");
}

#[test]
fn bad_surfaces_fail_with_one_line_and_no_file() {
    let dir = tempdir("surface-bad");
    let stl = dir.join("bad.stl");
    // Two tetrahedra sharing one edge: three triangles on it... four.
    let crowded = dir.join("crowded.obj");
    std::fs::write(
        &crowded,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nv 0 0 -1\nf 1 3 2\nf 1 2 4\nf 1 2 5\nf 1 2 6\n",
    )
    .unwrap();
    let text = dir.join("not.stl");
    std::fs::write(&text, "hello").unwrap();
    let crowded = crowded.display().to_string();
    let text = text.display().to_string();
    for (args, says) in [
        (vec!["--mesh", "teapot", "--points", "0,0,0;1,1,1"], "no mesh file or built-in base named 'teapot'"),
        (vec!["--mesh", "egg", "--points", "0,0,0"], "at least 2 points"),
        (
            vec!["--mesh", "egg", "--points", "0,0,0;1,1,1;2,2,2", "--closed", "--twist", "200"],
            "--twist: the twist must be at most 90 degrees, not 200",
        ),
        (vec!["--mesh", "egg", "--points", "1,2;3,4,5"], "point 1 (1,2) is not three numbers"),
        (vec!["--mesh", &crowded, "--points", "0,0,0;1,0,0"], "shared by more than two triangles"),
        (vec!["--mesh", &text, "--points", "0,0,0;1,0,0"], "is not a valid STL file"),
        (vec!["--mesh", "egg", "--points", "0,0,0;1,1,1", "--along", "line:10"], "not --along"),
        (vec!["--mesh", "vase", "--points", "30,0,25;0,30,25", "--mode", "carve", "--wall", "6"], "for a 6 mm wall"),
        (
            vec!["--mesh", "egg", "--points", "21,0,20;0,-19,40", "--mode", "carve", "--wall", "0"],
            "--wall: the wall must be above 0 mm, not 0",
        ),
    ] {
        let out = tracery().args(["surface", "--exemplar", "lace", "--stl"]).arg(&stl).args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} succeeded");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
        assert!(!stl.exists(), "{args:?} left a file");
    }
}
