//! Bad input and broken writes, as a person (or an attacker) meets them:
//! every failure is one line naming what to change, exits 1 (2 for usage),
//! panics never, and leaves no file behind; a run killed or cancelled at
//! any moment leaves the old file or the whole new one.

#[path = "common/cli.rs"]
mod cli;
use cli::{tempdir, tracery};

use std::path::Path;
use std::process::{Output, Stdio};
use std::time::{Duration, Instant};

/// Each failure: the arguments, the exit code, and words the one line must hold.
const REFUSALS: &[(&[&str], i32, &[&str])] = &[
    // Coordinates far off the table once panicked in the outline library.
    (&["synth", "--exemplar", "lace", "--along", "circle:20", "--jump-ring", "1e308,0"], 1, &["jump ring", "10000 mm"]),
    (&["synth", "--exemplar", "lace", "--along", "circle:20", "--jump-ring", "1e6,1e6"], 1, &["jump ring", "10000 mm"]),
    // A ring far from the pattern once made a kilometre-long stem.
    (&["synth", "--exemplar", "lace", "--along", "circle:20", "--jump-ring", "100,0"], 1, &["jump ring", "25 mm"]),
    (
        &["surface", "--exemplar", "chain", "--mesh", "vase", "--band", "6", "--points", "1e308,0,25;0,30,25"],
        1,
        &["--points", "point 1", "10000 mm"],
    ),
    // Sizes that were allocated before any cap was checked.
    (&["raster", "--exemplar", "rope", "--along", "circle:20", "--step", "1e-9"], 1, &["--step", "at least 0.1"]),
    (&["raster", "--exemplar", "rope", "--along", "circle:1e9"], 1, &["circle radius", "10000"]),
    (&["synth", "--exemplar", "lace", "--along", "line:1e12"], 1, &["line length", "10000"]),
    // Absurd values once accepted.
    (
        &["synth", "--exemplar", "lace", "--along", "circle:20", "--thickness", "1e12"],
        1,
        &["--thickness", "1e12", "500"],
    ),
    (
        &["synth", "--exemplar", "lace", "--along", "circle:20", "--corner-radius", "1e12"],
        1,
        &["--corner-radius", "1e12"],
    ),
    (&["synth", "--exemplar", "lace", "--along", "circle:20", "--band", "1e-300"], 1, &["--band", "at least 0.5"]),
    (&["synth", "--exemplar", "lace", "--along", "circle:20", "--scale", "1e-300"], 1, &["--scale", "at least"]),
    (&["synth", "--exemplar", "lace", "--along", "circle:20", "--min-portal", "1e10"], 1, &["--min-portal"]),
    (
        &["fill", "--exemplar", "vine", "--region", "rect:50x50", "--stroke-width", "1e12"],
        1,
        &["--stroke-width", "100"],
    ),
    (&["fill", "--exemplar", "vine", "--region", "rect:50x50", "--frame", "1e12"], 1, &["--frame", "100"]),
    (&["quilt", "--swatch", "weave", "--base", "plane:40x40", "--scale", "1e12"], 1, &["--scale", "100"]),
    (
        &[
            "surface",
            "--exemplar",
            "chain",
            "--mesh",
            "vase",
            "--points",
            "0,30,20;30,0,20",
            "--wall",
            "1e9",
            "--mode",
            "carve",
        ],
        1,
        &["--wall", "50 mm"],
    ),
    (&["raster", "--exemplar", "rope", "--along", "circle:20", "--thickness", "1e12"], 1, &["--thickness"]),
    (
        &["synth", "--exemplar", "lace", "--along", "circle:20", "--slicing", "uniform:99999999999999"],
        1,
        &["--slicing", "1 to 256"],
    ),
    // Found by fuzzing: a region kilometres across was cut into a polygon of
    // ten million sides before any check.
    (&["fill", "--exemplar", "vine", "--region", "circle:1e12"], 1, &["is not a region", "10000"]),
    // A negative number is a value, not a flag.
    (&["shade", "--exemplar", "lace", "--cylinder", "-1,60"], 1, &["radius", "-1"]),
    // Usage errors exit 2.
    (&["synth", "--exemplar", "lace", "--along", "circle:20", "--band", "wide"], 2, &["--band", "wide"]),
];

/// One line on stderr, no panic, no wrapped integer, no part said twice.
fn check_one_line(args: &[&str], out: &Output) -> String {
    let err = String::from_utf8_lossy(&out.stderr).trim().to_string();
    assert_eq!(err.lines().count(), 1, "{args:?}: not one line:\n{err}");
    assert!(!err.contains("panicked") && !err.contains("RUST_BACKTRACE"), "{args:?}: {err}");
    assert!(!err.contains("18446744073709551615"), "{args:?}: a wrapped integer: {err}");
    assert!(!err.contains("cargo feature"), "{args:?}: a developer's message: {err}");
    let parts: Vec<&str> = err.split([':', '(', ')']).map(str::trim).filter(|p| p.len() > 12).collect();
    for (k, part) in parts.iter().enumerate() {
        assert!(!parts[..k].contains(part), "{args:?}: '{part}' said twice: {err}");
    }
    err
}

#[test]
fn every_refusal_is_one_line_naming_what_to_change_and_leaves_no_file() {
    for (args, code, words) in REFUSALS {
        let dir = tempdir("refusal");
        let out = tracery()
            .args(*args)
            .arg("--stl")
            .arg(dir.join("o.stl"))
            .arg("--report")
            .arg(dir.join("o.json"))
            .env_remove("RUST_BACKTRACE")
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(*code), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        let err = check_one_line(args, &out);
        for word in *words {
            assert!(err.contains(word), "{args:?}: '{word}' missing from: {err}");
        }
        let left: Vec<_> = std::fs::read_dir(&*dir).unwrap().collect();
        assert!(left.is_empty(), "{args:?} left {left:?}");
    }
}

#[test]
fn hostile_files_are_refused_in_words_a_person_reads() {
    let dir = tempdir("hostile");
    let svgz = dir.join("x.svgz");
    // A gzip header: usvg's own message asks for a cargo feature.
    std::fs::write(&svgz, [0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 3, 1, 0, 0, 0xff, 0xff, 0, 0, 0, 0, 0, 0, 0, 0]).unwrap();
    let svgz = svgz.to_str().unwrap();
    let along = format!("svg:{svgz}");
    for args in [
        vec!["synth", "--exemplar", svgz, "--along", "circle:20"],
        vec!["synth", "--exemplar", "lace", "--along", &along],
        vec!["fill", "--exemplar", svgz, "--region", "rect:40x40"],
    ] {
        let out = tracery().args(&args).arg("--svg").arg(dir.join("o.svg")).output().unwrap();
        assert_eq!(out.status.code(), Some(1));
        let err = check_one_line(&args, &out);
        assert!(err.contains("compressed SVG") && err.contains("plain SVG"), "{args:?}: {err}");
    }
    assert!(!dir.join("o.svg").exists());

    // Found by fuzzing: a drawing kilometres across, flattened at a fixed
    // tolerance, made billions of points.
    let huge = dir.join("huge.svg");
    std::fs::write(&huge, r#"<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><circle r="1e9"/></svg>"#)
        .unwrap();
    let region = format!("svg:{}", huge.display());
    let args = ["fill", "--exemplar", "vine", "--region", &region];
    let out = tracery().args(args).arg("--svg").arg(dir.join("o.svg")).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = check_one_line(&args, &out);
    assert!(err.contains("is not a region") || err.contains("units"), "{err}");

    // Found by fuzzing: an arc of radius 1e123 in a path made usvg, turning
    // arcs into curves, ask for 7.5 GB, and the process was killed.
    let arc = dir.join("arc.svg");
    std::fs::write(
        &arc,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 160 40"><path d="M148.5,20 A3.5,1e123.5 0 1 1 155.5,20 Z"/></svg>"#,
    )
    .unwrap();
    let arc = arc.to_str().unwrap();
    let (along, region) = (format!("svg:{arc}"), format!("svg:{arc}"));
    for args in [
        vec!["synth", "--exemplar", arc, "--along", "circle:20"],
        vec!["synth", "--exemplar", "lace", "--along", &along],
        vec!["fill", "--exemplar", "vine", "--region", &region],
        vec!["fill", "--exemplar", arc, "--region", "rect:40x40"],
    ] {
        let out = tracery().args(&args).arg("--svg").arg(dir.join("o.svg")).output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = check_one_line(&args, &out);
        assert!(err.contains("too large to draw (1e123"), "{args:?}: {err}");
    }
}

/// CRC-32 (PNG's) of `bytes`.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 { (crc >> 1) ^ 0xEDB8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

/// A PNG's signature and header for a `width` × `height` RGBA picture, and
/// its end: a valid picture's start, whose pixels the decoder never reaches.
fn png_header(width: u32, height: u32) -> Vec<u8> {
    let chunk = |kind: &[u8], data: &[u8]| {
        let mut c = (data.len() as u32).to_be_bytes().to_vec();
        let body = [kind, data].concat();
        c.extend_from_slice(&body);
        c.extend_from_slice(&crc32(&body).to_be_bytes());
        c
    };
    let ihdr = [width.to_be_bytes().as_slice(), &height.to_be_bytes(), &[8, 6, 0, 0, 0]].concat();
    // A zlib stream of nothing: the header is read up to the first IDAT.
    let idat = chunk(b"IDAT", &[0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01]);
    [b"\x89PNG\r\n\x1a\n".as_slice(), &chunk(b"IHDR", &ihdr), &idat, &chunk(b"IEND", &[])].concat()
}

#[test]
fn a_large_picture_is_told_too_large_not_damaged() {
    let dir = tempdir("large-png");
    // 12000 × 12000 RGBA is 576 MB decoded, past the decoder's memory
    // limit: it was refused as "not a PNG picture (Memory limit exceeded)".
    let png = dir.join("large.png");
    std::fs::write(&png, png_header(12_000, 12_000)).unwrap();
    let args = ["raster", "--exemplar", png.to_str().unwrap(), "--along", "circle:20"];
    let out = tracery().args(args).arg("--stl").arg(dir.join("o.stl")).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = check_one_line(&args, &out);
    assert!(err.contains("12000 x 12000 pixels") && err.contains("scale it down"), "{err}");
}

#[test]
fn outputs_are_checked_before_the_work_and_written_all_or_none() {
    let dir = tempdir("outputs");
    let stl = dir.join("o.stl");
    // The exemplar does not exist either: the output's folder is named
    // first, because outputs are checked before anything is read or made.
    let out = tracery()
        .args(["synth", "--exemplar", "no-such.svg", "--along", "circle:20", "--stl"])
        .arg(&stl)
        .args(["--svg", "/nonexistent-folder/o.svg"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = check_one_line(&[], &out);
    assert!(err.contains("--svg") && err.contains("/nonexistent-folder"), "{err}");
    assert!(!stl.exists(), "one output written while another failed");

    // One file for two outputs would write one over the other.
    let same = dir.join("same.out");
    let same_again = dir.join(".").join("same.out");
    let out = tracery()
        .args(["synth", "--exemplar", "lace", "--along", "circle:20", "--stl"])
        .arg(&same)
        .arg("--3mf")
        .arg(&same_again)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = check_one_line(&[], &out);
    assert!(err.contains("--stl and --3mf"), "{err}");
    assert!(!same.exists());

    // A folder given as a file.
    let out =
        tracery().args(["synth", "--exemplar", "lace", "--along", "circle:20", "--stl"]).arg(&*dir).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(check_one_line(&[], &out).contains("folder"));

    // All written: and no temporary file beside them.
    let out = tracery()
        .args(["synth", "--exemplar", "lace", "--along", "circle:20", "--quiet", "--stl"])
        .arg(&stl)
        .arg("--svg")
        .arg(dir.join("o.svg"))
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stdout.is_empty(), "--quiet printed {}", String::from_utf8_lossy(&out.stdout));
    let mut names: Vec<String> =
        std::fs::read_dir(&*dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, ["o.stl", "o.svg"]);
}

/// Whether `path` holds a whole binary STL: its size agrees with its triangle count.
fn whole_stl(path: &Path) -> Option<usize> {
    let bytes = std::fs::read(path).ok()?;
    let count = u32::from_le_bytes(bytes.get(80..84)?.try_into().ok()?) as usize;
    (bytes.len() == 84 + 50 * count).then_some(count)
}

#[test]
fn a_run_killed_at_any_moment_leaves_the_old_file_or_the_whole_new_one() {
    let dir = tempdir("killed");
    let stl = dir.join("o.stl");
    // A long pattern whose STL takes a while to make and write.
    let args = ["synth", "--exemplar", "lace", "--along", "line:900", "--band", "6", "--quiet", "--stl"];
    let started = Instant::now();
    let out = tracery().args(args).arg(&stl).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let whole_run = started.elapsed();
    let new_count = whole_stl(&stl).expect("the first run's STL is whole");
    let kills = 24;
    let mut outcomes = [0; 2];
    for k in 0..kills {
        // The old file: a different, smaller STL.
        std::fs::write(&stl, [vec![0u8; 80], 1u32.to_le_bytes().to_vec(), vec![0u8; 50]].concat()).unwrap();
        let mut child = tracery().args(args).arg(&stl).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
        // Kills spread over the whole run, the last ones near its end,
        // when the file is being written.
        let at = whole_run.mul_f64((k as f64 + 0.5) / kills as f64 * 1.1);
        std::thread::sleep(at);
        let _ = child.kill();
        let _ = child.wait();
        let count = whole_stl(&stl).expect("the STL is whole after a kill");
        assert!(count == 1 || count == new_count, "kill {k}: {count} triangles");
        outcomes[usize::from(count == new_count)] += 1;
        let names: Vec<String> =
            std::fs::read_dir(&*dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        assert_eq!(names, ["o.stl"], "kill {k} left a temporary file");
    }
    eprintln!("{kills} kills over a {whole_run:?} run: {} left the old file, {} the new one", outcomes[0], outcomes[1]);
    assert!(outcomes[0] > 0, "no kill landed before the write: {outcomes:?}");
}

#[test]
fn ctrl_c_cancels_cleanly_and_leaves_no_file() {
    // A quilt over the vase runs for minutes, checking for Ctrl+C often; a
    // long narrow synth spends seconds in stages that check seldom.
    let runs: [&[&str]; 2] = [
        &["quilt", "--swatch", "weave", "--base", "vase"],
        &["synth", "--exemplar", "lace", "--along", "line:9000", "--band", "0.5"],
    ];
    for args in runs {
        let dir = tempdir("ctrl-c");
        let child = tracery().args(args).arg("--stl").arg(dir.join("o.stl")).stderr(Stdio::piped()).spawn().unwrap();
        std::thread::sleep(Duration::from_secs(2));
        let status = std::process::Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
        assert!(status.success());
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(130), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        assert!(check_one_line(args, &out).contains("cancelled"));
        assert_eq!(std::fs::read_dir(&*dir).unwrap().count(), 0, "{args:?}: Ctrl+C left a file");
    }
}
