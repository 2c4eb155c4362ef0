//! A closed solid from an open, oriented sheet of triangles: the sheet as
//! its top, a copy as its bottom, and walls along the sheet's boundary.

use std::collections::HashSet;

use super::Mesh;

/// The solid between two placements of `sheet`: vertex `i` of the sheet
/// stands at `bottom[i]` and at `top[i]`. The top keeps the sheet's
/// orientation, the bottom is reversed, and every boundary edge of the
/// sheet (a directed edge whose reverse no triangle has) gets a wall of two
/// triangles. The solid is therefore closed by construction, whatever the
/// placements, with one shell per edge-connected part of the sheet.
///
/// Walls joining each sheet vertex's own two placements are what lets a
/// bent solid stay free of slivers: were the flat solid bent instead, its
/// walls (as tall as the solid is thick, and sometimes a micrometre wide)
/// would be split into needles whose vertices fall together in `f32`.
///
/// # Panics
/// When `bottom` or `top` does not have one position per sheet vertex.
///
/// ```
/// use tracery_core::mesh::{Mesh, thicken};
/// let square = Mesh {
///     vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
///     triangles: vec![[0, 1, 2], [0, 2, 3]],
/// };
/// let top: Vec<[f64; 3]> = square.vertices.iter().map(|v| [v[0], v[1], 2.0]).collect();
/// let solid = thicken(&square, &square.vertices, &top);
/// assert!(solid.sanity_check().is_ok());
/// assert!((solid.signed_volume() - 2.0).abs() < 1e-12);
/// ```
pub fn thicken(sheet: &Mesh, bottom: &[[f64; 3]], top: &[[f64; 3]]) -> Mesh {
    let n = sheet.vertices.len();
    assert!(bottom.len() == n && top.len() == n, "one bottom and one top position per sheet vertex");
    let count = n as u32;
    let mut solid =
        Mesh { vertices: Vec::with_capacity(2 * n), triangles: Vec::with_capacity(2 * sheet.triangles.len()) };
    solid.vertices.extend_from_slice(bottom);
    solid.vertices.extend_from_slice(top);
    let mut directed: HashSet<(u32, u32)> = HashSet::with_capacity(3 * sheet.triangles.len());
    for &[a, b, c] in &sheet.triangles {
        solid.triangles.push([a + count, b + count, c + count]);
        solid.triangles.push([a, c, b]);
        directed.extend([(a, b), (b, c), (c, a)]);
    }
    for &[a, b, c] in &sheet.triangles {
        for (from, to) in [(a, b), (b, c), (c, a)] {
            if !directed.contains(&(to, from)) {
                // The sheet lies to the left of a boundary edge (its
                // triangles run counter-clockwise), so the wall faces right.
                solid.triangles.push([from, to, to + count]);
                solid.triangles.push([from, to + count, from + count]);
            }
        }
    }
    solid
}
