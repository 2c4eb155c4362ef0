//! Fuzzing every loader and every specification parser with proptest (cargo
//! fuzz needs a nightly compiler): files mutated from real ones and text
//! built from the numbers that break programs. Each must answer `Ok` or a
//! refusal: never panic, never abort on an allocation.
//!
//! A short run goes in CI. A long run (`docs/robustness.md`):
//! `TRACERY_FUZZ_SECONDS=3600 cargo test -p tracery-core --release --test fuzz_inputs`
//! repeats every target with fresh random seeds until the time is spent.

use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use tracery_core::curve::{Along, first_path_points, svg_shapes};
use tracery_core::mesh::{read_obj, read_stl};
use tracery_core::mesh_quilt::{parse_base, parse_strokes};
use tracery_core::raster_brush::RasterExemplar;
use tracery_core::region_fill::{CurveExemplar, parse_region};
use tracery_core::setting::WORLD_EXTENT_MM;
use tracery_core::surface::{Shade, SurfaceSettings};
use tracery_core::vector_brush::{BUILTIN_NAMES, Exemplar, LoadOptions, builtin_svg};

/// Cases per target and round: `TRACERY_FUZZ_CASES`, 48 by default.
fn cases() -> u32 {
    std::env::var("TRACERY_FUZZ_CASES").ok().and_then(|c| c.parse().ok()).unwrap_or(48)
}

/// Runs `property` on values of `strategy` for [`cases`], and again with
/// fresh seeds until `TRACERY_FUZZ_SECONDS` have passed when that is set.
/// The seconds are wall-clock time for the whole file: shared among its
/// targets, which run side by side on the test threads.
///
/// With `TRACERY_FUZZ_LAST=DIR`, each input is written to `DIR/NAME` before
/// it is tried: when the process is killed (out of memory), the input that
/// did it is there.
fn fuzz<S: Strategy>(name: &str, strategy: S, property: impl Fn(S::Value))
where
    S::Value: std::fmt::Debug,
{
    let last =
        std::env::var_os("TRACERY_FUZZ_LAST").map(|dir| std::path::PathBuf::from(dir).join(name.replace('/', "-")));
    let seconds: u64 = std::env::var("TRACERY_FUZZ_SECONDS").ok().and_then(|s| s.parse().ok()).unwrap_or(0);
    let threads = std::env::var("RUST_TEST_THREADS")
        .ok()
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get() as u64));
    let deadline = Instant::now() + Duration::from_secs(seconds * threads.min(TARGETS) / TARGETS);
    let mut rounds = 0u64;
    loop {
        let config = Config { cases: cases(), failure_persistence: None, ..Config::default() };
        let mut runner = TestRunner::new(config);
        if let Err(e) = runner.run(&strategy, |value| {
            if let Some(last) = &last {
                let _ = std::fs::write(last, format!("{value:?}"));
            }
            property(value);
            Ok(())
        }) {
            panic!("{name}: {e}");
        }
        rounds += 1;
        if Instant::now() >= deadline {
            break;
        }
    }
    if seconds > 0 {
        eprintln!("{name}: {rounds} round(s) of {} cases, nothing found", cases());
    }
}

/// The targets in this file, which share the long run's seconds.
const TARGETS: u64 = 9;

/// Real SVGs: the built-in exemplars and, where the corpus is at hand, a
/// few real ornaments.
fn svg_seeds() -> Vec<Vec<u8>> {
    let mut seeds: Vec<Vec<u8>> =
        BUILTIN_NAMES.iter().filter_map(|n| builtin_svg(n)).map(|s| s.as_bytes().to_vec()).collect();
    let corpus = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus/ornaments");
    if let Ok(entries) = std::fs::read_dir(corpus) {
        let mut paths: Vec<_> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        paths.sort();
        seeds.extend(
            paths
                .iter()
                .filter(|p| p.extension().is_some_and(|e| e == "svg"))
                .take(6)
                .filter_map(|p| std::fs::read(p).ok()),
        );
    }
    seeds
}

/// One change to a file: overwrite, insert, delete or repeat a stretch.
#[derive(Clone, Debug)]
enum Edit {
    Set(usize, u8),
    Insert(usize, Vec<u8>),
    Delete(usize, usize),
    Repeat(usize, usize, usize),
}

/// Text that breaks parsers: extreme numbers, units and tokens.
const NASTY: &[&str] = &[
    "1e308",
    "-1e308",
    "1e-320",
    "NaN",
    "inf",
    "-0",
    "0",
    "99999999999999999999",
    "1e12",
    "-1",
    ".",
    "e",
    "%",
    "mm",
    "\u{0}",
    "<",
    ">",
    "&lt;",
    "\"",
    "'",
    " ",
    ",",
    ";",
    "x",
    "Z",
    "M",
    "L",
    "C",
    "A 1e308 1e308 0 1 1",
    "<g>",
    "</g>",
    "<use href=\"#a\"/>",
    "<image href=\"/dev/zero\"/>",
    "transform=\"scale(1e300)\"",
    "viewBox=\"0 0 0 0\"",
];

fn edits() -> impl Strategy<Value = Vec<Edit>> {
    let nasty = proptest::sample::select(NASTY).prop_map(|s| s.as_bytes().to_vec());
    let edit = prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(at, b)| Edit::Set(at, b)),
        (any::<usize>(), nasty).prop_map(|(at, text)| Edit::Insert(at, text)),
        (any::<usize>(), any::<usize>()).prop_map(|(at, n)| Edit::Delete(at, n % 64)),
        (any::<usize>(), any::<usize>(), 1usize..40).prop_map(|(at, n, times)| Edit::Repeat(at, n % 32 + 1, times)),
    ];
    proptest::collection::vec(edit, 0..12)
}

fn apply(mut bytes: Vec<u8>, edits: &[Edit]) -> Vec<u8> {
    for edit in edits {
        let len = bytes.len().max(1);
        match edit {
            Edit::Set(at, b) => {
                if !bytes.is_empty() {
                    let at = at % len;
                    bytes[at] = *b;
                }
            }
            Edit::Insert(at, text) => {
                let at = at % (bytes.len() + 1);
                bytes.splice(at..at, text.iter().copied());
            }
            Edit::Delete(at, n) => {
                let at = at % len;
                let end = (at + n).min(bytes.len());
                if at < end {
                    bytes.drain(at..end);
                }
            }
            Edit::Repeat(at, n, times) => {
                let at = at % len;
                let end = (at + n).min(bytes.len());
                let stretch: Vec<u8> = bytes.get(at..end).unwrap_or_default().to_vec();
                for _ in 0..*times {
                    bytes.splice(end..end, stretch.iter().copied());
                }
            }
        }
    }
    bytes
}

/// Files mutated from `seeds`.
fn mutated(seeds: Vec<Vec<u8>>) -> impl Strategy<Value = Vec<u8>> {
    (proptest::sample::select(seeds), edits()).prop_map(|(seed, edits)| apply(seed, &edits))
}

/// An SVG built around path data of nasty numbers.
fn built_svg() -> impl Strategy<Value = Vec<u8>> {
    let token = prop_oneof![
        proptest::sample::select(NASTY).prop_map(str::to_string),
        any::<f64>().prop_map(|x| x.to_string()),
        (-1e5f64..1e5).prop_map(|x| format!("{x:.3}")),
    ];
    let size = prop_oneof![Just("10mm".to_string()), Just("1e30".to_string()), Just("0".to_string()), token.clone()];
    (size.clone(), size, proptest::collection::vec(token, 0..40)).prop_map(|(w, h, tokens)| {
        let d = format!("M {}", tokens.join(" "));
        format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}"><path d="{d}" fill="black" stroke="black"/><circle r="{h}"/></svg>"#
        )
        .into_bytes()
    })
}

fn svgs() -> impl Strategy<Value = Vec<u8>> {
    prop_oneof![mutated(svg_seeds()), built_svg()]
}

#[test]
fn vector_exemplars_from_any_svg_load_or_are_refused() {
    fuzz("vector exemplar", svgs(), |data| {
        let _ = Exemplar::from_svg_data("fuzz", &data, &LoadOptions::default());
    });
}

#[test]
fn curves_from_any_svg_load_or_are_refused() {
    fuzz("curve svg", svgs(), |data| {
        if let Ok(points) = first_path_points(&data) {
            assert!(points.iter().all(|p| p.is_finite()));
        }
        let _ = svg_shapes(&data, 0.05);
    });
}

#[test]
fn region_fill_exemplars_from_any_svg_load_or_are_refused() {
    fuzz("fill exemplar", svgs(), |data| {
        let _ = CurveExemplar::from_svg_data("fuzz", &data);
    });
}

fn png_seed() -> Vec<u8> {
    let mut picture = image::RgbaImage::new(40, 16);
    for (x, y, pixel) in picture.enumerate_pixels_mut() {
        let opaque = (4..12).contains(&y) && x % 5 != 0;
        *pixel = image::Rgba([200, 40, 40, if opaque { 255 } else { 0 }]);
    }
    let mut bytes = Vec::new();
    picture.write_to(&mut std::io::Cursor::new(&mut bytes), image::ImageFormat::Png).unwrap();
    bytes
}

#[test]
fn raster_exemplars_from_any_png_load_or_are_refused() {
    fuzz("png", mutated(vec![png_seed()]), |data| {
        let _ = RasterExemplar::from_png("fuzz", &data);
    });
}

fn mesh_seeds() -> Vec<Vec<u8>> {
    let tetra = tracery_core::mesh::Mesh {
        vertices: vec![[0.0, 0.0, 0.0], [10.0, 0.0, 0.0], [0.0, 10.0, 0.0], [0.0, 0.0, 10.0]],
        triangles: vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    };
    let mut binary = Vec::new();
    tracery_core::export::write_stl(&tetra, &mut binary).unwrap();
    let ascii = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
    let obj = "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
    vec![binary, ascii.as_bytes().to_vec(), obj.as_bytes().to_vec()]
}

#[test]
fn meshes_from_any_stl_or_obj_load_or_are_refused() {
    fuzz("mesh", mutated(mesh_seeds()), |data| {
        for mesh in [read_stl(&data, "fuzz.stl"), read_obj(&data, "fuzz.obj")].into_iter().flatten() {
            assert!(mesh.vertices.iter().flatten().all(|c| c.is_finite()));
            assert!(mesh.triangles.iter().flatten().all(|&i| (i as usize) < mesh.vertices.len()));
        }
    });
}

/// Specification text: a kind, a colon and numbers, or anything.
fn specs() -> impl Strategy<Value = String> {
    let kind = proptest::sample::select(
        &["line", "circle", "wave", "square", "hexagon", "star", "heart", "rect", "plane", "", "svg-no"][..],
    );
    let number = prop_oneof![
        proptest::sample::select(NASTY).prop_map(str::to_string),
        any::<f64>().prop_map(|x| x.to_string()),
        (0.0f64..20_000.0).prop_map(|x| format!("{x}")),
    ];
    let separator = proptest::sample::select(&["x", ",", ";", " ", "", ":"][..]);
    prop_oneof![
        (kind, proptest::collection::vec((number, separator), 0..6)).prop_map(|(kind, parts)| {
            let rest: String = parts.into_iter().map(|(n, s)| format!("{n}{s}")).collect();
            format!("{kind}:{rest}")
        }),
        ".{0,40}",
    ]
}

#[test]
fn along_and_region_specifications_parse_or_are_refused() {
    fuzz("along/region", specs(), |spec| {
        if let Ok(along) = Along::parse(&spec) {
            assert!(along.length_mm().is_finite() && along.length_mm() <= 20.0 * WORLD_EXTENT_MM, "{spec}");
        }
        if let Ok(region) = parse_region(&spec) {
            assert!(region.area().is_finite(), "{spec}");
        }
        let _ = parse_base(&spec);
    });
}

#[test]
fn points_strokes_and_shades_parse_or_are_refused() {
    fuzz("points", specs(), |text| {
        if let Ok(points) = SurfaceSettings::parse_points(&text) {
            assert!(points.iter().flatten().all(|c| c.abs() <= WORLD_EXTENT_MM), "{text}");
        }
        let _ = parse_strokes(&text);
        let _ = Shade::parse_cylinder(&text);
        let _ = Shade::parse_cone(&text);
    });
}

#[test]
fn stroke_files_parse_or_are_refused() {
    let seed = "0,30,20;30,0,20;0,-30,20\n10,10,10;20,20,20\n".as_bytes().to_vec();
    fuzz("strokes", mutated(vec![seed]), |data| {
        let _ = parse_strokes(&String::from_utf8_lossy(&data));
    });
}

#[test]
fn svg_files_along_a_curve_are_read_or_refused() {
    let dir = std::env::temp_dir().join(format!("tracery-fuzz-along-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("along.svg");
    fuzz("along svg", svgs(), |data| {
        std::fs::write(&path, &data).unwrap();
        if let Ok(along) = Along::parse(&format!("svg:{}", path.display())) {
            assert!(along.length_mm().is_finite());
        }
    });
    let _ = std::fs::remove_dir_all(&dir);
}
