//! Chain mail over a model, as printed: its flat rings float over the model
//! by design, held up by the standing links through them, and the links
//! of each patch line up with the links already there. Counted on the
//! product's mesh, split into bodies here, apart from the code under test.

mod quilt_support;

use glam::DVec3;
use quilt_support::{bodies, turned};
use tracery_core::control::Control;
use tracery_core::mesh::Mesh;
use tracery_core::mesh_quilt::{GuidanceField, Settings, Swatch, builtin_swatch, make_surface_product};
use tracery_core::surface::{SurfaceMesh, builtin_base};

/// `swatch` quilted over `base` along its parallels with `settings`, as
/// printed: the product's mesh.
fn printed(swatch: &Swatch, base: &SurfaceMesh, settings: &Settings) -> Mesh {
    let product =
        make_surface_product(swatch, base, &GuidanceField::around_axis(base), settings, &Control::default()).unwrap();
    product.mesh_mm.unwrap()
}

/// A disk 80 mm across and 6 mm thick: its top is flat and wider than the
/// chain mail's diagonal, so it is quilted as a plane is, through the
/// curved bases' patches and shell.
///
/// Chain mail tiled without end has one flat ring to two standing links.
/// Before, every flat ring was left out of the print as resting nowhere on
/// the model (0 flat rings to 48 standing links over the middle); and
/// patches placed their links up to half a grid cell (1.7 mm) off the
/// links already there, so that many crossed them and were left out,
/// flat rings most (0.34 flat rings to a standing link; 0.26 to 0.39 over
/// seeds 1 to 5). Now 23 to 48 (0.38 to 0.48 over seeds 1 to 5), and the
/// middle holds as many links as the swatch's density gives (71 of 72).
#[test]
fn chain_mail_over_a_model_keeps_its_flat_rings_and_its_density() {
    let disk = turned(&[(40.0, 0.0), (40.0, 6.0), (0.0, 6.0)]);
    let swatch = builtin_swatch("chainmail").unwrap();
    let size = swatch.size_mm();
    let mesh = &printed(&swatch, &disk, &Settings::default());
    // Bodies over the middle of the top, clear of the rim.
    let (mut flat, mut standing) = (0, 0);
    for body in bodies(mesh) {
        let centre = body.iter().copied().sum::<DVec3>() / body.len() as f64;
        if centre.truncate().length() > 30.0 || centre.z < 6.0 {
            continue;
        }
        let (low, high) = body.iter().fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v.z), hi.max(v.z)));
        if high - low < 0.5 * size.z {
            flat += 1;
        } else {
            standing += 1;
        }
    }
    let expected = swatch.elements.len() as f64 * std::f64::consts::PI * 30.0 * 30.0 / (size.x * size.y);
    assert!(flat as f64 >= 0.4 * standing as f64, "{flat} flat rings to {standing} standing links");
    let links = (flat + standing) as f64;
    assert!(links >= 0.85 * expected, "{links} links over the middle, of about {expected:.0}");
}

/// Whether a vertex of one of `bodies` lies in the opening of the flat
/// ring `ring` (lying in the plane of the disk's top): within its inner
/// radius of its centre across the top, and between its lowest and
/// highest points.
fn passes_through(ring: &[DVec3], bodies: &[&Vec<DVec3>]) -> bool {
    let centre = ring.iter().copied().sum::<DVec3>() / ring.len() as f64;
    let inner_mm = ring.iter().map(|v| (*v - centre).truncate().length()).fold(f64::MAX, f64::min);
    let (low, high) = ring.iter().fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v.z), hi.max(v.z)));
    bodies
        .iter()
        .flat_map(|b| b.iter())
        .any(|v| (*v - centre).truncate().length() < inner_mm && (low..=high).contains(&v.z))
}

/// A flat ring floats over the model and prints loose unless a link that
/// rests on the model passes through it. Rings were kept when they came
/// near a resting link; one of seed 2's 27 over the top had none through
/// it (by the rim, 3.3 mm over the top). Now a ring is kept only when one
/// passes through it, found by the library as an edge crossing its
/// opening, and here as a vertex inside it.
#[test]
fn every_flat_ring_over_a_model_hangs_on_a_link_through_it() {
    let disk = turned(&[(40.0, 0.0), (40.0, 6.0), (0.0, 6.0)]);
    let swatch = builtin_swatch("chainmail").unwrap();
    for seed in 1..=3 {
        let mut settings = Settings::default();
        settings.seed = seed;
        let all = bodies(&printed(&swatch, &disk, &settings));
        // Over the top, clear of the rim; resting bodies sink into it.
        let over_top: Vec<&Vec<DVec3>> =
            all.iter().filter(|b| b.iter().all(|v| v.truncate().length() < 39.5 && v.z > 3.0)).collect();
        let (floating, resting): (Vec<&Vec<DVec3>>, Vec<&Vec<DVec3>>) =
            over_top.iter().partition(|b| b.iter().all(|v| v.z > 6.0));
        let loose = floating.iter().filter(|ring| !passes_through(ring, &resting)).count();
        assert!(!floating.is_empty());
        assert_eq!(loose, 0, "seed {seed}: {loose} of {} flat rings have no link through them", floating.len());
    }
}

/// Chain mail over the built-in cylinder (25 mm across, its top at
/// 60 mm), printed once for the tests that count its lattice.
fn chain_mail_cylinder() -> &'static Mesh {
    static PRINT: std::sync::OnceLock<Mesh> = std::sync::OnceLock::new();
    PRINT.get_or_init(|| {
        let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
        printed(&builtin_swatch("chainmail").unwrap(), &cylinder, &Settings::default())
    })
}

/// A cylinder whose top is narrower than the chain mail's diagonal: the
/// top is no cap of its own, and patches grown from the side ran over the
/// rim onto it. Laid flat, such a patch bent the side's lattice by up to
/// four times in area, and the next patch's links met the last's a few
/// millimetres off, crossed them and were left out: a scatter of standing
/// links with few flat rings between them. Patches of chain mail now keep
/// to their side of a crease. Counted on the print's bodies over the
/// side's middle, apart from the code under test: in chain mail each
/// standing link passes through two flat rings; before, 74 of 132 did
/// (56 %); now 130 of 132.
#[test]
fn chain_mail_round_a_cylinder_keeps_its_lattice_past_the_rim() {
    let swatch = builtin_swatch("chainmail").unwrap();
    let mesh = chain_mail_cylinder();
    let radial = |v: &DVec3| v.truncate().length();
    let (mut flat, mut standing): (Vec<Vec<DVec3>>, Vec<Vec<DVec3>>) = (Vec::new(), Vec::new());
    for body in bodies(mesh) {
        let centre = body.iter().copied().sum::<DVec3>() / body.len() as f64;
        if !(8.0..52.0).contains(&centre.z) {
            continue;
        }
        let (low, high) = body.iter().map(radial).fold((f64::MAX, f64::MIN), |(lo, hi), r| (lo.min(r), hi.max(r)));
        if high - low < 0.5 * swatch.size_mm().z { flat.push(body) } else { standing.push(body) }
    }
    // A vertex in a flat ring's opening: nearer its centre along the side
    // than its inner radius, and within its span out from the axis.
    let through = |link: &[DVec3], ring: &[DVec3]| {
        let centre = ring.iter().copied().sum::<DVec3>() / ring.len() as f64;
        let out = centre.truncate().normalize().extend(0.0);
        let across = |v: DVec3| (v - centre) - (v - centre).dot(out) * out;
        let inner_mm = ring.iter().map(|v| across(*v).length()).fold(f64::MAX, f64::min);
        let (low, high) = ring.iter().map(radial).fold((f64::MAX, f64::MIN), |(lo, hi), r| (lo.min(r), hi.max(r)));
        link.iter().any(|v| across(*v).length() < inner_mm && (low..=high).contains(&radial(v)))
    };
    let linked = standing.iter().filter(|l| flat.iter().filter(|r| through(l, r)).count() >= 2).count();
    let share = linked as f64 / standing.len().max(1) as f64;
    println!("{linked} of {} standing links through two flat rings ({} flat rings)", standing.len(), flat.len());
    assert!(standing.len() >= 40, "{} standing links over the side's middle", standing.len());
    assert!(share >= 0.8, "{linked} of {} standing links pass through two flat rings", standing.len());
}

/// The same cylinder's top, 50 mm across, is narrower than the chain
/// mail's diagonal (56 mm). Its rows went round the axis there, as on a
/// top too narrow for rows to lie straight, so each patch on it was turned
/// from the last and the top was a heap of rings: 3 of 10 standing links
/// over its middle passed through two flat rings. Chain mail's rows now lie
/// straight across a top of any width, its patches keeping to it: 15 of 16.
/// Counted as over the disk's top, a vertex in a flat ring's opening.
#[test]
fn chain_mail_on_a_top_narrower_than_the_swatch_is_a_lattice() {
    let swatch = builtin_swatch("chainmail").unwrap();
    let all = bodies(chain_mail_cylinder());
    let over_top: Vec<&Vec<DVec3>> =
        all.iter().filter(|b| b.iter().all(|v| v.truncate().length() < 25.0 && v.z > 57.0)).collect();
    let (flat, standing): (Vec<&Vec<DVec3>>, Vec<&Vec<DVec3>>) = over_top.iter().partition(|b| {
        let (low, high) = b.iter().fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v.z), hi.max(v.z)));
        high - low < 0.5 * swatch.size_mm().z
    });
    // Standing links clear of the rim, where a lattice has a ring each side.
    let middle: Vec<&Vec<DVec3>> = standing
        .into_iter()
        .filter(|l| (l.iter().copied().sum::<DVec3>() / l.len() as f64).truncate().length() < 15.0)
        .collect();
    let linked = middle.iter().filter(|l| flat.iter().filter(|r| passes_through(r, &[l])).count() >= 2).count();
    println!("{linked} of {} standing links over the top's middle through two flat rings", middle.len());
    assert!(middle.len() >= 6, "{} standing links over the top's middle", middle.len());
    assert!(linked as f64 >= 0.8 * middle.len() as f64, "{linked} of {} pass through two flat rings", middle.len());
}
