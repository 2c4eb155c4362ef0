//! Quilting over a sharp crease: compact elements laid across a rim the
//! swatch is too wide to keep off were folded round it by the shell,
//! crumpled, torn into long triangles or through themselves. Checked on
//! the output's own triangles, apart from the code under test.

mod quilt_support;

use glam::DVec3;
use quilt_support::{closed, crosses_itself};
use tracery_core::control::Control;
use tracery_core::mesh_quilt::{Element, GuidanceField, Settings, builtin_swatch, quilt_surface};
use tracery_core::surface::{SurfaceMesh, builtin_base};

/// The longest edge of `e`'s triangles, mm.
fn longest_edge_mm(e: &Element) -> f64 {
    e.triangles
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
        .map(|(a, b)| e.vertices[a as usize].distance(e.vertices[b as usize]))
        .fold(0.0, f64::max)
}

/// Scales on the cylinder, whose top (50 mm across) is narrower than the
/// swatch's diagonal (61 mm): patches lie across its rim, and scales laid
/// over it were crumpled: 11 of the elements by the rim passed through
/// themselves, and the longest edge among them was 2.14 times the
/// swatch's. Now none does, that edge is 1.46 times the swatch's, and the
/// top and the side under the rim still carry scales (16 and 8, then 21
/// and 9). Since a scale that would fold is moved off the rim instead of
/// being left out, 22 and 15.
#[test]
fn scales_laid_across_a_rim_are_neither_folded_nor_torn() {
    let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
    let top_z = cylinder.positions().iter().map(|p| p.z).fold(f64::MIN, f64::max);
    let swatch = builtin_swatch("scales").unwrap();
    let size = swatch.size_mm();
    assert!(size.x.hypot(size.y) > 50.0, "the swatch must be too wide for the top to be quilted alone");
    let swatch_edge_mm = swatch.elements.iter().map(longest_edge_mm).fold(0.0, f64::max);
    let quilt = quilt_surface(
        &swatch,
        &cylinder,
        &GuidanceField::around_axis(&cylinder),
        &Settings::default(),
        &Control::default(),
    )
    .unwrap();
    // Elements round the foot are cut at the floor after quilting (see
    // `trim_below`); the rim is what is checked here.
    let by_rim = |e: &&Element| e.vertices.iter().any(|v| v.z > top_z - 3.0);
    let mut on_top = 0;
    let mut under_rim = 0;
    for (k, e) in quilt.elements.iter().filter(by_rim).enumerate() {
        assert!(closed(e), "element {k} by the rim is open");
        assert!(!crosses_itself(e), "element {k} by the rim passes through itself");
        let stretch = longest_edge_mm(e) / swatch_edge_mm;
        assert!(stretch <= 1.75, "element {k} by the rim has an edge {stretch:.2} times the swatch's longest");
        let centre = e.vertices.iter().copied().sum::<DVec3>() / e.vertices.len() as f64;
        if centre.z > top_z - 0.5 {
            on_top += 1;
        } else if centre.truncate().length() > 20.0 {
            under_rim += 1;
        }
    }
    assert!(on_top >= 8 && under_rim >= 12, "{on_top} scales on the top and {under_rim} under its rim");
}

/// Rivets on the cone, whose top (24 mm across) is narrower than the
/// swatch's diagonal: a rivet laid over the rim would fold round it. Left
/// out, such rivets left the side bare for a band under the rim (53 % of
/// it farther than 1.5 mm from any rivet, against 33 % over the whole
/// cone); moved off the rim in the patch's flat frame, they fill it (37 %).
/// Measured on the base's faces, not by what the quilting counted.
#[test]
fn rivets_by_a_rim_move_off_it_rather_than_leave_it_bare() {
    let cone = SurfaceMesh::new(builtin_base("cone").unwrap()).unwrap();
    let top_z = cone.positions().iter().map(|p| p.z).fold(f64::MIN, f64::max);
    let swatch = builtin_swatch("rivets").unwrap();
    let quilt =
        quilt_surface(&swatch, &cone, &GuidanceField::around_axis(&cone), &Settings::default(), &Control::default())
            .unwrap();
    assert!(quilt.elements.iter().all(closed));
    assert!(quilt.elements.iter().all(|e| !crosses_itself(e)));
    // The side within 10 mm of the top.
    let bare =
        quilt_support::bare_share_where(&cone, &quilt.elements, 1.5, |n, c| n.z.abs() < 0.9 && c.z > top_z - 10.0);
    assert!(bare < 0.45, "{:.0} % of the side under the rim is bare", bare * 100.0);
}
