//! SVG output of a planar pattern, in millimetres: filled for engraving or
//! viewing, or hairline cut paths for a laser.

use std::fmt::Write;

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::geom::{OutlineSegment, Rect, Region, SmoothOptions, SmoothRing, offset, smooth_region, union};

/// Stroke colour of cut paths: laser software maps a colour to an operation.
pub const CUT_COLOUR: &str = "#FF0000";
/// Stroke width of cut paths, mm: a hairline, which laser software reads as "cut".
pub const HAIRLINE_MM: f64 = 0.01;
/// Margin around the pattern, mm.
const MARGIN_MM: f64 = 1.0;
/// Coordinates are written to 1 nm, so that outlines which touch at a point
/// still touch, and do not cross, when the file is read back; points closer
/// than that are one point.
const DECIMALS: usize = 6;

/// What the SVG is for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum SvgFlavour {
    /// Filled shapes (`evenodd`), for engraving, printing or viewing.
    #[default]
    Engrave,
    /// Closed outlines as hairline strokes with no fill, holes before the
    /// outline around them, so a laser cuts inner parts before it frees the
    /// part that holds them.
    Cut,
}

/// How to write an SVG.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
#[serde(default)]
pub struct SvgOptions {
    /// Filled or cut paths.
    pub flavour: SvgFlavour,
    /// Laser kerf, mm: outlines move out and holes move in by half of it,
    /// so that the cut part keeps its drawn size. Zero for none.
    pub kerf_mm: f64,
    /// Outlines as cubic curves through the vertices where they are chords
    /// of curves, so a laser does not cut the facets; corners and straight
    /// runs stay as they are (see [`crate::geom::smooth_ring`]). Where
    /// smoothing would make outlines touch or cross, the straight chords
    /// are written instead.
    pub smooth_curves: bool,
}

impl Default for SvgOptions {
    fn default() -> Self {
        SvgOptions { flavour: SvgFlavour::Engrave, kerf_mm: 0.0, smooth_curves: true }
    }
}

impl SvgOptions {
    /// Options for `flavour` with no kerf.
    pub fn new(flavour: SvgFlavour) -> Self {
        SvgOptions { flavour, ..SvgOptions::default() }
    }

    /// With a kerf of `kerf_mm`.
    pub fn with_kerf_mm(self, kerf_mm: f64) -> Self {
        SvgOptions { kerf_mm, ..self }
    }

    /// With outlines written as smooth curves or as the straight chords.
    pub fn with_smooth_curves(self, smooth_curves: bool) -> Self {
        SvgOptions { smooth_curves, ..self }
    }
}

/// The region as a filled SVG in millimetres ([`SvgFlavour::Engrave`]).
///
/// ```
/// use tracery_core::export::region_to_svg;
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let mut hole = square(1.0);
/// hole.reverse();
/// let frame = Region::new(vec![Polygon { outer: square(2.0), holes: vec![hole] }]);
/// let svg = region_to_svg(&frame);
/// assert_eq!(svg.matches("<path").count(), 1);
/// assert!(svg.contains("evenodd") && svg.contains("viewBox"));
/// ```
pub fn region_to_svg(region: &Region) -> String {
    write_svg(region, &SvgOptions::default())
}

/// The region as an SVG document: `width` and `height` in mm and a
/// `viewBox` of the same numbers from 0, so one user unit is one
/// millimetre, and no transforms (`y` is flipped in the coordinates).
///
/// The cut flavour unions the region first (patterns of several curves may
/// overlap), applies the kerf, and writes each ring as its own closed path:
/// holes of a part, then its outline.
///
/// ```
/// use tracery_core::export::{SvgFlavour, SvgOptions, write_svg};
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// let square = |s: f64| vec![DVec2::new(-s, -s), DVec2::new(s, -s), DVec2::new(s, s), DVec2::new(-s, s)];
/// let mut hole = square(1.0);
/// hole.reverse();
/// let frame = Region::new(vec![Polygon { outer: square(2.0), holes: vec![hole] }]);
/// let svg = write_svg(&frame, &SvgOptions::new(SvgFlavour::Cut));
/// assert_eq!(svg.matches("<path").count(), 2);
/// assert!(svg.contains(r#"fill="none""#) && !svg.contains("transform"));
/// ```
pub fn write_svg(region: &Region, options: &SvgOptions) -> String {
    let region = match options.flavour {
        SvgFlavour::Engrave if options.kerf_mm == 0.0 => region.clone(),
        _ => offset(&union(&[region]), options.kerf_mm / 2.0),
    };
    let bounds = region.bounds().unwrap_or(Rect::new(DVec2::ZERO, DVec2::ONE)).inflate(MARGIN_MM);
    let (mut svg, to_page) = page(&bounds);
    let smooth = if options.smooth_curves { smooth_region(&region, &SmoothOptions::default()) } else { None };
    // Each polygon's rings, outline first, as path data.
    let paths: Vec<Vec<Option<String>>> = region
        .polygons
        .iter()
        .enumerate()
        .map(|(k, polygon)| match &smooth {
            Some(smooth) => smooth[k].iter().map(|ring| smooth_ring_path(ring, to_page)).collect(),
            None => polygon.rings().map(|ring| ring_path(ring, to_page)).collect(),
        })
        .collect();
    match options.flavour {
        SvgFlavour::Engrave => {
            let _ = writeln!(svg, r#"  <g id="engrave">"#);
            for rings in &paths {
                let d: Vec<&str> = rings.iter().flatten().map(String::as_str).collect();
                if !d.is_empty() {
                    let _ = writeln!(svg, r#"    <path fill="black" fill-rule="evenodd" d="{}"/>"#, d.join(" "));
                }
            }
        }
        SvgFlavour::Cut => {
            let _ = writeln!(svg, r#"  <g id="cut">"#);
            for rings in &paths {
                // Holes first, then the outline around them.
                for d in rings.iter().skip(1).chain(rings.first()).flatten() {
                    let _ = writeln!(
                        svg,
                        r#"    <path fill="none" stroke="{CUT_COLOUR}" stroke-width="{HAIRLINE_MM}" d="{d}"/>"#
                    );
                }
            }
        }
    }
    svg.push_str("  </g>\n</svg>\n");
    svg
}

/// The document's opening tag for a page covering `bounds` (mm), and the
/// map from the plane (mm, `y` up) to the page (mm, `y` down, origin at
/// the top left).
fn page(bounds: &Rect) -> (String, impl Fn(DVec2) -> DVec2 + Copy + use<>) {
    let (w, h) = (bounds.width(), bounds.height());
    let (min_x, max_y) = (bounds.min.x, bounds.max.y);
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.3}mm" height="{h:.3}mm" viewBox="0 0 {w:.3} {h:.3}">"#
    );
    (svg, move |p: DVec2| DVec2::new(p.x - min_x, max_y - p.y))
}

/// A point on the page as written: `x,y` to [`DECIMALS`] places.
fn point_text(q: DVec2) -> String {
    format!("{:.DECIMALS$},{:.DECIMALS$}", q.x, q.y)
}

/// One closed subpath, with points that round to the same written
/// coordinates merged, so no segment has zero length. `None` when fewer
/// than three distinct points remain.
fn ring_path(ring: &[DVec2], to_page: impl Fn(DVec2) -> DVec2) -> Option<String> {
    let mut points: Vec<String> = Vec::with_capacity(ring.len());
    for p in ring {
        let text = point_text(to_page(*p));
        if points.last() != Some(&text) {
            points.push(text);
        }
    }
    while points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    if points.len() < 3 {
        return None;
    }
    Some(format!("M{} Z", points.join(" L")))
}

/// One closed subpath of lines and cubics, with segments whose end rounds
/// to the written coordinates of the one before dropped. `None` when fewer
/// than three distinct points remain.
fn smooth_ring_path(ring: &SmoothRing, to_page: impl Fn(DVec2) -> DVec2) -> Option<String> {
    let text = |p: DVec2| point_text(to_page(p));
    let start = text(ring.start);
    let mut last = start.clone();
    let mut d = format!("M{start}");
    let mut distinct = 1;
    for (k, segment) in ring.segments.iter().enumerate() {
        let end = text(segment.end());
        if end == last {
            continue;
        }
        // The closing straight edge is the `Z` itself.
        let closing = k + 1 == ring.segments.len() && end == start;
        match *segment {
            OutlineSegment::Line(_) if closing => continue,
            OutlineSegment::Line(_) => d += &format!(" L{end}"),
            OutlineSegment::Cubic(c1, c2, _) => d += &format!(" C{} {} {end}", text(c1), text(c2)),
        }
        if !closing {
            distinct += 1;
        }
        last = end;
    }
    (distinct >= 3).then(|| d + " Z")
}

/// Stroked paths as an SVG document for a pen plotter or a laser that
/// engraves lines: each path a black stroke of its own width with round
/// caps and joins, sized in millimetres as [`write_svg`] sizes regions;
/// then the `filled` shapes (a fill's discrete elements), filled black.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::export::write_paths_svg;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::product::StrokedPath;
/// let line = StrokedPath { points_mm: vec![DVec2::ZERO, DVec2::new(10.0, 5.0)], closed: false, width_mm: 0.8 };
/// let svg = write_paths_svg(&[line.clone()], &Region::default());
/// assert_eq!(svg.matches("<path").count(), 1);
/// assert!(svg.contains(r#"stroke-width="0.800""#) && svg.contains(r#"fill="none""#));
/// let dot = Polygon { outer: vec![DVec2::new(3.0, 3.0), DVec2::new(4.0, 3.0), DVec2::new(4.0, 4.0)], holes: vec![] };
/// let with_dot = write_paths_svg(&[line], &Region::new(vec![dot]));
/// assert_eq!(with_dot.matches("<path").count(), 2);
/// assert!(with_dot.contains(r#"<g id="elements" fill="black""#));
/// ```
pub fn write_paths_svg(paths: &[crate::product::StrokedPath], filled: &Region) -> String {
    let reach = paths.iter().map(|p| 0.5 * p.width_mm).fold(0.0, f64::max);
    let bounds = Rect::from_points(
        paths.iter().flat_map(|p| p.points_mm.iter().copied()).chain(filled.rings().flatten().copied()),
    )
    .unwrap_or(Rect::new(DVec2::ZERO, DVec2::ONE))
    .inflate(MARGIN_MM + reach);
    let (mut svg, to_page) = page(&bounds);
    let _ = writeln!(
        svg,
        r#"  <g id="strokes" fill="none" stroke="black" stroke-linecap="round" stroke-linejoin="round">"#
    );
    for path in paths {
        let points: Vec<String> = path.points_mm.iter().map(|p| point_text(to_page(*p))).collect();
        if points.len() < 2 {
            continue;
        }
        let close = if path.closed { " Z" } else { "" };
        let _ = writeln!(
            svg,
            r#"    <path fill="none" stroke-width="{:.3}" d="M{}{close}"/>"#,
            path.width_mm,
            points.join(" L")
        );
    }
    svg.push_str("  </g>\n");
    if !filled.is_empty() {
        let _ = writeln!(svg, r#"  <g id="elements" fill="black" stroke="none">"#);
        for polygon in &filled.polygons {
            let d: Vec<String> = polygon.rings().filter_map(|r| ring_path(r, to_page)).collect();
            if !d.is_empty() {
                let _ = writeln!(svg, r#"    <path fill-rule="evenodd" d="{}"/>"#, d.join(" "));
            }
        }
        svg.push_str("  </g>\n");
    }
    svg.push_str("</svg>\n");
    svg
}
