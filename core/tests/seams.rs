//! Seams without kinks: where the two sides of a seam meet at different
//! slopes, stitching bends them to a common tangent, measured on the
//! stitched outline by the independent seam measure
//! (`quality::seam_kinks_deg`).

use tracery_core::DVec2;
use tracery_core::quality::seam_kinks_deg;
use tracery_core::vector_brush::{CurveKind, Exemplar, LoadOptions, PieceSet, SliceOptions, SlicingMode, stitch};

/// A thin stroke, one unit thick across, climbing at a slope of 2 to a peak
/// and falling again, cut at `x = 8` and `x = 16`: the middle piece leaves
/// its left cut climbing and reaches its right cut falling. Laid after
/// itself, each seam joins a falling stroke to a climbing one, a valley
/// whose two sides turn by `2·atan 2` (127°), with the stroke's other edge
/// one unit above or below each endpoint on the seam.
fn chevron() -> (Exemplar, PieceSet, usize) {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 10">
        <path d="M7.25 0.5 L12 10 L16.75 0.5 L16.25 -0.5 L12 8 L7.75 -0.5 Z"/></svg>"#;
    let exemplar = Exemplar::from_svg_str("chevron", svg, &LoadOptions::default()).unwrap();
    let mut options = SliceOptions::default();
    options.mode = SlicingMode::Uniform { cuts: 2 };
    let set = PieceSet::new(&exemplar, &options).unwrap();
    let middle = (0..set.len())
        .find(|&p| set.pieces[p].left.len() == 1 && set.pieces[p].right.len() == 1)
        .expect("a piece the stroke crosses from cut to cut");
    assert!(set.joining(middle, middle).is_some(), "the middle piece should join itself");
    (exemplar, set, middle)
}

#[test]
fn a_stroke_meeting_another_slope_at_a_seam_turns_smoothly() {
    let (exemplar, set, middle) = chevron();
    let sequence = vec![middle; 4];
    let length: f64 = sequence.iter().map(|&p| set.pieces[p].width).sum();
    let band = stitch(&set, &sequence, &[0.0; 4], length, CurveKind::Open, 1e-3 * exemplar.height());
    assert_eq!(band.region.polygons.len(), 1, "the stroke should stay one part");
    assert!(band.region.polygons[0].holes.is_empty(), "no hole should open");
    // At each vertex on a seam line, the outline's turn per unit length
    // (the turn between the edges that arrive and leave, over their mean
    // length), against the same at the vertices before and after it. Where
    // the sides meet at a common tangent the outline bends there as it does
    // beside the seam; a kink turns there alone.
    let curvature = |a: DVec2, p: DVec2, b: DVec2| {
        let (d1, d2) = (p - a, b - p);
        d1.perp_dot(d2).atan2(d1.dot(d2)).abs().to_degrees() / (0.5 * (d1.length() + d2.length()))
    };
    let mut ratios = Vec::new();
    for ring in band.region.rings() {
        let n = ring.len();
        let at = |i: usize, k: isize| ring[(i as isize + k).rem_euclid(n as isize) as usize];
        for (i, &p) in ring.iter().enumerate() {
            let (prev, next) = (at(i, -1), at(i, 1));
            let Some(&seam) = band.seams.iter().find(|&&s| (p.x - s).abs() <= 1e-9 * length) else { continue };
            if (prev.x - seam) * (next.x - seam) >= 0.0 {
                continue;
            }
            let here = curvature(prev, p, next);
            let beside = curvature(at(i, -2), prev, p).max(curvature(p, next, at(i, 2)));
            ratios.push(here / beside.max(1e-9));
        }
    }
    // Two crossings (the stroke's two edges) on each of the three seams.
    assert_eq!(ratios.len(), 6, "{ratios:?}");
    let kinks = seam_kinks_deg(&band.region, &band.seams, 1e-9 * length);
    println!("turn per length at the seams over beside them: {ratios:.2?}; seam measure {kinks:.1?}");
    let worst = ratios.iter().copied().fold(0.0, f64::max);
    assert!(worst < 2.0, "the outline turns {worst:.1} times as sharply on a seam as beside it");
}
