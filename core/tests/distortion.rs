//! The stitching's distortion, as reported, against what the stitched
//! outline shows: a plain bar's rails are straight along the exemplar, so the
//! slope of their image is the shear, and its length along the band the
//! stretch.

use tracery_core::DVec2;
use tracery_core::vector_brush::{CurveKind, Exemplar, LoadOptions, PieceSet, SliceOptions, stitch};

/// A bar 30 wide and 10 high with two small holes, so that it is cut, and
/// two pieces `a`, `b` that join each other both ways.
fn bar() -> (Exemplar, PieceSet, usize, usize) {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 30 10">
        <path fill-rule="evenodd" d="M0 0H30V10H0Z M5 4H7V6H5Z M20 4H22V6H20Z"/></svg>"#;
    let exemplar = Exemplar::from_svg_str("bar", svg, &LoadOptions::default()).unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let n = set.len();
    let (a, b) = (0..n * n)
        .map(|k| (k / n, k % n))
        .find(|&(a, b)| set.joining(a, b).is_some() && set.joining(b, a).is_some())
        .expect("two pieces of the bar that join both ways");
    (exemplar, set, a, b)
}

/// The outline round the whole stitched bar (its holes left out).
fn outline(band: &tracery_core::vector_brush::BandPattern) -> Vec<Vec<DVec2>> {
    assert_eq!(band.region.polygons.len(), 1, "the bar should stay one part");
    vec![band.region.polygons[0].outer.clone()]
}

/// The steepest rail edge of the stitched outline, in degrees: every edge
/// of its outer ring more than 2 from the pattern's ends (where the cut
/// holes open into notches) runs along it.
fn steepest_rail_deg(rings: &[Vec<DVec2>], length: f64) -> f64 {
    let mut steepest: f64 = 0.0;
    for ring in rings {
        for (k, &a) in ring.iter().enumerate() {
            let b = ring[(k + 1) % ring.len()];
            let near_end = |p: DVec2| p.x < 2.0 || p.x > length - 2.0;
            if near_end(a) || near_end(b) {
                continue;
            }
            let d = b - a;
            steepest = steepest.max(d.y.abs().atan2(d.x.abs()).to_degrees());
        }
    }
    steepest
}

#[test]
fn a_bar_stretched_along_the_band_reports_that_stretch_and_no_shear() {
    let (exemplar, set, a, b) = bar();
    let sequence = vec![a, b, a];
    let natural: f64 = sequence.iter().map(|&p| set.pieces[p].width).sum();
    let length = 1.2 * natural;
    let band = stitch(&set, &sequence, &[0.0; 3], length, CurveKind::Open, 1e-3 * exemplar.height());
    // Measured on the outline: how much longer it came out than its pieces.
    let bounds = band.region.bounds().unwrap();
    let measured = bounds.width() / natural;
    assert!((measured - 1.2).abs() < 1e-6, "{measured}");
    let rings = outline(&band);
    assert!(steepest_rail_deg(&rings, length) < 1e-6);
    let d = &band.distortion;
    assert!(d.sample_count() > 100, "{} samples", d.sample_count());
    assert!((d.stretch_max() - measured).abs() < 1e-3, "reported {} for {measured}", d.stretch_max());
    assert!(d.shear_max_deg() < 0.01, "reported {}°", d.shear_max_deg());
}

#[test]
fn a_bar_raised_in_the_middle_reports_the_slope_of_its_rails_as_shear() {
    let (exemplar, set, a, b) = bar();
    let sequence = vec![a, b, a];
    let length: f64 = sequence.iter().map(|&p| set.pieces[p].width).sum();
    // The middle piece raised by half the bar: its ends meet the others'
    // halfway, so the rails climb and fall.
    let offsets = [0.0, 5.0, 0.0];
    let band = stitch(&set, &sequence, &offsets, length, CurveKind::Open, 1e-4 * exemplar.height());
    let rings = outline(&band);
    let measured = steepest_rail_deg(&rings, length);
    assert!(measured > 5.0, "the rails should climb: {measured}°");
    let reported = band.distortion.shear_max_deg();
    println!("rails at {measured:.2}°, shear reported {reported:.2}°");
    assert!((reported - measured).abs() <= 0.1 * measured + 0.5, "reported {reported}° for rails at {measured}°");
    // A rail climbing at `measured` is longer by 1 / cos of it at least.
    let stretch = band.distortion.stretch_max();
    assert!(stretch >= 0.98 / measured.to_radians().cos(), "stretch {stretch} for rails at {measured}°");
}
