//! Ornaments drawn as filled bands: the fill learns the lines they were
//! drawn along (`geom::centre_lines`, `CurveExemplar::curves`), checked
//! against the line each band was made from, and on the fill's output by
//! the independent crossing count.

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::geom::{Rect, brush_stroke, centre_lines, union};
use tracery_core::quality::curve_statistics_within;
use tracery_core::region_fill::{CurveExemplar, Settings, make_product, parse_region};

/// Distance from `p` to the polyline `line`, written here rather than
/// taken from the code under test.
fn distance_to(line: &[DVec2], p: DVec2) -> f64 {
    line.windows(2)
        .map(|s| {
            let (a, b) = (s[0], s[1]);
            let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            p.distance(a + (b - a) * t)
        })
        .fold(f64::INFINITY, f64::min)
}

/// A Greek key: a line with five right-angled turns, mm.
fn key() -> Vec<DVec2> {
    [(0.0, 0.0), (20.0, 0.0), (20.0, 12.0), (6.0, 12.0), (6.0, 5.0), (14.0, 5.0), (14.0, 8.0)]
        .map(|(x, y)| DVec2::new(x, y))
        .to_vec()
}

/// `line` resampled about `step` apart.
fn resampled(line: &[DVec2], step: f64) -> Vec<DVec2> {
    let mut points = Vec::new();
    for s in line.windows(2) {
        let n = (s[0].distance(s[1]) / step).ceil() as usize;
        points.extend((0..n).map(|k| s[0].lerp(s[1], k as f64 / n as f64)));
    }
    points.extend(line.last());
    points
}

#[test]
fn a_bands_centre_line_runs_down_its_middle_with_no_spurs() {
    let line = key();
    let band = brush_stroke(&line, 1.0, false);
    assert_eq!(band.polygons.len(), 1);
    let centre = centre_lines(&band.polygons[0], 0.2).expect("triangulated");
    assert_eq!(centre.paths.len(), 1, "one line, no spurs into the corners: {:?}", centre.paths.len());
    let (found, closed) = &centre.paths[0];
    assert!(!closed);
    // Every point of the found line is near the drawn one...
    let off = found.iter().map(|p| distance_to(&line, *p)).fold(0.0, f64::max);
    assert!(off < 0.2, "the centre line strays {off:.3} mm from the line the band was drawn along");
    // ...and the drawn one is covered, but for its ends, where the band's
    // round caps end the line a half width early.
    let ends = [line[0], *line.last().unwrap()];
    let missed = resampled(&line, 0.2)
        .into_iter()
        .filter(|p| ends.iter().all(|e| e.distance(*p) > 0.6))
        .map(|p| distance_to(found, p))
        .fold(0.0, f64::max);
    assert!(missed < 0.25, "a stretch of the drawn line is {missed:.3} mm from the centre line");
    assert!((centre.width_at(0.8) - 1.0).abs() < 0.2, "width {:.2}", centre.width_at(0.8));
}

/// Bands 1.2 mm wide, 10 mm long, from the origin along `directions`, united.
fn arms(directions: &[DVec2]) -> tracery_core::geom::Polygon {
    let arms: Vec<_> = directions.iter().map(|d| brush_stroke(&[DVec2::ZERO, *d * 10.0], 1.2, false)).collect();
    let shape = union(&arms.iter().collect::<Vec<_>>());
    assert_eq!(shape.polygons.len(), 1);
    shape.polygons[0].clone()
}

/// Whether segments `a` and `b` cross at a point inside both.
fn segments_cross(a: [DVec2; 2], b: [DVec2; 2]) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    side(a[0], a[1], b[0]) * side(a[0], a[1], b[1]) < 0.0 && side(b[0], b[1], a[0]) * side(b[0], b[1], a[1]) < 0.0
}

#[test]
fn bands_that_meet_give_lines_that_meet_at_one_junction() {
    let centre = centre_lines(&arms(&[DVec2::X, DVec2::Y, -DVec2::X]), 0.2).expect("triangulated");
    assert_eq!(centre.paths.len(), 3, "one line per arm of the T");
    // Each arm's line has one end out at its tip and one at the junction.
    let mut inner: Vec<DVec2> = Vec::new();
    for (points, _) in &centre.paths {
        let (a, b) = (points[0], *points.last().unwrap());
        let (near, far) = if a.length() < b.length() { (a, b) } else { (b, a) };
        assert!(far.length() > 9.0, "an arm's line stops at {far:?}");
        inner.push(near);
    }
    assert!(inner.iter().all(|p| p.distance(inner[0]) < 1e-9), "the arms meet at one point: {inner:?}");
    assert!(inner[0].length() < 0.6, "the junction lies where the bands meet, not {:?}", inner[0]);
}

#[test]
fn bands_that_cross_give_lines_that_cross() {
    let centre = centre_lines(&arms(&[DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y]), 0.2).expect("triangulated");
    assert_eq!(centre.paths.len(), 2, "a plus is two lines crossing, not four meeting");
    let segments = |k: usize| -> Vec<[DVec2; 2]> { centre.paths[k].0.windows(2).map(|s| [s[0], s[1]]).collect() };
    let crossings = segments(0)
        .iter()
        .flat_map(|a| segments(1).into_iter().map(move |b| (*a, b)))
        .filter(|(a, b)| segments_cross(*a, *b))
        .count();
    assert_eq!(crossings, 1, "the two lines cross once");
    for (points, _) in &centre.paths {
        let (a, b) = (points[0], *points.last().unwrap());
        assert!(a.distance(b) > 18.0, "each line runs tip to tip, not {a:?} to {b:?}");
    }
}

/// A fret drawn as filled bands 1 mm wide (a row of Greek keys, each a
/// band), as an SVG drawing.
fn banded_fret_svg() -> String {
    let mut d = String::new();
    for k in 0..3 {
        let shifted: Vec<DVec2> = key().iter().map(|p| *p + DVec2::new(24.0 * k as f64, 0.0)).collect();
        let mut line = vec![shifted[0] - DVec2::new(4.0, 0.0)];
        line.extend(shifted);
        for polygon in brush_stroke(&line, 1.0, false).polygons {
            for ring in polygon.rings() {
                d += &format!("M{:.3},{:.3} ", ring[0].x, 20.0 - ring[0].y);
                for p in &ring[1..] {
                    d += &format!("L{:.3},{:.3} ", p.x, 20.0 - p.y);
                }
                d += "Z ";
            }
        }
    }
    format!(r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="-5 0 80 25"><path fill-rule="evenodd" d="{d}"/></svg>"#)
}

#[test]
fn a_fret_of_filled_bands_fills_without_crossings() {
    let exemplar = CurveExemplar::from_svg_data("banded fret", banded_fret_svg().as_bytes()).unwrap();
    assert_eq!(exemplar.shapes.len(), 3);
    let settings = Settings::default();
    let curves = exemplar.curves(settings.delta_mm);
    assert_eq!(curves.paths.len(), 3, "each band is read as one line");
    let region = parse_region("rect:50x35").unwrap();
    let bounds: Rect = region.bounds().unwrap();
    let margin = settings.radius_mm();
    let crossings = |exemplar: &CurveExemplar| {
        let product = make_product(exemplar, &region, &settings, &Control::default()).unwrap();
        let paths: Vec<_> = product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
        curve_statistics_within(&paths, &bounds, margin).crossings_per_100mm
    };
    assert_eq!(crossings(&exemplar), 0.0, "the fill's lines cross, where the fret's never do");
}

/// Crossings per 100 mm in a 60 × 40 mm fill of `exemplar` drawn 40 mm
/// across, and how many crossings the synthesis made and the pipeline cut.
fn corpus_crossings(exemplar: &CurveExemplar) -> (f64, usize) {
    let bounds = Rect::from_points(exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied())).unwrap();
    let mut settings = Settings::default();
    settings.exemplar_scale = 40.0 / bounds.width().max(bounds.height());
    let region = parse_region("rect:60x40").unwrap();
    let product = make_product(exemplar, &region, &settings, &Control::default()).unwrap();
    let paths: Vec<_> = product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
    let crossings =
        curve_statistics_within(&paths, &region.bounds().unwrap(), settings.radius_mm()).crossings_per_100mm;
    let cut = product.facts.count("crossings_cut").expect("the fill reports its cut crossings as a count");
    (crossings, cut)
}

#[test]
fn corpus_frets_of_filled_bands_fill_without_braiding() {
    let dir = std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus/ornaments"));
    if !dir.exists() {
        eprintln!("the corpus is not next to this checkout; nothing to check");
        return;
    }
    // Two frets whose bands, about 1 mm wide at 40 mm, braided when their
    // outlines were learned (about 2 and 3 crossings per 100 mm). Crossings
    // left by the synthesis are cut after it, so the braid shows as cuts:
    // the centre lines must need none, where the outlines need some.
    for name in ["pgfhan4", "pgfhan10"] {
        let exemplar = CurveExemplar::load(&dir.join(format!("{name}.svg")).to_string_lossy()).unwrap();
        assert_eq!(corpus_crossings(&exemplar), (0.0, 0), "{name}: the fill's lines cross, where the fret's never do");
        let outlines = CurveExemplar::from_paths("outlines", exemplar.paths.clone());
        let (crossings, cut) = corpus_crossings(&outlines);
        assert_eq!(crossings, 0.0, "{name}: the outlines' crossings are cut");
        assert!(cut > 0, "{name}: outlines no longer braid; this test tests nothing");
    }
}
