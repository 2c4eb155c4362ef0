//! The built-in swatches, modelled here from tubes, tori and solids of
//! revolution: chain mail, a weave, rivets and nuts, scales and leaves.

use std::f64::consts::{FRAC_PI_2, PI};

use glam::{DMat3, DVec2, DVec3};

use super::shapes::{lathe, lathe_ring, orient_outward, torus, tube};
use super::{Element, Swatch};
use crate::random::SplitMix64;

/// The built-in swatches' names, for `tracery list --swatches` and the app.
pub const SWATCH_NAMES: [&str; 5] = ["chainmail", "weave", "rivets", "scales", "leaves"];

/// A built-in swatch by name.
///
/// ```
/// use tracery_core::mesh_quilt::{SWATCH_NAMES, builtin_swatch};
/// for name in SWATCH_NAMES {
///     let swatch = builtin_swatch(name).unwrap();
///     assert!(swatch.elements.iter().all(|e| e.is_closed()));
/// }
/// assert!(builtin_swatch("lace").is_none());
/// ```
pub fn builtin_swatch(name: &str) -> Option<Swatch> {
    let elements = match name {
        "chainmail" => chainmail(),
        "weave" => weave(),
        "rivets" => rivets(),
        "scales" => scales(),
        "leaves" => leaves(),
        _ => return None,
    };
    Swatch::from_elements(name, elements).ok()
}

/// Flat rings on a 10 mm grid, each pair of neighbours linked by a standing
/// ring through both their holes: every link is whole and none touches
/// another, so a quilt of it prints as loose, interlocked rings.
fn chainmail() -> Vec<Element> {
    const PITCH: f64 = 10.0;
    const N: usize = 4;
    let mut out = Vec::new();
    for i in 0..N {
        for j in 0..N {
            let at = DVec3::new(i as f64 * PITCH, j as f64 * PITCH, 0.0);
            out.push(torus(at, DMat3::IDENTITY, 4.0, 0.8, 32, 10));
            // The standing ring crosses the plane 2 mm from each flat
            // ring's centre, inside its 3.2 mm hole, and passes 2 mm from
            // its wire: 0.6 mm clear of both tubes.
            if i + 1 < N {
                let plane_xz = DMat3::from_cols(DVec3::X, DVec3::Z, -DVec3::Y);
                out.push(torus(at + DVec3::X * PITCH / 2.0, plane_xz, 3.0, 0.6, 28, 8));
            }
            if j + 1 < N {
                let plane_yz = DMat3::from_cols(DVec3::Y, DVec3::Z, DVec3::X);
                out.push(torus(at + DVec3::Y * PITCH / 2.0, plane_yz, 3.0, 0.6, 28, 8));
            }
        }
    }
    out
}

/// A plain weave: threads along `x` and along `y`, each passing over one
/// crossing and under the next; they clear each other by 0.6 mm.
fn weave() -> Vec<Element> {
    const PITCH: f64 = 6.0;
    const N: usize = 4;
    const AMPLITUDE: f64 = 1.2;
    const STEPS_PER_PITCH: usize = 16;
    let samples = N * STEPS_PER_PITCH + 1;
    let mut out = Vec::new();
    for row in 0..N {
        let lane = row as f64 * PITCH;
        let along = |k: usize| -PITCH / 2.0 + N as f64 * PITCH * k as f64 / (samples - 1) as f64;
        let phase = row as f64 * PI;
        let x_path: Vec<DVec3> = (0..samples)
            .map(|k| {
                let x = along(k);
                DVec3::new(x, lane, AMPLITUDE * (PI * x / PITCH + phase).cos())
            })
            .collect();
        let y_path: Vec<DVec3> = (0..samples)
            .map(|k| {
                let y = along(k);
                DVec3::new(lane, y, -AMPLITUDE * (PI * y / PITCH + phase).cos())
            })
            .collect();
        out.push(tube(&x_path, 0.9, 10, false));
        out.push(tube(&y_path, 0.9, 10, false));
    }
    out
}

/// Domed rivets and hexagon nuts of several sizes on a jittered grid.
fn rivets() -> Vec<Element> {
    const PITCH: f64 = 8.0;
    let mut random = SplitMix64::new(7);
    let mut out = Vec::new();
    for i in 0..5 {
        for j in 0..5 {
            let jitter = DVec3::new(random.next_unit() - 0.5, random.next_unit() - 0.5, 0.0) * 1.2;
            let at = DVec3::new(i as f64 * PITCH, j as f64 * PITCH, 0.0) + jitter;
            if random.next_unit() < 0.35 {
                let (inner, outer, height) = (1.0 + 0.3 * random.next_unit(), 2.6, 1.4 + 0.6 * random.next_unit());
                let profile = [
                    DVec2::new(inner, 0.0),
                    DVec2::new(outer, 0.0),
                    DVec2::new(outer, height),
                    DVec2::new(inner, height),
                ];
                out.push(lathe_ring(at, &profile, 6));
            } else {
                let head = 2.2 + 0.9 * random.next_unit();
                let (shank, neck, dome) = (1.0, 0.6 + 0.8 * random.next_unit(), 1.2 + 0.6 * random.next_unit());
                let mut profile = vec![DVec2::new(0.0, 0.0), DVec2::new(shank, 0.0), DVec2::new(shank, neck)];
                profile.extend((0..7).map(|k| {
                    let a = FRAC_PI_2 * k as f64 / 7.0;
                    DVec2::new(head * a.cos(), neck + dome * a.sin())
                }));
                profile.push(DVec2::new(0.0, neck + dome));
                out.push(lathe(at, &profile, 16, DMat3::IDENTITY));
            }
        }
    }
    out
}

/// A unit sphere as a solid of revolution.
fn sphere(rings: usize, sides: usize) -> Element {
    let profile: Vec<DVec2> = (0..=rings)
        .map(|k| {
            let a = -FRAC_PI_2 + PI * k as f64 / rings as f64;
            DVec2::new(a.cos().max(0.0), a.sin())
        })
        .collect();
    lathe(DVec3::ZERO, &profile, sides, DMat3::IDENTITY)
}

/// `element` with every vertex moved by `map`, kept facing out.
fn mapped(element: &Element, map: impl Fn(DVec3) -> DVec3) -> Element {
    let mut out =
        Element { vertices: element.vertices.iter().map(|&v| map(v)).collect(), triangles: element.triangles.clone() };
    orient_outward(&mut out);
    out
}

/// Oval scales in overlapping rows, each tipped up 20° so that it rides
/// over the row below without touching it.
fn scales() -> Vec<Element> {
    let unit = sphere(8, 18);
    let tilt = DMat3::from_rotation_x(20f64.to_radians());
    let mut out = Vec::new();
    for row in 0..6 {
        for column in 0..5 {
            let shift = if row % 2 == 1 { 4.3 } else { 0.0 };
            let at = DVec3::new(column as f64 * 8.6 + shift, row as f64 * 6.0, 2.2);
            out.push(mapped(&unit, |v| at + tilt * DVec3::new(4.0 * v.x, 5.0 * v.y, 0.5 * v.z)));
        }
    }
    out
}

/// Curled, pointed leaves at random angles on a jittered grid, never
/// touching one another.
fn leaves() -> Vec<Element> {
    let unit = sphere(8, 20);
    let mut random = SplitMix64::new(11);
    let mut out = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let jitter = DVec3::new(random.next_unit() - 0.5, random.next_unit() - 0.5, 0.0) * 0.8;
            let at = DVec3::new(i as f64 * 10.0, j as f64 * 10.0, 0.4) + jitter;
            let turn = DMat3::from_rotation_z(PI * random.next_unit());
            let curl = 0.15 + 0.2 * random.next_unit();
            out.push(mapped(&unit, |v| {
                // Along the sphere's z (the lathe axis) runs the leaf's midrib.
                let along = v.z;
                let across = 1.8 * v.x * (1.0 - 0.55 * along * along);
                let up = 0.35 * v.y + curl * 4.0 * along * along;
                at + turn * DVec3::new(4.0 * along, across, up)
            }));
        }
    }
    out
}
