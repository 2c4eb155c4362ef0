//! Combining parts into one object: pockets of air the parts seal between
//! them are filled, and a carved object keeps its hollow. Shells and
//! volumes are counted here, by the tests' own walk over shared edges.

use std::collections::HashMap;

use glam::{DVec2, DVec3};
use tracery_core::geom::{Polygon, Region};
use tracery_core::mesh::{Mesh, extrude};
use tracery_core::surface::{Part, PartRole, SurfaceMesh, assemble, builtin_base};

/// Each shell's signed volume (mm³), shells found by joining triangles
/// that share an edge.
fn shell_volumes(mesh: &Mesh) -> Vec<f64> {
    let mut shell: Vec<usize> = (0..mesh.triangles.len()).collect();
    fn root(shell: &mut [usize], mut t: usize) -> usize {
        while shell[t] != t {
            t = shell[t];
        }
        t
    }
    let mut first: HashMap<(u32, u32), usize> = HashMap::new();
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            match first.get(&(a.min(b), a.max(b))) {
                Some(&other) => {
                    let (x, y) = (root(&mut shell, t), root(&mut shell, other));
                    shell[x] = y;
                }
                None => {
                    first.insert((a.min(b), a.max(b)), t);
                }
            }
        }
    }
    let mut volumes: HashMap<usize, f64> = HashMap::new();
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let [a, b, c] = tri.map(|v| DVec3::from_array(mesh.vertices[v as usize]));
        *volumes.entry(root(&mut shell, t)).or_default() += a.dot(b.cross(c)) / 6.0;
    }
    volumes.into_values().collect()
}

fn square(x: f64, side: f64) -> Vec<DVec2> {
    vec![DVec2::new(x, x), DVec2::new(x + side, x), DVec2::new(x + side, x + side), DVec2::new(x, x + side)]
}

/// `region` from `z0_mm` to `z1_mm`.
fn slab(region: &Region, z0_mm: f64, z1_mm: f64) -> Mesh {
    let mut mesh = extrude(region, z1_mm - z0_mm).unwrap();
    mesh.vertices.iter_mut().for_each(|v| v[2] += z0_mm);
    mesh
}

#[test]
fn a_pocket_sealed_between_parts_is_filled_and_the_object_is_one_body() {
    // A floor, a square frame standing on it and a lid on the frame: a
    // closed box with 6 × 6 × 2 mm of air inside.
    let plate = Region::new(vec![Polygon { outer: square(0.0, 10.0), holes: vec![] }]);
    let mut window = square(2.0, 6.0);
    window.reverse();
    let frame = Region::new(vec![Polygon { outer: square(0.0, 10.0), holes: vec![window] }]);
    let (floor, walls, lid) = (slab(&plate, 0.0, 2.0), slab(&frame, 1.0, 5.0), slab(&plate, 4.0, 6.0));
    let parts: Vec<Part> = [&floor, &walls, &lid].iter().map(|m| Part { solid_mm: m, role: PartRole::Add }).collect();
    let object = assemble(None, false, &parts, &mut Default::default()).unwrap();
    assert!(object.mesh_mm.sanity_check().is_ok());
    let volumes = shell_volumes(&object.mesh_mm);
    assert_eq!(volumes.len(), 1, "one shell, facing out: {volumes:?}");
    assert_eq!((object.bodies, object.cavities), (1, 1));
    // The whole box, the pocket included: 10 × 10 × 6 mm.
    assert!((volumes[0] - 600.0).abs() < 1e-6, "{volumes:?}");
}

#[test]
fn a_carved_object_keeps_its_hollow() {
    // A cut that misses the egg leaves it hollowed and sealed: the hollow's
    // wall is a shell of its own, facing in, and stays.
    let egg = SurfaceMesh::new(builtin_base("egg").unwrap()).unwrap();
    let far = slab(&Region::new(vec![Polygon { outer: square(200.0, 5.0), holes: vec![] }]), 0.0, 5.0);
    let part = Part { solid_mm: &far, role: PartRole::Carve { wall_mm: 2.0 } };
    let object = assemble(Some(&egg), false, &[part], &mut Default::default()).unwrap();
    let mut volumes = shell_volumes(&object.mesh_mm);
    volumes.sort_by(f64::total_cmp);
    assert_eq!(volumes.len(), 2, "{volumes:?}");
    assert!(volumes[0] < 0.0 && volumes[1] > 0.0, "the hollow's wall faces in: {volumes:?}");
    assert_eq!(object.cavities, 0);
    assert!((volumes[0] + volumes[1]) < 0.5 * egg.mesh().signed_volume(), "the egg is a shell: {volumes:?}");
}
