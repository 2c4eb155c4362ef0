//! `tracery raster` end to end: built-in and imported PNG exemplars along a
//! wave and a closed heart. The PNG must decode at the asked resolution, the
//! STL must be closed with one shell per component counted in the report,
//! and bad input must fail with one line and leave no file.

#[path = "common/cli.rs"]
mod cli;
#[path = "common/stl.rs"]
mod stl;
#[path = "common/threemf.rs"]
mod threemf;
use cli::{field, tempdir, tracery};
use stl::check_stl;

#[test]
fn a_raster_rope_prints_and_renders() {
    let dir = tempdir("raster");
    for (name, along, closed) in [("rope", "wave:120", false), ("chain", "heart:70", true), ("lace", "wave:100", false)]
    {
        let (png, stl, report) = (dir.join("out.png"), dir.join("out.stl"), dir.join("out.json"));
        let three_mf = dir.join("out.3mf");
        let mut cmd = tracery();
        cmd.args(["raster", "--exemplar", name, "--along", along, "--dpi", "150"]);
        cmd.arg("--png").arg(&png).arg("--stl").arg(&stl).arg("--report").arg(&report).arg("--3mf").arg(&three_mf);
        if closed {
            cmd.arg("--closed");
        }
        let out = cmd.output().unwrap();
        assert!(out.status.success(), "{name}: {}", String::from_utf8_lossy(&out.stderr));
        let json = std::fs::read_to_string(&report).unwrap();
        let components: usize = field(&json, "components").parse().unwrap();
        let shells: usize = field(&json, "stl_shells").parse().unwrap();
        let pieces: usize = field(&json, "pieces").parse().unwrap();
        assert!(pieces >= 30, "{name}: {pieces} pieces");
        assert!(field(&json, "per_piece").parse::<f64>().unwrap() > 0.0);
        let valid: f64 = field(&json, "valid_fraction").parse().unwrap();
        assert!(valid > 0.0 && valid < 1.0, "{name}: valid fraction {valid}");
        let check = check_stl(&stl);
        assert_eq!(check.triangles, field(&json, "stl_triangles").parse::<usize>().unwrap());
        assert_eq!((check.open_edges, check.misoriented_edges), (0, 0), "{name}: STL not closed");
        assert_eq!(check.shells, components, "{name}: one body per counted component");
        assert_eq!(shells, components);
        // The slicer, apart from our code, reads the printed file as sound.
        let read = threemf::read_3mf(&std::fs::read(&three_mf).unwrap());
        assert_eq!((read.unit.as_str(), read.objects.len()), ("millimeter", 1), "{name}");
        assert!(read.declared_before_use && read.build_items == 1, "{name}");
        assert!(
            read.objects.iter().all(|(_, _, triangles)| threemf::is_closed(triangles)),
            "{name}: 3MF object not closed"
        );
        if let Some((manifold, objects)) = threemf::prusa_info(&three_mf) {
            assert!(manifold && objects == 1, "{name}: PrusaSlicer says manifold {manifold}, {objects} object(s)");
        }
        // 150 dpi: the picture spans the pattern's bounds at about 5.9 px per mm.
        let picture = image::load_from_memory(&std::fs::read(&png).unwrap()).unwrap().into_rgba8();
        let opaque = picture.pixels().filter(|p| p[3] >= 128).count();
        assert!(
            picture.width() > 300 && opaque > 2000,
            "{name}: {}x{} with {opaque} opaque",
            picture.width(),
            picture.height()
        );
    }
}

#[test]
fn an_imported_png_works_and_bad_ones_fail_cleanly() {
    let dir = tempdir("raster-import");
    // A striped bar with a transparent background, as a person might export it.
    let (w, h) = (80u32, 30u32);
    let bar = image::RgbaImage::from_fn(w, h, |x, y| {
        let on = (8..22).contains(&y);
        image::Rgba([if x % 10 < 5 { 200 } else { 90 }, 60, 40, if on { 255 } else { 0 }])
    });
    let good = dir.join("bar.png");
    bar.save(&good).unwrap();
    let (png, report) = (dir.join("out.png"), dir.join("out.json"));
    let out = tracery()
        .args(["raster", "--exemplar"])
        .arg(&good)
        .args(["--along", "circle:20", "--png"])
        .arg(&png)
        .arg("--report")
        .arg(&report)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let json = std::fs::read_to_string(&report).unwrap();
    assert_eq!(field(&json, "components"), "1");
    assert_eq!(field(&json, "loop_openings"), "1");

    let opaque = dir.join("opaque.png");
    image::RgbaImage::from_pixel(40, 20, image::Rgba([1, 2, 3, 255])).save(&opaque).unwrap();
    let rgb = dir.join("rgb.png");
    image::RgbImage::from_pixel(40, 20, image::Rgb([1, 2, 3])).save(&rgb).unwrap();
    let text = dir.join("notes.png");
    std::fs::write(&text, "not a picture").unwrap();
    for (exemplar, along, says) in [
        (&opaque, "wave:100", "fully opaque"),
        (&rgb, "wave:100", "no transparency"),
        (&text, "wave:100", "not a PNG"),
        (&good, "line:1", "shorter than one piece"),
        (&good, "rect:40x20", "runs along curves"),
    ] {
        let (png, stl) = (dir.join("bad.png"), dir.join("bad.stl"));
        let out = tracery()
            .args(["raster", "--exemplar"])
            .arg(exemplar)
            .args(["--along", along, "--png"])
            .arg(&png)
            .arg("--stl")
            .arg(&stl)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{says}: succeeded");
        assert!(err.contains(says) && err.trim().lines().count() == 1, "{says}: {err}");
        assert!(!png.exists() && !stl.exists(), "{says}: partial output left");
    }
}
