//! Jump rings, checked on the final geometry: the ring's hole and wall are
//! measured by probing the region, the piece stays one body, and the solid
//! is watertight.

use tracery_core::DVec2;
use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::geom::count_topology;
use tracery_core::print::{JumpRingError, JumpRings, PrintSettings, RingAt, add_jump_rings};
use tracery_core::vector_brush::{Settings, builtin, make_product};

fn product(exemplar: &str, along: &str) -> Product {
    make_product(&builtin(exemplar).unwrap(), &Along::parse(along).unwrap(), &Settings::default(), &Control::default())
        .unwrap()
}

/// Centres of the small holes (under 10 mm²): a jump ring's hole among them.
fn ring_centres(product: &Product) -> Vec<DVec2> {
    product
        .region_mm
        .polygons
        .iter()
        .flat_map(|p| p.holes.iter())
        .filter(|h| tracery_core::geom::signed_area(h).abs() < 10.0)
        .map(|h| h.iter().copied().sum::<DVec2>() / h.len() as f64)
        .collect()
}

/// Along a ray from `centre`: where material starts and how far it goes on.
fn probe(product: &Product, centre: DVec2, angle: f64) -> (f64, f64) {
    let dir = DVec2::from_angle(angle);
    let step = 0.005;
    let mut r = 0.0;
    while !product.region_mm.contains(centre + dir * r) {
        r += step;
        assert!(r < 10.0, "no material around the ring's centre");
    }
    let start = r;
    while product.region_mm.contains(centre + dir * r) && r < start + 10.0 {
        r += step;
    }
    (start, r - start)
}

fn assert_sound(product: &Product) {
    let mesh = product.mesh_mm.as_ref().unwrap();
    mesh.sanity_check().expect("watertight and manifold");
    assert_eq!(mesh.shell_count(), product.topology.components);
}

#[test]
fn a_pendant_gets_a_ring_at_its_top_that_prints_and_hangs_it_in_one_piece() {
    let pendant = product("chain", "circle:12");
    let rings = JumpRings::at(vec![RingAt::Top]);
    let done = add_jump_rings(pendant.clone(), &rings).unwrap();
    let counted = count_topology(&done.region_mm);
    assert_eq!(counted.components, 1);
    assert_eq!(counted.holes, count_topology(&pendant.region_mm).holes + 1, "one new hole: the ring's");
    assert_eq!((done.topology.jump_rings, done.topology.holes), (1, pendant.topology.holes));
    assert_sound(&done);
    // The ring's hole sits above the pattern, with the asked diameter and wall all around.
    let top = pendant.region_mm.bounds().unwrap().max.y;
    let centres: Vec<DVec2> = ring_centres(&done).into_iter().filter(|c| c.y > top).collect();
    assert_eq!(centres.len(), 1, "{centres:?}");
    for k in 0..12 {
        let (hole_radius, wall) = probe(&done, centres[0], k as f64 / 12.0 * std::f64::consts::TAU);
        assert!((hole_radius - 0.5 * rings.hole_mm).abs() < 0.02, "hole radius {hole_radius}");
        assert!(wall >= rings.wall_mm - 0.02, "wall {wall} at {k}");
    }
}

#[test]
fn an_earring_gets_rings_at_both_ends() {
    let earring = product("vine", "line:50");
    let done = add_jump_rings(earring.clone(), &JumpRings::at(vec![RingAt::Start, RingAt::End])).unwrap();
    assert_eq!(done.topology.components, 1);
    assert_eq!(done.topology.jump_rings, 2);
    assert_sound(&done);
    let (lo, hi) = (earring.region_mm.bounds().unwrap(), done.region_mm.bounds().unwrap());
    assert!(hi.min.x < lo.min.x - 2.0 && hi.max.x > lo.max.x + 2.0, "rings beyond both ends");
}

#[test]
fn a_ring_far_from_the_pattern_is_joined_by_a_stem() {
    let piece = product("lace", "line:40");
    let bounds = piece.region_mm.bounds().unwrap();
    let far = DVec2::new(bounds.center().x, bounds.max.y + 8.0);
    let done = add_jump_rings(piece, &JumpRings::at(vec![RingAt::Point { x_mm: far.x, y_mm: far.y }])).unwrap();
    assert_eq!(done.topology.components, 1, "the stem joins the ring to the lace");
    assert_sound(&done);
}

#[test]
fn rings_that_would_not_print_or_have_nowhere_to_go_are_refused() {
    let print = PrintSettings::default();
    let tiny_hole = JumpRings { hole_mm: 0.3, ..JumpRings::at(vec![RingAt::Top]) };
    assert!(matches!(tiny_hole.validate(&print), Err(JumpRingError::HoleTooSmall { .. })));
    let thin_wall = JumpRings { wall_mm: 0.2, ..JumpRings::at(vec![RingAt::Top]) };
    assert!(matches!(thin_wall.validate(&print), Err(JumpRingError::WallTooThin { .. })));
    let bracelet = product("lace", "circle:25");
    let ends = add_jump_rings(bracelet, &JumpRings::at(vec![RingAt::End]));
    assert!(matches!(ends, Err(JumpRingError::NoEnds)));
}
