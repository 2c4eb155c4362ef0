//! Exports read back by readers that share nothing with the writers: 3MF
//! through a zip reader and an XML parser, cut SVGs through usvg.

use std::collections::HashSet;
use std::io::Cursor;

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::export::{SvgFlavour, SvgOptions, ThreeMfObject, object_colour, write_3mf, write_svg};
use tracery_core::geom::{Region, polyline_distance};
use tracery_core::mesh::Mesh;
use tracery_core::vector_brush::{Settings, builtin, make_product};
use tracery_core::{DVec2, Product};

#[path = "../../tests/common/threemf.rs"]
mod threemf;
use threemf::{is_closed, read_3mf};

fn product(exemplar: &str, along: &str) -> Product {
    let along = Along::parse(along).unwrap();
    make_product(&builtin(exemplar).unwrap(), &along, &Settings::default(), &Control::default()).unwrap()
}

#[test]
fn a_3mf_reads_back_in_millimetres_with_one_closed_object_per_curve() {
    let bracelet = product("lace", "circle:30");
    let border = product("vine", "wave:120");
    let meshes: Vec<&Mesh> = [&bracelet, &border].iter().map(|p| p.mesh_mm.as_ref().unwrap()).collect();
    let objects: Vec<ThreeMfObject<'_>> = meshes
        .iter()
        .enumerate()
        .map(|(k, m)| ThreeMfObject { name: format!("Curve {}", k + 1), colour_rgb: object_colour(k), mesh: m })
        .collect();
    let mut bytes = Cursor::new(Vec::new());
    write_3mf(&objects, &mut bytes).unwrap();
    let read = read_3mf(bytes.get_ref());
    assert_eq!(read.unit, "millimeter");
    assert_eq!(read.objects.len(), 2);
    assert_eq!(read.build_items, 2);
    assert!(read.declared_before_use, "colours are declared before the objects that use them");
    for ((name, vertices, triangles), mesh) in read.objects.iter().zip(&meshes) {
        assert!(name.starts_with("Curve "));
        assert_eq!(triangles.len(), mesh.triangles.len());
        assert!(triangles.iter().flatten().all(|&i| i < vertices.len()));
        assert!(is_closed(triangles), "{name} is watertight and consistently oriented");
        // Millimetres: the same extent as the mesh, to f32 precision.
        for axis in 0..3 {
            let extent =
                |vs: &mut dyn Iterator<Item = f64>| vs.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
            let (lo, hi) = extent(&mut vertices.iter().map(|v| v[axis]));
            let (mlo, mhi) = extent(&mut mesh.vertices.iter().map(|v| v[axis]));
            assert!((lo - mlo).abs() < 1e-4 && (hi - mhi).abs() < 1e-4);
        }
    }
    // The bracelet is 60 mm across and 2 mm thick.
    let xs: Vec<f64> = read.objects[0].1.iter().map(|v| v[0]).collect();
    let width = xs.iter().cloned().fold(f64::MIN, f64::max) - xs.iter().cloned().fold(f64::MAX, f64::min);
    assert!((60.0..75.0).contains(&width), "{width} mm");
}

#[test]
fn a_3mf_with_nothing_in_it_is_refused() {
    let empty = Mesh::default();
    let object = ThreeMfObject { name: "empty".into(), colour_rgb: [0, 0, 0], mesh: &empty };
    assert!(write_3mf(&[object], Cursor::new(Vec::new())).is_err());
}

/// The closed rings of a cut SVG, in document order, in its user units, and
/// whether every path is stroke-only.
fn read_cut_svg(svg: &str) -> (Vec<Vec<DVec2>>, bool) {
    let tree = usvg::Tree::from_str(svg, &usvg::Options::default()).expect("a valid SVG");
    let mut paths = Vec::new();
    collect_paths(tree.root(), &mut paths);
    let mut rings = Vec::new();
    let mut stroke_only = true;
    for path in paths {
        stroke_only &= path.fill().is_none() && path.stroke().is_some();
        // The only transform is usvg's own from the viewBox to the page: one
        // user unit is one millimetre (96/25.4 px), with no offset.
        let t = path.abs_transform();
        let px_per_mm = 96.0 / 25.4;
        assert!((t.sx - px_per_mm).abs() < 1e-4 && (t.sy - px_per_mm).abs() < 1e-4, "{t:?}");
        assert!(t.kx == 0.0 && t.ky == 0.0 && t.tx.abs() < 1e-3 && t.ty.abs() < 1e-3, "{t:?}");
        let mut ring = Vec::new();
        let mut closed = false;
        for segment in path.data().segments() {
            use usvg::tiny_skia_path::PathSegment as S;
            match segment {
                S::MoveTo(p) => {
                    assert!(ring.is_empty(), "one ring per path");
                    ring.push(DVec2::new(p.x as f64, p.y as f64));
                }
                S::LineTo(p) => ring.push(DVec2::new(p.x as f64, p.y as f64)),
                // Curves read as 16 chords each, by the Bézier formula itself.
                S::CubicTo(c1, c2, p) => {
                    let a = *ring.last().expect("a curve starts somewhere");
                    let [b, c, d] = [c1, c2, p].map(|q| DVec2::new(q.x as f64, q.y as f64));
                    for k in 1..=16 {
                        let t = k as f64 / 16.0;
                        let s = 1.0 - t;
                        ring.push(a * s * s * s + b * 3.0 * s * s * t + c * 3.0 * s * t * t + d * t * t * t);
                    }
                }
                S::Close => closed = true,
                other => panic!("unexpected segment {other:?}"),
            }
        }
        assert!(closed, "every path is closed");
        // A closing curve ends where the ring began.
        if ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        rings.push(ring);
    }
    (rings, stroke_only)
}

fn collect_paths<'a>(group: &'a usvg::Group, out: &mut Vec<&'a usvg::Path>) {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => collect_paths(g, out),
            usvg::Node::Path(p) => out.push(p),
            _ => panic!("only paths in a cut SVG"),
        }
    }
}

fn area(ring: &[DVec2]) -> f64 {
    tracery_core::geom::signed_area(ring).abs()
}

fn inside(ring: &[DVec2], p: DVec2) -> bool {
    tracery_core::geom::ring_contains(ring, p)
}

#[test]
fn a_cut_svg_has_closed_hairlines_in_mm_holes_first_and_no_repeated_segment() {
    let region: Region = product("lace", "line:80").region_mm;
    let svg = write_svg(&region, &SvgOptions::new(SvgFlavour::Cut));
    assert!(!svg.contains("transform"));
    // Width and height in mm, with a viewBox of the same numbers.
    let number = |key: &str| svg.split(&format!("{key}=\"")).nth(1).unwrap().split('"').next().unwrap().to_string();
    let (width, height, view_box) = (number("width"), number("height"), number("viewBox"));
    assert!(width.ends_with("mm") && height.ends_with("mm"));
    let vb: Vec<f64> = view_box.split(' ').map(|v| v.parse().unwrap()).collect();
    assert_eq!(vb[0..2], [0.0, 0.0]);
    assert!((vb[2] - width.trim_end_matches("mm").parse::<f64>().unwrap()).abs() < 1e-9);
    assert!((vb[3] - height.trim_end_matches("mm").parse::<f64>().unwrap()).abs() < 1e-9);

    let (rings, stroke_only) = read_cut_svg(&svg);
    assert!(stroke_only);
    assert_eq!(rings.len(), region.component_count() + region.hole_count());
    // A ring inside another is a hole: it comes first.
    for (i, a) in rings.iter().enumerate() {
        for (j, b) in rings.iter().enumerate() {
            if i != j && area(a) < area(b) && inside(b, a[0]) {
                assert!(i < j, "hole {i} comes after the outline {j} around it");
            }
        }
    }
    // No segment twice, in either direction, and none of zero length.
    let mut seen = HashSet::new();
    for ring in &rings {
        for k in 0..ring.len() {
            let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
            assert!(a.distance(b) > 0.0);
            let key = |p: DVec2| ((p.x * 1e4).round() as i64, (p.y * 1e4).round() as i64);
            let edge = if key(a) < key(b) { (key(a), key(b)) } else { (key(b), key(a)) };
            assert!(seen.insert(edge), "segment {a} {b} appears twice");
        }
    }
    // In mm: the line pattern is 80 mm long (with a 1 mm margin each side).
    assert!((80.0..86.0).contains(&vb[2]), "{} mm wide", vb[2]);
}

#[test]
fn kerf_moves_outlines_out_and_holes_in_by_half_of_it() {
    let region: Region = product("lace", "line:60").region_mm;
    let kerf = 0.2;
    let (plain, _) = read_cut_svg(&write_svg(&region, &SvgOptions::new(SvgFlavour::Cut)));
    let (widened, _) = read_cut_svg(&write_svg(&region, &SvgOptions::new(SvgFlavour::Cut).with_kerf_mm(kerf)));
    let largest = |rings: &[Vec<DVec2>]| rings.iter().map(|r| area(r)).fold(0.0, f64::max);
    let outline = rings_perimeter(&plain, &largest(&plain));
    // The outline's area grows by about its perimeter times kerf / 2.
    let grown = largest(&widened) - largest(&plain);
    assert!(
        (grown - outline * kerf / 2.0).abs() < 0.15 * outline * kerf / 2.0,
        "grew {grown}, expected {}",
        outline * kerf / 2.0
    );
    // Every hole that survives is smaller: the total hole area shrinks.
    let holes = |rings: &[Vec<DVec2>]| {
        let big = largest(rings);
        rings.iter().map(|r| area(r)).filter(|a| *a < big).sum::<f64>()
    };
    assert!(holes(&widened) < holes(&plain));
}

fn rings_perimeter(rings: &[Vec<DVec2>], with_area: &f64) -> f64 {
    let ring = rings.iter().find(|r| area(r) == *with_area).unwrap();
    tracery_core::geom::ring_perimeter(ring)
}

/// Joins where successive edges, both at least 20 µm long (after points
/// within 5 µm of the last are merged), turn by 5° to 20°: facets anyone
/// sees on a cut part; and all joins. A curve read back as 16 chords turns
/// a sixteenth of its turn at each join; a chord's end turns it all.
fn visible_facets(ring: &[DVec2]) -> (usize, usize) {
    let mut kept: Vec<DVec2> = Vec::new();
    for &p in ring {
        if kept.last().is_none_or(|q| q.distance(p) >= 0.005) {
            kept.push(p);
        }
    }
    let n = kept.len();
    let facets = (0..n)
        .filter(|&k| {
            let a = kept[k] - kept[(k + n - 1) % n];
            let b = kept[(k + 1) % n] - kept[k];
            let turn = a.angle_to(b).abs().to_degrees();
            a.length() >= 0.02 && b.length() >= 0.02 && (5.0..=20.0).contains(&turn)
        })
        .count();
    (facets, n)
}

#[test]
fn a_cut_svg_follows_curves_smoothly_through_the_outlines_vertices() {
    let region: Region = product("lace", "line:80").region_mm;
    let (rings, _) = read_cut_svg(&write_svg(&region, &SvgOptions::new(SvgFlavour::Cut)));
    let (chords, _) = read_cut_svg(&write_svg(&region, &SvgOptions::new(SvgFlavour::Cut).with_smooth_curves(false)));
    assert_eq!(rings.len(), region.component_count() + region.hole_count());
    // The page is the region's box with a 1 mm margin, y down.
    let bounds = region.bounds().unwrap().inflate(1.0);
    let to_page = |p: DVec2| DVec2::new(p.x - bounds.min.x, bounds.max.y - p.y);
    let page_rings: Vec<Vec<DVec2>> = region.rings().map(|r| r.iter().map(|&p| to_page(p)).collect()).collect();
    // Each of the pattern's vertices lies on the written outline (read
    // back as 16 chords per curve, usvg's f32), and the outline strays from
    // the pattern's own chords by no more than it takes to round them: a
    // 3 mm hole drawn as a decagon has its chords 0.073 mm inside the circle.
    let on_outline = |p: DVec2| rings.iter().map(|r| polyline_distance(r, true, p)).fold(f64::INFINITY, f64::min);
    let to_chords = |p: DVec2| page_rings.iter().map(|r| polyline_distance(r, true, p)).fold(f64::INFINITY, f64::min);
    let worst_vertex = page_rings.iter().flatten().map(|&p| on_outline(p)).fold(0.0, f64::max);
    let worst_stray = rings.iter().flatten().map(|&p| to_chords(p)).fold(0.0, f64::max);
    assert!(worst_vertex < 1e-4, "a vertex {worst_vertex} mm off the written outline");
    assert!(worst_stray < 0.1, "the outline strays {worst_stray} mm from the pattern");
    // Areas agree: nothing crossed or folded (holes come first, the outline
    // last). Rounding the holes' chords out takes a little material.
    let written: f64 = area(rings.last().unwrap()) - rings[..rings.len() - 1].iter().map(|r| area(r)).sum::<f64>();
    assert!(
        (written - region.area()).abs() < 0.015 * region.area(),
        "{written} mm² written, {} mm² drawn",
        region.area()
    );
    // The facets are gone: the straight chords show dozens (the holes'),
    // the curves a tenth as many at most.
    let count =
        |rings: &[Vec<DVec2>]| rings.iter().map(|r| visible_facets(r)).fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    let (smooth, chord) = (count(&rings), count(&chords));
    assert!(chord.0 >= 20, "the chords were expected to show facets: {chord:?}");
    assert!(smooth.0 * 10 <= chord.0, "facets left: {smooth:?}, against {chord:?} with chords");
}
