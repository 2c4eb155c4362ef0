//! A quilt too sparse for its model says so: the warning is checked
//! against the model's bare area, measured here apart from the code under
//! test.

mod quilt_support;

use quilt_support::{bare_share_of_faces, turned};
use tracery_core::control::Control;
use tracery_core::mesh_quilt::{Element, GuidanceField, Settings, builtin_swatch, make_surface_product};
use tracery_core::report::Warning;

/// A post 8 mm across: the weave at scale 1 (25 mm wide) is far larger
/// than its curve, and at scale 0.3 (7.5 mm) it is not. Before, both
/// quilts were made without a word, though at scale 1 92 % of the post
/// lay more than 1 mm from any thread (1.4 % at scale 0.3).
#[test]
fn a_weave_too_large_for_a_thin_post_warns_and_a_small_one_does_not() {
    let post = turned(&[(4.0, 0.0), (4.0, 40.0), (0.0, 40.0)]);
    for scale in [1.0, 0.3] {
        let mut settings = Settings::default();
        settings.scale = scale;
        let swatch = builtin_swatch("weave").unwrap();
        let product =
            make_surface_product(&swatch, &post, &GuidanceField::around_axis(&post), &settings, &Control::default())
                .unwrap();
        let mesh = product.mesh_mm.as_ref().unwrap();
        let element = Element {
            vertices: mesh.vertices.iter().map(|v| glam::DVec3::from_array(*v)).collect(),
            triangles: mesh.triangles.clone(),
        };
        let bare = bare_share_of_faces(&post, &[element], 1.0);
        let warned = product.warnings.iter().any(|w| matches!(w, Warning::QuiltSparse { .. }));
        println!("scale {scale}: bare {bare:.3} at 1 mm, warned {warned}");
        if scale == 1.0 {
            assert!(bare > 0.5 && warned, "scale 1: {:.0} % bare, warned: {warned}", bare * 100.0);
        } else {
            assert!(bare < 0.1 && !warned, "scale {scale}: {:.0} % bare, {:?}", bare * 100.0, product.warnings);
        }
    }
}
