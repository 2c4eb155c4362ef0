//! Printability on crafted geometry whose flaws are known: a 0.2 mm neck and
//! a 0.3 mm slot, found at their places with their widths, and nothing else;
//! thickening that fixes the neck without changing the topology; bridges on
//! seams; and thickened built-in patterns that still mesh as planned.

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::{FillRule, Region, count_topology, resolve_contours};
use tracery_core::print::{PrintSettings, check, finish, thicken};
use tracery_core::vector_brush::{BUILTIN_NAMES, Settings, builtin, make_product};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<DVec2> {
    vec![DVec2::new(x0, y0), DVec2::new(x1, y0), DVec2::new(x1, y1), DVec2::new(x0, y1)]
}

/// Two 4 mm blocks joined by a 0.2 mm × 1.5 mm neck (x 4 to 5.5, y 1.9 to
/// 2.1); the right block has a 0.3 mm slot, 2.5 mm deep, from its top
/// (x 7.35 to 7.65).
fn crafted() -> Region {
    let parts = resolve_contours(
        &[rect(0.0, 0.0, 4.0, 4.0), rect(3.9, 1.9, 5.6, 2.1), rect(5.5, 0.0, 9.5, 4.0)],
        FillRule::NonZero,
    );
    let slot = resolve_contours(&[rect(7.35, 1.5, 7.65, 4.5)], FillRule::NonZero);
    tracery_core::geom::difference(&parts, &slot)
}

/// Material along the vertical line at `x`, mm (an independent width probe).
fn material_across(region: &Region, x: f64, y0: f64, y1: f64) -> f64 {
    let steps = 4000;
    let dy = (y1 - y0) / steps as f64;
    (0..steps).filter(|k| region.contains(DVec2::new(x, y0 + (*k as f64 + 0.5) * dy))).count() as f64 * dy
}

#[test]
fn a_known_neck_and_slot_are_found_where_they_are_and_nothing_else() {
    let region = crafted();
    assert_eq!(count_topology(&region).components, 1);
    let found = check(&region, &[], &PrintSettings::default(), 2.0);

    assert_eq!(found.thin_features.len(), 1, "{:?}", found.thin_features);
    let neck = &found.thin_features[0];
    assert!((neck.width_mm - 0.2).abs() < 0.005, "neck {} mm", neck.width_mm);
    assert!((4.0..5.5).contains(&neck.at_mm.x) && (1.9..2.1).contains(&neck.at_mm.y), "neck at {}", neck.at_mm);
    assert_eq!(found.thinnest_feature_mm, Some(neck.width_mm));

    assert_eq!(found.narrow_gaps.len(), 1, "{:?}", found.narrow_gaps);
    let slot = &found.narrow_gaps[0];
    assert!((slot.width_mm - 0.3).abs() < 0.005, "slot {} mm", slot.width_mm);
    assert!((7.35..7.65).contains(&slot.at_mm.x) && (1.5..4.0).contains(&slot.at_mm.y), "slot at {}", slot.at_mm);
    assert_eq!(found.narrowest_gap_mm, Some(slot.width_mm));

    // A finer nozzle prints both.
    let fine = check(&region, &[], &PrintSettings::default().with_nozzle_mm(0.15), 2.0);
    assert!(fine.thin_features.is_empty() && fine.narrow_gaps.is_empty());
    // The blocks' square corners are not thin features.
    let blocks = resolve_contours(&[rect(0.0, 0.0, 4.0, 4.0)], FillRule::NonZero);
    let plain = check(&blocks, &[], &PrintSettings::default(), 2.0);
    assert!(plain.thin_features.is_empty() && plain.narrow_gaps.is_empty());
}

#[test]
fn thickening_widens_the_neck_to_the_nozzle_and_keeps_one_piece() {
    let region = crafted();
    let settings = PrintSettings::default();
    let found = check(&region, &[], &settings, 2.0);
    let thick = thicken(&region, &found.thin_features, settings.min_width_mm());
    assert_eq!(count_topology(&thick), count_topology(&region), "same components and holes");
    for x in [4.2, 4.75, 5.3] {
        let before = material_across(&region, x, 1.0, 3.0);
        let after = material_across(&thick, x, 1.0, 3.0);
        assert!((before - 0.2).abs() < 0.01, "{before}");
        assert!((0.399..0.5).contains(&after), "neck at x = {x} is {after} mm after thickening");
    }
    // The slot is a gap, not a feature: thickening leaves it open.
    assert!(material_across(&thick, 7.5, 2.0, 3.9) < 0.01);
    assert!(check(&thick, &[], &settings, 2.0).thin_features.is_empty());
}

#[test]
fn a_seam_across_the_neck_is_a_weak_bridge_and_one_across_a_block_is_not() {
    let region = crafted();
    let seams = [[DVec2::new(4.7, -1.0), DVec2::new(4.7, 5.0)], [DVec2::new(2.0, -1.0), DVec2::new(2.0, 5.0)]];
    let found = check(&region, &seams, &PrintSettings::default(), 2.0);
    assert_eq!(found.weak_bridges.len(), 1);
    let b = &found.weak_bridges[0];
    assert!((b.width_mm - 0.2).abs() < 1e-6 && (b.at_mm - DVec2::new(4.7, 2.0)).length() < 1e-6, "{b:?}");
}

#[test]
fn too_few_layers_and_flaws_are_reported_as_warnings() {
    let along = Along::parse("line:60").unwrap();
    let mut settings = Settings::default();
    settings.thickness_mm = 0.4;
    let product = make_product(&builtin("meander").unwrap(), &along, &settings, &Control::default()).unwrap();
    let checked = finish(product, &PrintSettings::default());
    let text: Vec<String> = checked.warnings.iter().map(|w| w.to_string()).collect();
    assert!(text.iter().any(|w| w.contains("2.0 layers")), "{text:?}");
}

#[test]
fn thickened_builtin_patterns_mesh_with_the_topology_counted() {
    let along = Along::parse("circle:20").unwrap();
    for name in BUILTIN_NAMES {
        let Ok(product) = make_product(&builtin(name).unwrap(), &along, &Settings::default(), &Control::default())
        else {
            continue;
        };
        // A coarse nozzle, so that every exemplar has something to thicken.
        let settings = PrintSettings::default().with_nozzle_mm(0.8).with_thicken(true);
        let done = finish(product, &settings);
        let found = done.printability.as_ref().unwrap();
        assert!(found.thickened || found.thin_features.is_empty());
        assert!(found.thin_features.is_empty(), "{name}: thin features left after thickening");
        let mesh = done.mesh_mm.as_ref().unwrap();
        mesh.sanity_check().unwrap_or_else(|e| panic!("{name}: {e}"));
        let counted = count_topology(&done.region_mm);
        assert_eq!(mesh.shell_count(), counted.components, "{name}");
        assert_eq!(done.topology.components, counted.components, "{name}");
        assert_eq!(done.topology.holes + done.topology.loop_openings, counted.holes, "{name}");
    }
}

#[test]
fn bridges_on_real_seams_are_material_and_add_up_to_what_a_probe_measures() {
    let along = Along::parse("circle:25").unwrap();
    for name in ["lace", "braid", "filigree"] {
        let product = make_product(&builtin(name).unwrap(), &along, &Settings::default(), &Control::default()).unwrap();
        let region = &product.region_mm;
        // A limit no bridge reaches: every bridge is listed.
        let mut settings = PrintSettings::default().with_nozzle_mm(3.0);
        settings.bridge_nozzles = 20.0;
        let found = check(region, &product.overlays.seams_mm, &settings, 2.0);
        assert!(!found.weak_bridges.is_empty());
        for b in &found.weak_bridges {
            assert!(region.contains(b.at_mm), "{name}: bridge at {} ({} mm) is not material", b.at_mm, b.width_mm);
        }
        // Per seam, the bridges' total equals the material a fine probe finds.
        let listed: f64 = found.weak_bridges.iter().map(|b| b.width_mm).sum();
        let probed: f64 = product
            .overlays
            .seams_mm
            .iter()
            .map(|[a, b]| {
                let steps = 2000;
                let inside =
                    (0..steps).filter(|k| region.contains(a.lerp(*b, (*k as f64 + 0.5) / steps as f64))).count();
                a.distance(*b) * inside as f64 / steps as f64
            })
            .sum();
        assert!((listed - probed).abs() < 0.01 * probed, "{name}: bridges {listed} mm, probe {probed} mm");
    }
}
