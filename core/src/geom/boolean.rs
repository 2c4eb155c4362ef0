//! Polygon booleans, through [`i_overlay`].
//!
//! Coordinates go through `i_overlay`'s 64-bit integer engine: with 32 bits
//! the grid is about a millionth of the drawing, coarse enough for two copies
//! of one seam, computed along different paths, to land on different grid
//! lines and leave a hairline gap.
//!
//! Every function returns a clean [`Region`]: polygons that do not overlap,
//! outer rings counter-clockwise, holes clockwise, one polygon per connected
//! component.

use glam::DVec2;
use i_overlay::core::fill_rule::FillRule as OverlayFill;
use i_overlay::core::overlay::ShapeType;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;
use i_overlay::float::simplify::SimplifyShape;
use i_overlay::float::single::SingleFloatOverlay;
use i_overlay::i_float::adapter::FloatPointAdapter;

use super::{Polygon, Rect, Region};

/// How overlapping or self-intersecting contours decide what is filled.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FillRule {
    /// Filled where the winding number is not zero (SVG `nonzero`).
    #[default]
    NonZero,
    /// Filled where a ray crosses the boundary an odd number of times (SVG `evenodd`).
    EvenOdd,
}

impl From<usvg::FillRule> for FillRule {
    fn from(rule: usvg::FillRule) -> Self {
        match rule {
            usvg::FillRule::NonZero => FillRule::NonZero,
            usvg::FillRule::EvenOdd => FillRule::EvenOdd,
        }
    }
}

impl From<FillRule> for OverlayFill {
    fn from(rule: FillRule) -> Self {
        match rule {
            FillRule::NonZero => OverlayFill::NonZero,
            FillRule::EvenOdd => OverlayFill::EvenOdd,
        }
    }
}

pub(super) type Contour = Vec<[f64; 2]>;

fn to_contour(ring: &[DVec2]) -> Contour {
    ring.iter().map(|p| [p.x, p.y]).collect()
}

fn region_contours(region: &Region) -> Vec<Contour> {
    region.rings().map(|r| to_contour(r)).collect()
}

pub(super) fn from_shapes(shapes: Vec<Vec<Vec<[f64; 2]>>>) -> Region {
    let ring = |c: Vec<[f64; 2]>| c.into_iter().map(|[x, y]| DVec2::new(x, y)).collect::<Vec<_>>();
    let extent = shapes.iter().flatten().flatten().fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    // Rings of no area (collinear slivers left where two edges meet) are
    // not holes or parts a person could see or print.
    let negligible = (extent * 1e-9).powi(2);
    let polygons = shapes
        .into_iter()
        .filter_map(|shape| {
            let mut contours = shape.into_iter();
            let outer = ring(contours.next()?);
            let holes = contours.map(ring).filter(|h| super::signed_area(h).abs() > negligible).collect();
            Some(Polygon { outer, holes })
        })
        .filter(|p| p.outer.len() >= 3 && super::signed_area(&p.outer).abs() > negligible)
        .collect();
    Region { polygons }
}

/// Resolves arbitrary closed contours (possibly self-intersecting or
/// overlapping) into a clean region under `rule`.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{resolve_contours, FillRule};
/// let outer = vec![DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)];
/// let inner = vec![DVec2::new(1.0, 1.0), DVec2::new(3.0, 1.0), DVec2::new(3.0, 3.0), DVec2::new(1.0, 3.0)];
/// let region = resolve_contours(&[outer, inner], FillRule::EvenOdd);
/// assert_eq!((region.component_count(), region.hole_count()), (1, 1));
/// ```
pub fn resolve_contours(contours: &[Vec<DVec2>], rule: FillRule) -> Region {
    let input: Vec<Contour> = contours.iter().filter(|c| c.len() >= 3).map(|c| to_contour(c)).collect();
    if input.is_empty() {
        return Region::default();
    }
    from_shapes(input.simplify_shape_as::<i64>(rule.into()))
}

/// Union of all polygons of all regions.
pub fn union(regions: &[&Region]) -> Region {
    let contours: Vec<Contour> = regions.iter().flat_map(|r| region_contours(r)).collect();
    if contours.is_empty() {
        return Region::default();
    }
    // Clean regions wind +1 inside their outer rings and 0 in holes, so the
    // nonzero rule over all their rings together is exactly their union.
    from_shapes(contours.simplify_shape_as::<i64>(OverlayFill::NonZero))
}

/// The part of `region` inside `rect`.
///
/// Only the rings that reach the rectangle go through the overlay: slicing
/// an exemplar clips the whole drawing once per piece, and the rings of the
/// other pieces took most of that time (a third of a run's whole pipeline on
/// the most detailed ornaments of the corpus). A ring wholly outside the
/// rectangle winds only outside it, so the intersection is the same; the
/// integer grid is still fitted to every ring, so that the points come out
/// exactly where a clip of the whole region puts them.
pub fn clip_to_rect(region: &Region, rect: &Rect) -> Region {
    let subject = region_contours(region);
    if subject.is_empty() {
        return Region::default();
    }
    let clip = to_contour(&rect.corners());
    // The grid `overlay_as` would fit to the subject and the clip together.
    let adapter = FloatPointAdapter::with_iter_conservative(subject.iter().flatten().chain(clip.iter()));
    // `subject` holds the rings in the region's order.
    let reaching: Vec<Contour> = region
        .rings()
        .zip(&subject)
        .filter(|(ring, _)| Rect::from_points(ring.iter().copied()).is_some_and(|b| b.overlaps(rect)))
        .map(|(_, contour)| contour.clone())
        .collect();
    if reaching.is_empty() {
        return Region::default();
    }
    let capacity = reaching.iter().map(Vec::len).sum::<usize>() + clip.len();
    // `unsafe_add_source` (a safe function) asks that every point lie within
    // the adapter's box: it was fitted to all of them.
    let shapes = FloatOverlay::<[f64; 2], i64>::with_adapter(adapter, capacity)
        .unsafe_add_source(&reaching, ShapeType::Subject)
        .unsafe_add_source(&clip, ShapeType::Clip)
        .overlay(OverlayRule::Intersect, OverlayFill::NonZero);
    from_shapes(shapes)
}

/// The part of `a` inside `b`.
///
/// ```
/// use glam::DVec2;
/// use tracery_core::geom::{Polygon, Region, intersection};
/// let square = |x: f64| Region::new(vec![Polygon {
///     outer: vec![DVec2::new(x, 0.0), DVec2::new(x + 2.0, 0.0), DVec2::new(x + 2.0, 2.0), DVec2::new(x, 2.0)],
///     holes: vec![],
/// }]);
/// assert!((intersection(&square(0.0), &square(1.0)).area() - 2.0).abs() < 1e-9);
/// ```
pub fn intersection(a: &Region, b: &Region) -> Region {
    let subject = region_contours(a);
    let clip = region_contours(b);
    if subject.is_empty() || clip.is_empty() {
        return Region::default();
    }
    from_shapes(subject.overlay_as::<i64>(&clip, OverlayRule::Intersect, OverlayFill::NonZero))
}

/// The part of `a` outside `b`.
pub fn difference(a: &Region, b: &Region) -> Region {
    let subject = region_contours(a);
    let clip = region_contours(b);
    if subject.is_empty() {
        return Region::default();
    }
    if clip.is_empty() {
        return union(&[a]);
    }
    from_shapes(subject.overlay_as::<i64>(&clip, OverlayRule::Difference, OverlayFill::NonZero))
}
