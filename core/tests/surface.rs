//! The shade stage alone: rows laid between the rims, full bands wrapped
//! onto a cylinder and a cone and measured against the solids' formulas,
//! and the edge splitting that bends a flat mesh smoothly.

use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};
use tracery_core::geom::{Polygon, Region};
use tracery_core::mesh::{Mesh, extrude, split_edges};
use tracery_core::surface::{RowPlace, Shade, ShadeSettings, wrap_rows};

/// A full band along a counter-clockwise circle of `radius`, `band` high,
/// as a row made along that circle would be (up is toward the centre).
fn full_row(radius: f64, band: f64) -> Region {
    let n = 720;
    let circle = |r: f64| -> Vec<DVec2> { (0..n).map(|i| DVec2::from_angle(TAU * i as f64 / n as f64) * r).collect() };
    let mut hole = circle(radius - 0.5 * band);
    hole.reverse();
    Region::new(vec![Polygon { outer: circle(radius + 0.5 * band), holes: vec![hole] }])
}

fn volume(mesh: &Mesh) -> f64 {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| DVec3::from_array(mesh.vertices[i as usize]));
            a.dot(b.cross(c)) / 6.0
        })
        .sum()
}

#[test]
fn rows_fill_the_height_between_the_rims_exactly() {
    for (band, rim, overlap, height) in [(10.0, 3.0, 1.0, 80.0), (7.0, 0.0, 0.5, 33.0), (12.0, 5.0, 2.0, 100.0)] {
        let mut settings = ShadeSettings::default();
        settings.shade = Shade::cylinder(40.0, height).unwrap();
        settings.rim_mm = rim;
        settings.row_overlap_mm = overlap;
        let rows = settings.rows(band).unwrap();
        let bottom = rows[0].centre_slant_mm - 0.5 * rows[0].band_mm;
        let last = rows.last().unwrap();
        let top = last.centre_slant_mm + 0.5 * last.band_mm;
        let (want_bottom, want_top) = if rim > 0.0 { (rim - overlap, height - rim + overlap) } else { (0.0, height) };
        assert!((bottom - want_bottom).abs() < 1e-9 && (top - want_top).abs() < 1e-9, "{rows:?}");
        for pair in rows.windows(2) {
            let gap =
                (pair[1].centre_slant_mm - 0.5 * pair[1].band_mm) - (pair[0].centre_slant_mm + 0.5 * pair[0].band_mm);
            assert!((gap + overlap).abs() < 1e-9, "rows overlap by {}", -gap);
        }
        // The band is adjusted by less than half a row.
        assert!((rows[0].band_mm - band).abs() < 0.5 * band, "{rows:?}");
    }
}

#[test]
fn a_full_cylinder_wraps_into_a_tube_of_the_right_volume() {
    let (radius, height, thickness) = (25.0, 30.0, 2.0);
    let mut settings = ShadeSettings::default();
    settings.shade = Shade::cylinder(radius, height).unwrap();
    let rows: Vec<(Region, RowPlace)> =
        settings.rows(10.0).unwrap().into_iter().map(|p| (full_row(p.radius_mm, p.band_mm), p)).collect();
    let wrapped = wrap_rows(&rows, &settings, thickness).unwrap();
    let mesh = &wrapped.mesh_mm;
    assert!(mesh.sanity_check().is_ok(), "{:?}", mesh.sanity_check());
    assert_eq!(mesh.shell_count(), 1);
    assert_eq!((wrapped.topology.components, wrapped.topology.holes, wrapped.topology.loop_openings), (1, 0, 1));
    let tube = PI * ((radius + thickness).powi(2) - radius.powi(2)) * height;
    assert!((volume(mesh) - tube).abs() < 0.002 * tube, "volume {} against {tube}", volume(mesh));
    // Unrolled, the tube is a rectangle as wide as its girth.
    let area = wrapped.development_mm.area();
    assert!((area - TAU * radius * height).abs() < 0.002 * area, "development {area} mm²");
}

#[test]
fn a_full_cone_wraps_onto_the_cone_and_unrolls_to_its_area() {
    let (r1, r2, height, thickness) = (40.0, 20.0, 35.0, 1.0);
    let mut settings = ShadeSettings::default();
    settings.shade = Shade::cone(r1, r2, height).unwrap();
    let slant = settings.shade.slant_height_mm();
    let rows: Vec<(Region, RowPlace)> =
        settings.rows(8.0).unwrap().into_iter().map(|p| (full_row(p.radius_mm, p.band_mm), p)).collect();
    let wrapped = wrap_rows(&rows, &settings, thickness).unwrap();
    let mesh = &wrapped.mesh_mm;
    assert!(mesh.sanity_check().is_ok());
    assert_eq!(mesh.shell_count(), 1);
    // Every vertex on the cone or outward of it by at most the thickness.
    for v in &mesh.vertices {
        let on_cone = r1 + (r2 - r1) * v[2] / height;
        let outward = (v[0].hypot(v[1]) - on_cone) * height / slant;
        assert!((-1e-9..=thickness + 1e-6).contains(&outward), "vertex {outward} mm off the cone");
    }
    let lateral = PI * (r1 + r2) * slant;
    let area = wrapped.development_mm.area();
    assert!((area - lateral).abs() < 0.002 * lateral, "development {area} mm² against {lateral}");
}

#[test]
fn split_edges_keep_a_mesh_closed_and_bound_the_bend() {
    let square = vec![DVec2::new(0.0, 0.0), DVec2::new(30.0, 0.0), DVec2::new(30.0, 8.0), DVec2::new(0.0, 8.0)];
    let flat = extrude(&Region::new(vec![Polygon { outer: square, holes: vec![] }]), 1.0).unwrap();
    // Bend the strip round a cylinder of radius 10.
    let bend = |v: [f64; 3]| DVec3::new((10.0 + v[2]) * (v[0] / 10.0).cos(), (10.0 + v[2]) * (v[0] / 10.0).sin(), v[1]);
    let tolerance = 0.01;
    let fine = split_edges(&flat, |a, b| {
        let middle = bend([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])]);
        middle.distance(0.5 * (bend(a) + bend(b))) > tolerance
    });
    assert!(fine.sanity_check().is_ok());
    assert_eq!(fine.shell_count(), 1);
    // No edge across the strip longer than the chord that strays by the tolerance.
    let longest = (8.0 * 11.0 * tolerance).sqrt();
    for t in &fine.triangles {
        for k in 0..3 {
            let (a, b) = (fine.vertices[t[k] as usize], fine.vertices[t[(k + 1) % 3] as usize]);
            assert!((a[0] - b[0]).abs() <= longest + 1e-9, "edge spans {} mm of arc", (a[0] - b[0]).abs());
        }
    }
}
