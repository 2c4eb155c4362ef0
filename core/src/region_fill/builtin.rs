//! Built-in curve exemplars, drawn here as polylines in a tile about 40 mm
//! square: spirals, a vine with tendrils, a meander, waves, crackle,
//! scales, and berries on stalks. Each is made of stroked paths; where one
//! path ends on another the two join (a junction). The berries also have
//! filled shapes (discrete elements).

use std::f64::consts::{PI, TAU};

use glam::DVec2;

use super::CurvePath;
use crate::geom::{Polygon, disc};

/// The built-in curve exemplars' names.
pub const BUILTIN_CURVES: [&str; 7] = ["spirals", "vine", "meander", "waves", "crackle", "scales", "berries"];

/// Side of the square tile the built-ins are drawn in, mm.
const TILE_MM: f64 = 40.0;

/// Points per millimetre of curve: fine enough that flattening is far below any sample spacing.
const POINTS_PER_MM: f64 = 4.0;

/// The built-in curve exemplar `name`, or `None`: its stroked paths, then
/// the outlines of its filled shapes ([`builtin_shapes`]), as an SVG
/// drawing of it would be read.
///
/// ```
/// use tracery_core::region_fill::{BUILTIN_CURVES, builtin_curves};
/// for name in BUILTIN_CURVES {
///     let paths = builtin_curves(name).unwrap();
///     assert!(!paths.is_empty(), "{name}");
/// }
/// assert!(builtin_curves("nothing").is_none());
/// ```
pub fn builtin_curves(name: &str) -> Option<Vec<CurvePath>> {
    let mut paths = builtin_strokes(name)?;
    paths.extend(builtin_shapes(name).into_iter().map(|s| CurvePath { points_mm: s.outer, closed: true }));
    Some(paths)
}

/// The stroked paths of the built-in `name`.
pub(super) fn builtin_strokes(name: &str) -> Option<Vec<CurvePath>> {
    Some(match name {
        "spirals" => spirals(),
        "vine" => vine(),
        "meander" => meander(),
        "waves" => waves(),
        "crackle" => crackle(),
        "scales" => scales(),
        "berries" => stems_and_stalks(),
        _ => return None,
    })
}

/// The filled shapes of the built-in `name` (none for most).
///
/// ```
/// use tracery_core::region_fill::builtin_shapes;
/// assert_eq!(builtin_shapes("berries").len(), 20);
/// assert!(builtin_shapes("waves").is_empty());
/// ```
pub fn builtin_shapes(name: &str) -> Vec<Polygon> {
    match name {
        "berries" => berries(),
        _ => Vec::new(),
    }
}

/// Radius of a berry, mm.
const BERRY_MM: f64 = 1.1;

/// Radius of a loose dot between the stems, mm.
const DOT_MM: f64 = 0.6;

/// Where the berries' stalks leave the stems: `(x, stem row, side)`.
fn stalks() -> Vec<(f64, usize, f64)> {
    (0..16).map(|k| (2.5 + 5.0 * (k % 8) as f64, k / 8, if k % 2 == 0 { 1.0 } else { -1.0 })).collect()
}

/// A stem of the berries, row `row`, at `x`.
fn berry_stem(row: usize, x: f64) -> DVec2 {
    let y = [11.0, 29.0][row];
    DVec2::new(x, y + 2.5 * (x / TILE_MM * TAU + 2.0 * row as f64).sin())
}

/// The direction a stalk leaves its stem: 60° from `+x`, up or down.
fn stalk_direction(side: f64) -> DVec2 {
    DVec2::from_angle(side * PI / 3.0)
}

/// Length of a stalk, mm.
const STALK_MM: f64 = 2.5;

/// Two wavy stems, with a short straight stalk leaving them every 5 mm,
/// up and down by turns, each ending on a berry.
fn stems_and_stalks() -> Vec<CurvePath> {
    let mut out: Vec<CurvePath> = (0..2).map(|row| traced(TILE_MM, |t| berry_stem(row, t * TILE_MM))).collect();
    for (x, row, side) in stalks() {
        let start = berry_stem(row, x);
        let end = start + stalk_direction(side) * STALK_MM;
        out.push(CurvePath { points_mm: vec![start, end], closed: false });
    }
    out
}

/// A berry at the end of each stalk, and a loose dot between the stems
/// every 10 mm.
fn berries() -> Vec<Polygon> {
    let sides = 24;
    let mut out: Vec<Polygon> = stalks()
        .into_iter()
        .map(|(x, row, side)| {
            let end = berry_stem(row, x) + stalk_direction(side) * STALK_MM;
            disc(end + stalk_direction(side) * BERRY_MM, BERRY_MM, sides)
        })
        .collect();
    out.extend((0..4).map(|k| disc(DVec2::new(5.0 + 10.0 * k as f64, 20.0), DOT_MM, sides)));
    out
}

/// An open path through `f(t)` for `t` in `0..=1`, `length_mm` long about.
fn traced(length_mm: f64, f: impl Fn(f64) -> DVec2) -> CurvePath {
    let n = (length_mm * POINTS_PER_MM).ceil().max(2.0) as usize;
    CurvePath { points_mm: (0..=n).map(|k| f(k as f64 / n as f64)).collect(), closed: false }
}

/// Archimedean spirals of three and a half turns, some turning each way.
fn spirals() -> Vec<CurvePath> {
    let centres = [(10.0, 10.0, 1.0), (30.0, 11.0, -1.0), (20.0, 24.0, 1.0), (8.0, 32.0, -1.0), (32.0, 32.0, 1.0)];
    centres
        .iter()
        .map(|&(x, y, turn)| {
            let (turns, radius) = (3.5, 6.5);
            traced(turns * PI * radius, |t| {
                let a = turn * t * turns * TAU;
                DVec2::new(x, y) + DVec2::from_angle(a) * (radius * t)
            })
        })
        .collect()
}

/// Two wavy stems across the tile, with curling tendrils branching off them.
fn vine() -> Vec<CurvePath> {
    let mut out = Vec::new();
    for (row, y) in [12.0, 30.0].into_iter().enumerate() {
        let stem = |x: f64| DVec2::new(x, y + 3.0 * (x / TILE_MM * TAU + row as f64).sin());
        out.push(traced(TILE_MM * 1.1, |t| stem(t * TILE_MM)));
        for k in 0..4 {
            let x0 = 5.0 + 10.0 * k as f64;
            let side = if k % 2 == 0 { 1.0 } else { -1.0 };
            out.push(tendril(stem(x0), side));
        }
    }
    out
}

/// A tendril leaving the stem at `start` straight up (`side` 1) or down
/// (−1), then curling ever tighter toward `+x`: its curvature grows along it.
fn tendril(start: DVec2, side: f64) -> CurvePath {
    let (length_mm, step_mm) = (12.0, 1.0 / POINTS_PER_MM);
    let mut points = vec![start];
    let (mut p, mut heading) = (start, side * 0.5 * PI);
    let steps = (length_mm / step_mm) as usize;
    for k in 0..steps {
        let s = k as f64 * step_mm;
        let curvature = 0.05 + 0.55 * s / length_mm;
        heading -= side * curvature * step_mm;
        p += DVec2::from_angle(heading) * step_mm;
        points.push(p);
    }
    CurvePath { points_mm: points, closed: false }
}

/// Rows of Greek keys: a base line per row, and keys rising from it,
/// each winding inward in right angles (its start on the line is a junction).
fn meander() -> Vec<CurvePath> {
    let unit = 2.5;
    let key = [(0.0, 0.0), (0.0, 4.0), (3.0, 4.0), (3.0, 1.0), (1.0, 1.0), (1.0, 3.0), (2.0, 3.0), (2.0, 2.0)];
    let mut out = Vec::new();
    for y in [3.0, 17.0, 31.0] {
        out.push(CurvePath { points_mm: vec![DVec2::new(0.0, y), DVec2::new(TILE_MM, y)], closed: false });
        for k in 0..3 {
            let x0 = 1.0 + 5.0 * k as f64;
            let points = key.iter().map(|&(u, v)| DVec2::new((x0 + u) * unit, y + v * unit)).collect();
            out.push(CurvePath { points_mm: points, closed: false });
        }
    }
    out
}

/// Parallel waves, each with a phase of its own.
fn waves() -> Vec<CurvePath> {
    (0..6)
        .map(|k| {
            let y = 4.0 + 6.5 * k as f64;
            let phase = 0.7 * k as f64;
            traced(TILE_MM * 1.2, |t| DVec2::new(t * TILE_MM, y + 1.8 * (t * 3.0 * TAU + phase).sin()))
        })
        .collect()
}

/// The crackle's jitter for `seed`, in `[-0.5, 0.5)`.
fn jitter(seed: u64) -> f64 {
    crate::random::unit(crate::random::splitmix64(seed)) - 0.5
}

/// Cracks: a jittered grid of points, each joined to its right and upper
/// neighbour by a slightly bent path, with a few joins left out, so cells
/// of different sizes meet at junctions of three and four.
fn crackle() -> Vec<CurvePath> {
    let n = 6;
    let step = TILE_MM / (n - 1) as f64;
    let point = |i: usize, j: usize| {
        let seed = (i * 31 + j) as u64;
        DVec2::new(i as f64 * step + 2.0 * jitter(seed), j as f64 * step + 2.0 * jitter(seed + 1000))
    };
    let mut out = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for (di, dj, salt) in [(1, 0, 0u64), (0, 1, 500)] {
                let (i2, j2) = (i + di, j + dj);
                let seed = (i * 31 + j) as u64 + salt;
                if i2 >= n || j2 >= n || jitter(seed + 77) > 0.3 {
                    continue;
                }
                let (a, b) = (point(i, j), point(i2, j2));
                let bend = (b - a).perp() * 0.15 * jitter(seed + 99);
                out.push(traced(step, |t| a + (b - a) * t + bend * (PI * t).sin()));
            }
        }
    }
    out
}

/// Fish scales: rows of half circles hanging down, each row shifted by
/// half a scale, its arcs ending on the bottoms of the arcs of the row above.
fn scales() -> Vec<CurvePath> {
    let radius = 5.0;
    let mut out = Vec::new();
    for row in 0..5 {
        let y = 8.0 + row as f64 * radius;
        let shift = if row % 2 == 0 { 0.0 } else { radius };
        for k in 0..4 {
            let centre = DVec2::new(shift + radius + 2.0 * radius * k as f64, y);
            out.push(traced(PI * radius, |t| centre + DVec2::from_angle(PI + PI * t) * radius));
        }
    }
    out
}
