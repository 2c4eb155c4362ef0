//! The gallery's alternatives: all meet the targets (counted on the final
//! geometry), differ substantially by a measure the solver does not
//! optimize, and each can be made again on its own.

use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::count_topology;
use tracery_core::product::Fact;
use tracery_core::quality::distinctness;
use tracery_core::vector_brush::{ALTERNATIVES, Settings, builtin, make_alternatives, make_product};

fn shapes(p: &Product) -> Vec<(usize, f64)> {
    match p.facts.get("shape_sequence") {
        Some(Fact::Indices(v)) => v.iter().map(|&c| (c, 1.0)).collect(),
        _ => panic!("no shape sequence"),
    }
}

#[test]
fn alternatives_meet_the_targets_and_differ_over_a_quarter_of_their_length() {
    for (exemplar, curve) in [
        ("lace", "line:150"),
        ("vine", "wave:150"),
        ("braid", "line:150"),
        ("lace", "circle:30"),
        ("vine", "circle:30"),
    ] {
        let along = Along::parse(curve).unwrap();
        let closed = curve.starts_with("circle");
        let all = make_alternatives(
            &builtin(exemplar).unwrap(),
            &along,
            &Settings::default(),
            ALTERNATIVES,
            &Control::default(),
        )
        .unwrap();
        assert_eq!(all.len(), ALTERNATIVES as usize);
        for (k, p) in all.iter().enumerate() {
            let counted = count_topology(&p.region_mm);
            assert_eq!(counted.components, 1, "{exemplar} {curve} #{k}");
            assert_eq!(p.mesh_mm.as_ref().unwrap().shell_count(), 1, "{exemplar} {curve} #{k}");
        }
        let mut least = f64::INFINITY;
        for i in 0..all.len() {
            for j in i + 1..all.len() {
                least = least.min(distinctness(&shapes(&all[i]), &shapes(&all[j]), closed));
            }
        }
        assert!(least >= 0.25, "{exemplar} {curve}: two alternatives differ over only {:.0}%", 100.0 * least);
    }
}

#[test]
fn each_alternative_is_made_again_alone_with_its_setting() {
    let along = Along::parse("wave:120").unwrap();
    let exemplar = builtin("vine").unwrap();
    let all = make_alternatives(&exemplar, &along, &Settings::default(), 4, &Control::default()).unwrap();
    for (k, expected) in all.iter().enumerate() {
        let mut settings = Settings::default();
        settings.alternative = k as u32;
        let alone = make_product(&exemplar, &along, &settings, &Control::default()).unwrap();
        assert_eq!(alone.facts.get("piece_sequence"), expected.facts.get("piece_sequence"), "alternative {k}");
    }
    let mut settings = Settings::default();
    settings.alternative = ALTERNATIVES;
    assert!(settings.validate().is_err());
}
