//! Quilts a built-in base with a built-in swatch and prints what it did:
//! `cargo run -p tracery-core --release --example quilt_surface -- [BASE] [SWATCH] [SCALE] [OUT.stl] [SEED]`.
//!
//! Three measures of the result that the quilting never reads: `bare`, the
//! share of the base's area (all but the faces it stands on) farther than
//! 1, 1.5 and 3 mm from every texture vertex (and at 1.5 mm, of the side's
//! top 10 mm; a weave missing rows between its threads up the model shows
//! at 1 mm, where every point still lies within 1.5 mm of a thread);
//! `runs`, the median length of the elements along their longest axis, mm
//! (woven threads broken into short runs show as short ones); and `tilt`,
//! the median angle between an element's longest axis and the nearer of
//! round the `z` axis or across that, 0° to 45° (threads running round a
//! vase or up it lie at 0°).

use std::time::Instant;

use glam::DVec3;
use rustc_hash::FxHashMap;

use tracery_core::control::Control;
use tracery_core::export::write_stl;
use tracery_core::mesh::Mesh;
use tracery_core::mesh_quilt::{GuidanceField, Settings, builtin_swatch, crosses_itself, quilt_surface};
use tracery_core::surface::{SurfaceMesh, builtin_base};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let base = args.get(1).map_or("vase", String::as_str);
    let swatch = args.get(2).map_or("rivets", String::as_str);
    let scale: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1.0);
    let surface = SurfaceMesh::new(builtin_base(base).expect("a built-in base")).expect("a sound base");
    let swatch = builtin_swatch(swatch).expect("a built-in swatch").scaled(scale);
    let mut settings = Settings::default();
    if let Some(seed) = args.get(5).and_then(|s| s.parse().ok()) {
        settings.seed = seed;
    }
    let start = Instant::now();
    let quilt = quilt_surface(&swatch, &surface, &GuidanceField::around_axis(&surface), &settings, &Control::default())
        .expect("a quilt");
    let elapsed = start.elapsed().as_millis();
    let mut mesh = Mesh::default();
    for e in &quilt.elements {
        mesh.append(&e.to_mesh());
    }
    let vertices: Vec<DVec3> = quilt.elements.iter().flat_map(|e| e.vertices.iter().copied()).collect();
    let bare: Vec<String> =
        [1.0, 1.5, 3.0].iter().map(|&d| format!("{:.3}", bare_share(&surface, &vertices, d))).collect();
    let bare = bare.join("/");
    // The side just under the rim: faces not facing up or down, within
    // 10 mm of the top.
    let top_z = surface.positions().iter().map(|p| p.z).fold(f64::MIN, f64::max);
    let under_rim = bare_share_of(&surface, &vertices, 1.5, |n, c| n.z.abs() < 0.9 && c.z > top_z - 10.0);
    let (mut runs, mut tilts): (Vec<f64>, Vec<f64>) = quilt.elements.iter().map(|e| run_and_tilt(&e.vertices)).unzip();
    let median = |values: &mut Vec<f64>| {
        values.sort_by(f64::total_cmp);
        values.get(values.len() / 2).copied().unwrap_or(0.0)
    };
    let (run, tilt) = (median(&mut runs), median(&mut tilts));
    println!(
        "{base} + {}: {} ms, bare {bare} (under the rim {under_rim:.3}), runs {run:.1} mm, tilt {tilt:.1}°, {} patches, {} elements ({} crossing), {} faces; {:?}; {:?}",
        swatch.name,
        elapsed,
        quilt.counts.patches,
        quilt.elements.len(),
        quilt.elements.iter().filter(|e| crosses_itself(e)).count(),
        mesh.triangles.len(),
        quilt.counts.merges,
        quilt.shell
    );
    if let Some(out) = args.get(4) {
        let mut file = std::fs::File::create(out).expect("create the STL");
        write_stl(&mesh, &mut file).expect("write the STL");
    }
}

/// The share of `surface`'s area, less the faces facing straight down,
/// whose centroid lies farther than `reach_mm` from every one of `points`.
fn bare_share(surface: &SurfaceMesh, points: &[DVec3], reach_mm: f64) -> f64 {
    bare_share_of(surface, points, reach_mm, |normal, _| normal.z >= -0.9)
}

/// As [`bare_share`], over the faces for which `counts(unit normal,
/// centre)` holds.
fn bare_share_of(surface: &SurfaceMesh, points: &[DVec3], reach_mm: f64, counts: impl Fn(DVec3, DVec3) -> bool) -> f64 {
    let cell = |p: DVec3| (p / reach_mm).floor().as_ivec3();
    let mut grid: FxHashMap<glam::IVec3, Vec<DVec3>> = FxHashMap::default();
    for &p in points {
        grid.entry(cell(p)).or_default().push(p);
    }
    let (mut bare, mut total) = (0.0, 0.0);
    for (f, t) in surface.triangles().iter().enumerate() {
        let [a, b, c] = t.map(|v| surface.positions()[v as usize]);
        let area = 0.5 * (b - a).cross(c - a).length();
        let centre = (a + b + c) / 3.0;
        if !counts(surface.face_normal(f as u32), centre) {
            continue;
        }
        let home = cell(centre);
        let near = (-1..=1).any(|x| {
            (-1..=1).any(|y| {
                (-1..=1).any(|z| {
                    grid.get(&(home + glam::IVec3::new(x, y, z)))
                        .is_some_and(|ps| ps.iter().any(|p| p.distance(centre) <= reach_mm))
                })
            })
        });
        total += area;
        if !near {
            bare += area;
        }
    }
    bare / total.max(f64::MIN_POSITIVE)
}

/// How far `points` reach along their principal axis (the covariance's
/// leading eigenvector, by power iteration), mm; and the angle between
/// that axis and the nearer of round the `z` axis (at their centre) or
/// square to that, degrees.
fn run_and_tilt(points: &[DVec3]) -> (f64, f64) {
    let centre = points.iter().sum::<DVec3>() / points.len().max(1) as f64;
    let mut cov = glam::DMat3::ZERO;
    for &p in points {
        let d = p - centre;
        cov += glam::DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    let mut axis = DVec3::new(1.0, 0.7, 0.3);
    for _ in 0..50 {
        axis = (cov * axis).normalize_or_zero();
    }
    let (lo, hi) = points.iter().map(|p| p.dot(axis)).fold((f64::MAX, f64::MIN), |(lo, hi), d| (lo.min(d), hi.max(d)));
    let around = DVec3::Z.cross(centre.with_z(0.0)).normalize_or_zero();
    let angle = axis.dot(around).abs().min(1.0).acos().to_degrees();
    ((hi - lo).max(0.0), angle.min(90.0 - angle))
}
