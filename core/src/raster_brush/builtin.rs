//! Built-in raster exemplars, painted procedurally here: rope, chain, braid,
//! lace, vine and stitches. Each is a shape test per point, supersampled
//! 4 × 4 for smooth edges, with shading from the shape's own geometry.
//! Sizes are the paper's where it gives them (199 × 82 and 325 × 64).

use std::f64::consts::{PI, TAU};

use super::{ExemplarError, RasterExemplar};

/// The built-in raster exemplars, in picker order.
pub const BUILTIN_NAMES: &[&str] = &["rope", "chain", "braid", "lace", "vine", "stitches"];

/// Samples per pixel side when painting.
const SUPERSAMPLING: usize = 4;

type Rgb = [f64; 3];

/// Paints a `width × height` picture from `shade(x, y)`: the colour at a
/// point (pixels, `y` down), or `None` where it is transparent.
fn paint(width: u32, height: u32, shade: impl Fn(f64, f64) -> Option<Rgb>) -> Vec<u8> {
    let mut rgba = Vec::with_capacity((4 * width * height) as usize);
    let n = SUPERSAMPLING;
    for y in 0..height {
        for x in 0..width {
            let (mut sum, mut hits) = ([0.0; 3], 0usize);
            for j in 0..n {
                for i in 0..n {
                    let p = (f64::from(x) + (i as f64 + 0.5) / n as f64, f64::from(y) + (j as f64 + 0.5) / n as f64);
                    if let Some(c) = shade(p.0, p.1) {
                        (0..3).for_each(|k| sum[k] += c[k]);
                        hits += 1;
                    }
                }
            }
            let alpha = hits as f64 / (n * n) as f64;
            let colour = |k: usize| if hits > 0 { (sum[k] / hits as f64).clamp(0.0, 255.0) as u8 } else { 0 };
            rgba.extend_from_slice(&[colour(0), colour(1), colour(2), (alpha * 255.0).round() as u8]);
        }
    }
    rgba
}

fn tint(base: Rgb, light: f64) -> Rgb {
    base.map(|c| c * light)
}

/// Lighting across a round strand: 1 on its axis, darker to its sides.
fn round_light(across: f64) -> f64 {
    0.45 + 0.55 * (1.0 - across.clamp(-1.0, 1.0).powi(2)).sqrt()
}

fn rope(x: f64, y: f64) -> Option<Rgb> {
    let cy = 32.0;
    // The twist's period drifts a little along the rope, so no two stretches match exactly.
    let along = x + 2.5 * (x / 23.0).sin() - 0.9 * (y - cy);
    let s = (along / 15.0).rem_euclid(1.0);
    let strand = (PI * s).sin();
    let radius = 21.0 - 3.0 * (1.0 - strand);
    if (y - cy).abs() > radius {
        return None;
    }
    let light = round_light((y - cy) / 22.0) * (0.35 + 0.65 * strand.sqrt());
    Some(tint([196.0, 152.0, 92.0], light))
}

fn chain(x: f64, y: f64) -> Option<Rgb> {
    let (cy, pitch, x0) = (41.0, 36.0, 10.0);
    let steel = [176.0, 182.0, 194.0];
    // Edge-on links lie over the face-on ones.
    for k in (1..6).step_by(2) {
        let cx = x0 + pitch * k as f64;
        let half_length = 25.0 + 1.5 * (k as f64 * 1.7).sin();
        let (dx, dy) = ((x - cx).abs() - (half_length - 4.5), y - cy);
        let d = if dx > 0.0 { dx.hypot(dy) } else { dy.abs() };
        if d <= 4.5 {
            return Some(tint(steel, round_light(dy / 4.5) * (0.8 + 0.2 * (x / 9.0).cos())));
        }
    }
    for k in (0..7).step_by(2) {
        let cx = x0 + pitch * k as f64;
        let a = 27.0 + 1.5 * (k as f64 * 2.3).sin();
        let b = 17.0 + (k as f64 * 1.1).cos();
        let r = ((x - cx) / a).hypot((y - cy) / b);
        let thickness = 6.5 / b;
        if (1.0 - thickness..=1.0).contains(&r) {
            let across = 2.0 * (r - (1.0 - thickness)) / thickness - 1.0;
            return Some(tint(steel, round_light(across)));
        }
    }
    None
}

fn braid(x: f64, y: f64) -> Option<Rgb> {
    let cy = 32.0;
    let colours = [[214.0, 178.0, 108.0], [168.0, 116.0, 66.0], [232.0, 206.0, 150.0]];
    let mut best: Option<(f64, Rgb)> = None;
    for (k, colour) in colours.iter().enumerate() {
        let phase = TAU * x / 52.0 + TAU * k as f64 / 3.0 + 0.3 * (x / 41.0).sin();
        let centre = cy + 13.0 * phase.sin();
        // Half-width measured across the strand, which runs at a slope.
        let slope = 13.0 * TAU / 52.0 * phase.cos();
        let d = (y - centre) / (1.0 + slope * slope).sqrt();
        let half = 8.5;
        let depth = phase.cos();
        if d.abs() <= half && best.is_none_or(|(z, _)| depth > z) {
            best = Some((depth, tint(*colour, round_light(d / half) * (0.75 + 0.25 * depth))));
        }
    }
    best.map(|(_, c)| c)
}

fn lace(x: f64, y: f64) -> Option<Rgb> {
    let cream = [238.0, 230.0, 212.0];
    let (top, bottom) = (12.0, 21.0);
    let i = ((x - 4.0) / 24.0).round();
    let cx = 4.0 + 24.0 * i;
    let tall = (i as i64).rem_euclid(3) == 1;
    let radius = if tall { 17.5 } else { 15.0 };
    let dist = (x - cx).hypot(y - bottom);
    // Eyelets along the header, between scallops.
    let eyelet = (x - cx - 12.0).hypot(y - 16.5) < 2.2 || (x - cx + 12.0).hypot(y - 16.5) < 2.2;
    if (top..=bottom).contains(&y) && !eyelet {
        return Some(tint(cream, 0.85 + 0.15 * ((y - top) / (bottom - top) * PI).sin()));
    }
    if y > bottom && dist <= radius {
        let hole = if tall {
            (x - cx).hypot(y - bottom - 7.0) < 6.5
        } else {
            (x - cx - 4.5).hypot(y - bottom - 5.5) < 3.0 || (x - cx + 4.5).hypot(y - bottom - 5.5) < 3.0
        };
        if hole {
            return None;
        }
        return Some(tint(cream, 0.7 + 0.3 * (1.0 - dist / radius).sqrt()));
    }
    // A picot under every scallop, overlapping it.
    if (x - cx).hypot(y - bottom - radius - 2.0) < 3.2 {
        return Some(tint(cream, 0.8));
    }
    None
}

fn vine(x: f64, y: f64) -> Option<Rgb> {
    let stem_y = |x: f64| 40.0 + 9.0 * (TAU * x / 110.0).sin();
    let stem = [62.0, 104.0, 48.0];
    if (y - stem_y(x)).abs() < 2.6 {
        return Some(tint(stem, round_light((y - stem_y(x)) / 2.6)));
    }
    for j in 0..7 {
        let bx = 14.0 + 33.0 * j as f64;
        let by = stem_y(bx);
        let up = if j % 2 == 0 { -1.0 } else { 1.0 };
        let angle: f64 = up * (0.9 + 0.15 * (j as f64 * 1.3).sin());
        let (dir_x, dir_y) = (angle.cos(), angle.sin());
        let length = 21.0 + 3.0 * (j as f64 * 2.1).cos();
        // Leaf coordinates: along its midrib from the stem, and across it.
        let (px, py) = (x - bx, y - by);
        let along = px * dir_x + py * dir_y;
        let across = -px * dir_y + py * dir_x;
        if (0.0..=length).contains(&along) {
            let width = 7.0 * (PI * along / length).sin().powf(0.8);
            if across.abs() <= width {
                let rib = if across.abs() < 0.7 && along > 2.0 { 0.7 } else { 1.0 };
                return Some(tint([110.0, 168.0, 72.0], rib * (0.75 + 0.25 * (1.0 - across.abs() / width.max(0.1)))));
            }
        }
        // A curling tendril beside every other leaf.
        if j % 2 == 1 {
            let (tx, ty) = (bx + 16.0, by - 9.0 * up);
            let r = (x - tx).hypot(y - ty);
            let theta = (y - ty).atan2(x - tx);
            if (r - 5.0).abs() < 1.1 && theta.sin() * up < 0.6 {
                return Some(tint(stem, 0.9));
            }
            if (x - (bx + 8.0)).abs() < 8.0 && ((y - stem_y(x)) * -up - ((x - bx) * 0.9)).abs() < 1.2 && x > bx + 2.0 {
                return Some(tint(stem, 0.9));
            }
        }
    }
    None
}

fn stitches(x: f64, y: f64) -> Option<Rgb> {
    // A row of cross stitches over a running stitch.
    let red = [196.0, 52.0, 58.0];
    let blue = [52.0, 86.0, 170.0];
    let i = ((x - 10.0) / 20.0).round();
    let cx = 10.0 + 20.0 * i;
    let (dx, dy) = (x - cx, y - 20.0);
    let size = 7.0 + 0.6 * (i * 1.9).sin();
    if dx.abs() <= size && dy.abs() <= size {
        let d1 = (dx - dy).abs() / 2f64.sqrt();
        let d2 = (dx + dy).abs() / 2f64.sqrt();
        let thread = 1.7;
        if d1 < thread {
            return Some(tint(red, round_light(d1 / thread) * if d2 < thread { 0.8 } else { 1.0 }));
        }
        if d2 < thread {
            return Some(tint(red, round_light(d2 / thread)));
        }
    }
    let j = ((x - 4.0) / 18.0).floor();
    let start = 4.0 + 18.0 * j;
    let t = x - start;
    let centre = 46.0 + (t - 6.0) * 0.12;
    if (0.0..12.0).contains(&t) && (y - centre).abs() < 2.0 {
        return Some(tint(blue, round_light((y - centre) / 2.0)));
    }
    None
}

/// A built-in exemplar by name.
///
/// ```
/// use tracery_core::raster_brush::{BUILTIN_NAMES, builtin};
/// for name in BUILTIN_NAMES {
///     let e = builtin(name).unwrap();
///     assert!(e.coverage() > 0.05 && e.coverage() < 0.9, "{name}");
/// }
/// assert!(builtin("nothing").is_none());
/// ```
pub fn builtin(name: &str) -> Option<RasterExemplar> {
    let (width, height, rgba) = match name {
        "rope" => (200, 64, paint(200, 64, rope)),
        "chain" => (199, 82, paint(199, 82, chain)),
        "braid" => (325, 64, paint(325, 64, braid)),
        "lace" => (200, 64, paint(200, 64, lace)),
        "vine" => (220, 80, paint(220, 80, vine)),
        "stitches" => (200, 60, paint(200, 60, stitches)),
        _ => return None,
    };
    let made: Result<RasterExemplar, ExemplarError> = RasterExemplar::from_rgba(name, width, height, rgba);
    made.ok()
}
