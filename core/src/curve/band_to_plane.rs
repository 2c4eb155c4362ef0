//! Mapping a band-space pattern onto the plane along a curve.

use glam::DVec2;

use super::{Curve, CurveCursor};
use rayon::prelude::*;

use crate::geom::{Outline, Polygon, Region, joined_without_union, refine_mapped_indexed, signed_area, union};
use crate::report::Warning;

/// A pattern laid along a curve, in the plane, in millimetres.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanarPattern {
    /// The pattern: clean polygons with holes.
    pub region: Region,
    /// What was done to keep the output free of self-intersections.
    pub warnings: Vec<Warning>,
    /// Smallest factor the band was narrowed by (1 where it was not).
    pub narrowest_band: f64,
}

/// Fraction of the local radius of curvature the inner half of the band may
/// use before it is narrowed: beyond the radius the band folds over itself.
const CURVATURE_MARGIN: f64 = 0.85;

/// Largest distance between a mapped outline and its straight edges, mm.
pub const MAPPING_TOLERANCE_MM: f64 = 0.005;

/// Lays `band_region` (band space, exemplar units) along `curve` (millimetres), `scale`
/// millimetres per exemplar unit. The band's `u` must run over the curve's length.
///
/// Where the curve turns tighter than the band's half-height, the band would
/// fold over itself; there it is narrowed smoothly (a warning says where).
/// Where distant parts of the curve come close enough for the band to overlap,
/// the overlapping parts are merged by a union (a warning says so), so the
/// output never intersects itself. Where nothing overlaps, the mapped rings
/// are already clean and a loop's two ends are joined without one.
pub fn map_along(band_region: &Region, scale: f64, curve: &Curve) -> PlanarPattern {
    map_along_within(band_region, scale, curve, MAPPING_TOLERANCE_MM)
}

/// [`map_along`] with the mapped outlines within `tolerance_mm` of the true
/// images of the band's edges, instead of [`MAPPING_TOLERANCE_MM`].
///
/// Where the curve turns, the inner side of the band is squeezed along it;
/// a neck of material squeezed to less than about twice the tolerance can
/// have its two sides' chords cross, and the union then cuts it through.
/// A finer tolerance keeps the neck whole, at the cost of more points.
///
/// ```
/// use tracery_core::curve::{Curve, map_along_within};
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::DVec2;
/// let bar = Region::new(vec![Polygon {
///     outer: vec![DVec2::new(0.0, -1.0), DVec2::new(100.0, -1.0), DVec2::new(100.0, 1.0), DVec2::new(0.0, 1.0)],
///     holes: vec![],
/// }]);
/// let curve = Curve::circle(100.0 / std::f64::consts::TAU).unwrap();
/// let coarse = map_along_within(&bar, 1.0, &curve, 0.05);
/// let fine = map_along_within(&bar, 1.0, &curve, 0.0005);
/// let points = |r: &Region| r.rings().map(Vec::len).sum::<usize>();
/// assert!(points(&fine.region) > points(&coarse.region));
/// ```
pub fn map_along_within(band_region: &Region, scale: f64, curve: &Curve, tolerance_mm: f64) -> PlanarPattern {
    let mut warnings = Vec::new();
    let half = band_region.reach_from_axis() * scale;
    let length = curve.length();
    // Narrowing factor sampled along the curve.
    let samples = ((length / (0.25 * half.max(1e-3))).ceil() as usize).clamp(64, 20_000);
    let du = length / samples as f64;
    let mut factor: Vec<f64> = (0..=samples)
        .map(|k| {
            let kappa = curve.curvature(k as f64 * du, half.max(du)).abs();
            if kappa * half <= CURVATURE_MARGIN { 1.0 } else { CURVATURE_MARGIN / (kappa * half) }
        })
        .collect();
    // Spread each narrowing over a band-height either side, then smooth it.
    let reach = ((2.0 * half / du).ceil() as usize).max(1);
    let spread: Vec<f64> = (0..=samples)
        .map(|k| {
            let (a, b) = (k.saturating_sub(reach), (k + reach).min(samples));
            factor[a..=b].iter().copied().fold(1.0, f64::min)
        })
        .collect();
    factor = (0..=samples)
        .map(|k| {
            let (a, b) = (k.saturating_sub(reach), (k + reach).min(samples));
            spread[a..=b].iter().sum::<f64>() / (b - a + 1) as f64
        })
        .collect();
    let narrowest = factor.iter().copied().fold(1.0, f64::min);
    if narrowest < 0.999 {
        let at = factor.iter().position(|&f| f == narrowest).unwrap_or(0) as f64 * du;
        warnings.push(Warning::BandNarrowed { at_mm: at, percent: narrowest * 100.0 });
    }
    let narrowing = |u: f64| {
        let x = (u / du).clamp(0.0, samples as f64);
        let k = (x.floor() as usize).min(samples - 1);
        let t = x - k as f64;
        factor[k] * (1.0 - t) + factor[k + 1] * t
    };
    let step = (half).min(length / 50.0).max(1e-3);
    let closed = curve.is_closed();
    // Each ring's points come in order along it, so each ring's mapping
    // follows the curve with a cursor of its own.
    let place = |cursor: &CurveCursor, p: DVec2| {
        let mut u = p.x * scale;
        // The end of a loop is its start: the same point, to the last bit,
        // so that the closing seam welds (a union's grid may have left
        // either side a few ulps off its line).
        if closed && ((u - length).abs() <= 1e-9 * length || u.abs() <= 1e-9 * length) {
            u = 0.0;
        }
        cursor.map(u, p.y * scale * narrowing(u))
    };
    // Points are added where the curve bends an edge away from its chord.
    // A loop's two ends are one line in the plane, where `place` puts the
    // same point for the same `v`: points there are marked, so that the
    // outlines meeting across it are joined.
    let line_of = |x: f64| {
        if !closed {
            None
        } else if (x * scale).abs() <= 1e-9 * length {
            Some(0)
        } else if (x * scale - length).abs() <= 1e-9 * length {
            Some(1)
        } else {
            None
        }
    };
    let outline = |(polygon, r): (usize, &Vec<DVec2>)| {
        let cursor = curve.cursor();
        let (points, origins) = refine_mapped_indexed(r, |p| place(&cursor, p), step / scale, tolerance_mm);
        let mut lines = vec![None; points.len()];
        for (p, &i) in r.iter().zip(&origins) {
            lines[i] = line_of(p.x);
        }
        Outline { polygon, points, lines }
    };
    // Rings are mapped on every core.
    let rings: Vec<(usize, &Vec<DVec2>)> =
        band_region.polygons.iter().enumerate().flat_map(|(p, polygon)| polygon.rings().map(move |r| (p, r))).collect();
    let outlines: Vec<Outline> = rings.into_par_iter().map(outline).collect();
    // Each polygon's area as mapped, outer ring less holes: what the
    // pattern covers if nothing overlaps.
    let mut separate = 0.0;
    let mut outer_seen = vec![false; band_region.polygons.len()];
    for outline in &outlines {
        let area = signed_area(&outline.points).abs();
        separate += if std::mem::replace(&mut outer_seen[outline.polygon], true) { -area } else { area };
    }
    let region = joined_without_union(band_region.polygons.len(), &outlines, None).unwrap_or_else(|| {
        let mut mapped: Vec<Polygon> = band_region.polygons.iter().map(|_| Polygon::default()).collect();
        for outline in outlines {
            let polygon = &mut mapped[outline.polygon];
            if polygon.outer.is_empty() {
                polygon.outer = outline.points;
            } else {
                polygon.holes.push(outline.points);
            }
        }
        union(&[&Region::new(mapped)])
    });
    // Where the band overlapped itself, part of it went through a union.
    if separate > 0.0 && (separate - region.area()) / separate > 1e-3 {
        warnings.push(Warning::BandOverlapsItself { merged_percent: 100.0 * (separate - region.area()) / separate });
    }
    PlanarPattern { region, warnings, narrowest_band: narrowest }
}
