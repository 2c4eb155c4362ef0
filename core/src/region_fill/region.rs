//! The region a fill goes in: from a spec (`rect:`, `circle:`, `svg:`), or
//! from outlines a person drew, checked before any work starts.

use std::path::Path;

use glam::DVec2;

use super::{FillError, Settings};
use crate::curve::svg_shapes;
use crate::geom::{FillRule, Rect, Region, arc_step, disc, offset, resolve_contours, ring_crossing};
use crate::setting::WORLD_EXTENT_MM;

/// Largest distance between a region's curved edges and their chords, mm.
pub const REGION_TOLERANCE_MM: f64 = 0.01;

/// Most output samples a fill may take (about a 450 mm square at 1.5 mm).
pub const MAX_FILL_SAMPLES: usize = 100_000;

/// The region a spec names: `rect:WxH` (from the origin), `circle:R`
/// (centred on the origin) or `svg:FILE` (the drawing's closed and filled
/// shapes, even-odd, so a shape inside another is a hole).
///
/// ```
/// use tracery_core::region_fill::parse_region;
/// let r = parse_region("rect:60x40").unwrap();
/// assert!((r.area() - 2400.0).abs() < 1e-9);
/// let c = parse_region("circle:10").unwrap();
/// assert!((c.area() - std::f64::consts::PI * 100.0).abs() < 0.5);
/// assert!(parse_region("square:3").is_err());
/// assert!(parse_region("rect:0x4").is_err());
/// ```
/// Sizes must be at most [`WORLD_EXTENT_MM`]; an SVG's drawing is held to it by `svg_shapes`.
pub fn parse_region(spec: &str) -> Result<Region, FillError> {
    let bad = || FillError::BadRegionSpec(spec.to_string());
    let (kind, rest) = spec.split_once(':').ok_or_else(bad)?;
    // Sizes stop at the table's edge before anything is allocated from them.
    let number = |s: &str| {
        s.trim().parse::<f64>().ok().filter(|x| x.is_finite() && *x > 0.0 && *x <= WORLD_EXTENT_MM).ok_or_else(bad)
    };
    match kind {
        "rect" => {
            let (w, h) = rest.split_once(['x', 'X']).ok_or_else(bad)?;
            let (w, h) = (number(w)?, number(h)?);
            Ok(Region::rectangle(&Rect::new(DVec2::ZERO, DVec2::new(w, h))))
        }
        "circle" => {
            let r = number(rest)?;
            let sides = (std::f64::consts::TAU / arc_step(r, REGION_TOLERANCE_MM)).ceil().max(16.0) as usize;
            Ok(Region::new(vec![disc(DVec2::ZERO, r, sides)]))
        }
        "svg" => {
            let data = std::fs::read(Path::new(rest))
                .map_err(|e| FillError::Read { path: rest.to_string(), message: e.to_string() })?;
            let outlines: Vec<Vec<DVec2>> = svg_shapes(&data, REGION_TOLERANCE_MM)?
                .into_iter()
                .filter(|s| s.closed || s.filled)
                .map(|s| s.points_mm)
                .collect();
            region_from_outlines(&outlines)
        }
        _ => Err(bad()),
    }
}

/// The region inside closed `outlines` (even-odd: an outline inside
/// another is a hole), refusing an outline that crosses itself.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::region_from_outlines;
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let frame = region_from_outlines(&[square(20.0), square(5.0)]).unwrap();
/// assert_eq!(frame.hole_count(), 1);
/// let bow_tie = vec![DVec2::ZERO, DVec2::new(10.0, 10.0), DVec2::new(10.0, 0.0), DVec2::new(0.0, 10.0)];
/// assert!(region_from_outlines(&[bow_tie]).is_err());
/// ```
pub fn region_from_outlines(outlines: &[Vec<DVec2>]) -> Result<Region, FillError> {
    let mut rings = Vec::new();
    for outline in outlines {
        let mut ring = outline.clone();
        ring.dedup_by(|a, b| a.distance(*b) < 1e-9);
        while ring.len() > 2 && ring[0].distance(ring[ring.len() - 1]) < 1e-9 {
            ring.pop();
        }
        if ring.len() < 3 {
            continue;
        }
        if let Some(p) = ring_crossing(&ring) {
            return Err(FillError::RegionCrossesItself { x_mm: p.x, y_mm: p.y });
        }
        rings.push(ring);
    }
    let region = resolve_contours(&rings, FillRule::EvenOdd);
    if region.is_empty() {
        return Err(FillError::EmptyRegion);
    }
    Ok(region)
}

/// Checks a fill of `region` can be made with `settings`: room somewhere
/// for a whole neighbourhood, and not more samples than the cap.
pub fn check_region(region: &Region, settings: &Settings) -> Result<(), FillError> {
    if region.is_empty() || region.area() <= 0.0 {
        return Err(FillError::EmptyRegion);
    }
    let radius = settings.radius_mm();
    if offset(region, -radius).is_empty() {
        return Err(FillError::RegionTooSmall { diameter_mm: 2.0 * radius });
    }
    let bounds = region.bounds().ok_or(FillError::EmptyRegion)?;
    let samples = (bounds.width() * bounds.height() / (settings.delta_mm * settings.delta_mm)).ceil() as usize;
    if samples > MAX_FILL_SAMPLES {
        return Err(FillError::RegionTooLarge { samples, max: MAX_FILL_SAMPLES });
    }
    Ok(())
}
