//! Quilting models as CAD programs export them: a few long triangles (a
//! box has 12, a flat plate 2), and sheets open at their edges. Counted on
//! the product's mesh, split into bodies here, apart from the code under
//! test.

mod quilt_support;

use glam::DVec3;
use quilt_support::bodies;
use tracery_core::control::Control;
use tracery_core::mesh::Mesh;
use tracery_core::mesh_quilt::{GuidanceField, Settings, builtin_swatch, make_surface_product, unite_with_base};
use tracery_core::surface::SurfaceMesh;

/// A box `side_mm` on a side as 12 triangles looking out, its corner at
/// the origin.
fn box_of(side_mm: f64) -> Mesh {
    let corners =
        (0..8).map(|k| [side_mm * (k & 1) as f64, side_mm * ((k >> 1) & 1) as f64, side_mm * (k >> 2) as f64]);
    Mesh {
        vertices: corners.collect(),
        triangles: vec![
            [0, 2, 3],
            [0, 3, 1],
            [4, 5, 7],
            [4, 7, 6],
            [0, 1, 5],
            [0, 5, 4],
            [2, 6, 7],
            [2, 7, 3],
            [0, 4, 6],
            [0, 6, 2],
            [1, 3, 7],
            [1, 7, 5],
        ],
    }
}

/// Chain mail quilted over `mesh` round the `z` axis, as printed.
fn chain_mail_over(mesh: Mesh) -> Mesh {
    let base = SurfaceMesh::new(mesh).unwrap();
    let swatch = builtin_swatch("chainmail").unwrap();
    let field = GuidanceField::around_axis(&base);
    let product = make_surface_product(&swatch, &base, &field, &Settings::default(), &Control::default()).unwrap();
    product.mesh_mm.unwrap()
}

/// A plate 60 mm square as two triangles, lying on the bed and looking up,
/// open at its edges. Before, its chain mail was cut away whole where the
/// plate stands, for it all sank below the plate's lowest level: an empty
/// print, reported as made. With that mended, patches grown face by face
/// over two faces laid two blocks of chain mail along the diagonal, and
/// the plate's quarters held 10, 21, 15 and 4 links of the 23 or so the
/// swatch's density gives. Faces are now split before quilting: 21, 21,
/// 21 and 22.
#[test]
fn chain_mail_over_a_plate_of_two_triangles_covers_it() {
    let plate = Mesh {
        vertices: vec![[0.0, 0.0, 0.0], [60.0, 0.0, 0.0], [60.0, 60.0, 0.0], [0.0, 60.0, 0.0]],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
    };
    let swatch = builtin_swatch("chainmail").unwrap();
    let size = swatch.size_mm();
    let all = bodies(&chain_mail_over(plate));
    // Links by the quarter of the plate their middle lies over.
    let mut quarters = [0usize; 4];
    for b in &all {
        let centre = b.iter().copied().sum::<DVec3>() / b.len() as f64;
        if (0.0..60.0).contains(&centre.x) && (0.0..60.0).contains(&centre.y) {
            quarters[usize::from(centre.x >= 30.0) + 2 * usize::from(centre.y >= 30.0)] += 1;
        }
    }
    let expected = swatch.elements.len() as f64 * 30.0 * 30.0 / (size.x * size.y);
    println!("links over the plate's quarters: {quarters:?}, of about {expected:.0} each");
    let least = *quarters.iter().min().unwrap();
    assert!(
        least as f64 >= 0.7 * expected,
        "links over the plate's quarters: {quarters:?}, of about {expected:.0} each"
    );
}

/// A box 60 mm on a side as 12 triangles, each face two triangles 60 mm
/// across. In chain mail each standing link passes through two flat rings.
/// Over the middle of the box's front 2 of 21 did, a tangle; with faces
/// split to two grid cells (6.7 mm), 12 of 26, the rings by each edge bent
/// into hearts where the shell fans out over the faces along it; with
/// those split into a 2 mm strip as well, 32 of 32.
#[test]
fn chain_mail_over_a_box_of_twelve_triangles_is_a_lattice() {
    let box_mesh = box_of(60.0);
    let depth_mm = builtin_swatch("chainmail").unwrap().size_mm().z;
    let centre = |b: &[DVec3]| b.iter().copied().sum::<DVec3>() / b.len() as f64;
    // Bodies standing out of the front (y = 0).
    let front: Vec<Vec<DVec3>> = bodies(&chain_mail_over(box_mesh)).into_iter().filter(|b| centre(b).y < 0.0).collect();
    let span = |b: &[DVec3]| b.iter().fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v.y), hi.max(v.y)));
    let (flat, standing): (Vec<&Vec<DVec3>>, Vec<&Vec<DVec3>>) = front.iter().partition(|b| {
        let (low, high) = span(b);
        high - low < 0.5 * depth_mm
    });
    // Standing links over the front's middle, with the rings either side.
    let middle = |c: DVec3| (10.0..50.0).contains(&c.x) && (10.0..50.0).contains(&c.z);
    let standing: Vec<&Vec<DVec3>> = standing.into_iter().filter(|l| middle(centre(l))).collect();
    // A vertex in a flat ring's opening: nearer its centre across the
    // front than its inner radius, and within its span out from the front.
    let through = |link: &[DVec3], ring: &[DVec3]| {
        let centre = centre(ring);
        let across = |v: DVec3| (v.x - centre.x).hypot(v.z - centre.z);
        let inner_mm = ring.iter().map(|v| across(*v)).fold(f64::MAX, f64::min);
        let (low, high) = span(ring);
        link.iter().any(|v| across(*v) < inner_mm && (low..=high).contains(&v.y))
    };
    let linked = standing.iter().filter(|l| flat.iter().filter(|r| through(l, r)).count() >= 2).count();
    println!("{linked} of {} standing links over the front's middle through two flat rings", standing.len());
    assert!(standing.len() >= 5, "{} standing links over the front's middle", standing.len());
    assert!(linked as f64 >= 0.8 * standing.len() as f64, "{linked} of {} pass through two flat rings", standing.len());
}

/// Some programs write a closed model with every face looking in. Rivets
/// on such a box were grown inside it, and united with it came out as 97
/// loose bodies and no box. The model is now turned outward when loaded:
/// one body, whose volume is the box's and more (counted on the mesh
/// here).
#[test]
fn rivets_on_a_box_written_inside_out_print_as_one_body_with_it() {
    let mut inside_out = box_of(40.0);
    for t in &mut inside_out.triangles {
        t.swap(1, 2);
    }
    let base = SurfaceMesh::new(inside_out).unwrap();
    let swatch = builtin_swatch("rivets").unwrap();
    let field = GuidanceField::around_axis(&base);
    let texture = make_surface_product(&swatch, &base, &field, &Settings::default(), &Control::default()).unwrap();
    let object = unite_with_base(texture, &base).unwrap();
    let mesh = object.mesh_mm.unwrap();
    let volume_mm3: f64 = mesh
        .triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| DVec3::from_array(mesh.vertices[v as usize]));
            a.dot(b.cross(c)) / 6.0
        })
        .sum();
    assert_eq!(bodies(&mesh).len(), 1);
    assert!(volume_mm3 > 40.0 * 40.0 * 40.0, "{volume_mm3:.0} mm³");
}
