//! [`make_product`]: a region filled with a curve texture, as stroked paths
//! (for pens and lasers) and as a printable solid (the strokes drawn with a
//! round pen, clipped to the region, united with an optional frame).

use crate::control::Control;
use crate::geom::{
    Polygon, Rect, Region, brush_stroke, clip_polylines, count_topology, difference, fill_triangles, intersection,
    join_parts, offset, union,
};
use crate::mesh::extrude;
use crate::product::{Fact, Facts, Product, StrokedPath};
use crate::report::Timings;

use glam::DVec2;

use super::fragments::{degrees, key};
use super::{
    CurveExemplar, CurvePath, Elements, FillError, FragmentLimits, JOIN_TOLERANCE_MM, PlacedElement, SampleGraph,
    Settings, Synthesized, check_region, crossings, cut_crossings, cut_runs_along_drawn, join_drawn_ends,
    smooth_paths_oriented, synthesize_oriented,
};

/// Paths left shorter than this many sample spacings by clipping are
/// dropped: stubs where a curve grazes the region's edge, too short to read
/// as part of the pattern.
const MIN_CLIPPED_SPACINGS: f64 = 1.0;

/// Spurs and loose bits shorter than this many spacings go when the
/// exemplar has none to learn a length from.
const FRAGMENT_FALLBACK_SPACINGS: f64 = 4.0;

/// Spurs and loose bits longer than this many neighbourhood radii stay,
/// whatever the exemplar: longer than the spirals' loose spirals (7.6
/// radii at the defaults), and past what one neighbourhood can judge stray.
const FRAGMENT_CAP_RADII: f64 = 8.0;

/// The share of an element's area that may lie outside the region (by
/// rounding, where its edge runs along the region's) before it is left out.
const ELEMENT_OUTSIDE_SHARE: f64 = 1e-6;

/// Fills `region` (mm) with a curve texture like `exemplar`.
///
/// ```no_run
/// use tracery_core::control::Control;
/// use tracery_core::region_fill::{CurveExemplar, Settings, make_product, parse_region};
/// let exemplar = CurveExemplar::builtin("waves").unwrap();
/// let region = parse_region("circle:25").unwrap();
/// let product = make_product(&exemplar, &region, &Settings::default(), &Control::default()).unwrap();
/// assert!(!product.paths_mm.is_empty() && product.mesh_mm.is_some());
/// ```
pub fn make_product(
    exemplar: &CurveExemplar,
    region: &Region,
    settings: &Settings,
    control: &Control,
) -> Result<Product, FillError> {
    make_product_around(exemplar, region, &Drawn::default(), settings, control)
}

/// What a person drew in a region, mm: pen strokes, and filled shapes
/// (the discrete elements they drew or accepted).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Drawn {
    /// The strokes.
    pub paths: Vec<CurvePath>,
    /// The filled shapes.
    pub shapes: Vec<Polygon>,
}

impl Drawn {
    /// Strokes alone.
    pub fn paths(paths: Vec<CurvePath>) -> Drawn {
        Drawn { paths, shapes: Vec::new() }
    }

    /// Whether nothing was drawn.
    pub fn is_empty(&self) -> bool {
        self.paths.is_empty() && self.shapes.is_empty()
    }
}

/// What autocomplete or clone suggests: new paths, and new discrete
/// elements whole.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Prediction {
    /// Smoothed and clipped to the region, mm.
    pub paths: Vec<CurvePath>,
    /// The shapes of the elements lying wholly within the region, none
    /// overlapping a drawn shape, mm.
    pub elements: Vec<Polygon>,
    /// Crossings the synthesis made where the exemplar has none, cut
    /// after reconstruction ([`cut_crossings`]).
    pub crossings_cut: usize,
    /// Stretches of new paths that ran along a drawn stroke, cut out
    /// ([`cut_runs_along_drawn`]).
    pub along_drawn_cut: usize,
}

impl Prediction {
    /// Whether nothing is suggested.
    pub fn is_empty(&self) -> bool {
        self.paths.is_empty() && self.elements.is_empty()
    }
}

/// As [`make_product`], around what a person drew (`drawn`, mm): the fill
/// grows out of the strokes and joins them ([`synthesize_around`]), and
/// shapes like the exemplar's elements stay where they are, among the new
/// ones. The product's paths and elements are the new ones; its print
/// holds the drawn ones too, so that *one piece* and the counts see the
/// whole.
pub fn make_product_around(
    exemplar: &CurveExemplar,
    region: &Region,
    drawn: &Drawn,
    settings: &Settings,
    control: &Control,
) -> Result<Product, FillError> {
    let mut timings = Timings::default();
    let predicted = predict_timed(exemplar, region, drawn, settings, control, &mut timings)?;
    // Everything may also go as fragments or outside the region.
    if predicted.is_empty() && drawn.is_empty() {
        let bounds = region.bounds().ok_or(FillError::EmptyRegion)?;
        return Err(nothing_left(exemplar, &bounds, settings.exemplar_scale, settings));
    }
    finish(predicted, region, drawn, settings, control, timings)
}

/// What prints of what a person `drawn` in `region` (mm) alone, with
/// the frame: a fill not filled automatically.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::control::Control;
/// use tracery_core::region_fill::{CurvePath, Drawn, Settings, parse_region, print_drawn};
/// let drawn = CurvePath { points_mm: vec![DVec2::new(5.0, 20.0), DVec2::new(35.0, 20.0)], closed: false };
/// let region = parse_region("rect:40x40").unwrap();
/// let product = print_drawn(&region, &Drawn::paths(vec![drawn]), &Settings::default(), &Control::default()).unwrap();
/// assert_eq!(product.topology.components, 1);
/// ```
pub fn print_drawn(
    region: &Region,
    drawn: &Drawn,
    settings: &Settings,
    control: &Control,
) -> Result<Product, FillError> {
    settings.validate()?;
    if region.is_empty() {
        return Err(FillError::EmptyRegion);
    }
    finish(Prediction::default(), region, drawn, settings, control, Timings::default())
}

/// Exemplars of at most this many lines, and no elements, that fit the
/// region yet leave nothing are blamed on their few lines, not their size.
const FEW_CURVES: usize = 2;

/// Why a fill of `bounds` kept nothing of `exemplar` drawn `scale` times larger.
fn nothing_left(exemplar: &CurveExemplar, bounds: &Rect, scale: f64, settings: &Settings) -> FillError {
    let size = Rect::from_points(exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied()))
        .map_or(DVec2::ZERO, |b| b.size() * scale);
    // Not far larger than the region (its own size, give or take half).
    let fits = size.cmple(bounds.size() * 1.5).all();
    if fits && exemplar.paths.len() <= FEW_CURVES && exemplar.elements.is_empty() {
        let longest_mm = exemplar.paths.iter().map(CurvePath::length_mm).fold(0.0, f64::max) * scale;
        return FillError::FewCurves { paths: exemplar.paths.len(), longest_mm };
    }
    FillError::NothingSynthesized {
        exemplar_mm: [size.x, size.y],
        region_mm: [bounds.width(), bounds.height()],
        delta_mm: settings.delta_mm,
    }
}

/// The product of what was `predicted` and what was `drawn` in `region`.
fn finish(
    predicted: Prediction,
    region: &Region,
    drawn: &Drawn,
    settings: &Settings,
    control: &Control,
    mut timings: Timings,
) -> Result<Product, FillError> {
    let Prediction { paths, elements, crossings_cut, along_drawn_cut } = predicted;
    let printed: Vec<CurvePath> = paths.iter().chain(&clip_paths(&drawn.paths, region, 0.0)).cloned().collect();
    let shapes: Vec<Polygon> = elements.iter().chain(&drawn.shapes).cloned().collect();
    let (print, bridges) = timings.time("strokes", || print_region(&printed, &shapes, region, settings));
    control.check()?;
    let topology = count_topology(&print);
    // Nothing drawn yet in a fill that is not filled automatically prints nothing.
    let mesh =
        if print.is_empty() { None } else { Some(timings.time("mesh", || extrude(&print, settings.thickness_mm))?) };
    let mut facts = Facts::default();
    facts.push("paths", Fact::Count(paths.len()));
    facts.push("elements", Fact::Count(elements.len()));
    facts.push("length_mm", Fact::Number(paths.iter().map(CurvePath::length_mm).sum()));
    facts.push("region_area_mm2", Fact::Number(region.area()));
    facts.push("coverage", Fact::Number(print.area() / region.area()));
    facts.push("crossings_cut", Fact::Count(crossings_cut));
    facts.push("along_drawn_cut", Fact::Count(along_drawn_cut));
    if settings.one_piece {
        facts.push("bridges", Fact::Count(bridges));
        facts.push("one_piece", Fact::Text(if topology.components == 1 { "joined" } else { "not joined" }.into()));
    }
    let mut product = Product {
        fill_mm: fill_triangles(&print),
        paths_mm: stroked_paths(paths, region, settings),
        filled_mm: Region::new(elements),
        mesh_mm: mesh,
        topology: topology.into(),
        timings,
        facts,
        ..Product::default()
    };
    product.region_mm = print;
    Ok(product)
}

/// Steps per level for predictions, at most: a suggestion must come while
/// the person still looks at what they drew (within 250 ms for a 40 mm
/// window), and starting from patches the synthesis has settled by then
/// (`docs/region-fill.md` compares 5 and 7).
pub const PREDICTION_ITERATIONS: usize = 5;

/// New paths and elements like `exemplar` in `region` (mm) that continue
/// what was `drawn`: the autocomplete's predictions, and the clone's when
/// the exemplar is the source region's paths and shapes. Synthesized over
/// the region's bounds with at most [`PREDICTION_ITERATIONS`] steps per
/// level, cleared of stray fragments, smoothed and clipped to the region.
///
/// ```no_run
/// use tracery_core::DVec2;
/// use tracery_core::control::Control;
/// use tracery_core::region_fill::{CurveExemplar, CurvePath, Drawn, Settings, parse_region, predict};
/// let drawn = CurvePath { points_mm: vec![DVec2::new(5.0, 20.0), DVec2::new(35.0, 20.0)], closed: false };
/// let window = parse_region("rect:40x40").unwrap();
/// let exemplar = CurveExemplar::builtin("waves").unwrap();
/// let drawn = Drawn::paths(vec![drawn]);
/// let predicted = predict(&exemplar, &window, &drawn, &Settings::default(), &Control::default()).unwrap();
/// assert!(!predicted.paths.is_empty());
/// ```
pub fn predict(
    exemplar: &CurveExemplar,
    region: &Region,
    drawn: &Drawn,
    settings: &Settings,
    control: &Control,
) -> Result<Prediction, FillError> {
    let settings = Settings { iterations: settings.iterations.min(PREDICTION_ITERATIONS), ..settings.clone() };
    predict_timed(exemplar, region, drawn, &settings, control, &mut Timings::default())
}

fn predict_timed(
    exemplar: &CurveExemplar,
    region: &Region,
    drawn: &Drawn,
    settings: &Settings,
    control: &Control,
    timings: &mut Timings,
) -> Result<Prediction, FillError> {
    settings.validate()?;
    let scaled;
    let exemplar = if settings.exemplar_scale == 1.0 {
        exemplar
    } else {
        scaled = exemplar.scaled(settings.exemplar_scale);
        &scaled
    };
    // Filled bands are learned as the lines they were drawn along.
    let exemplar = &timings.time("centre_lines", || exemplar.curves(settings.delta_mm));
    exemplar.validate(settings.delta_mm)?;
    check_region(region, settings)?;
    let bounds = region.bounds().ok_or(FillError::EmptyRegion)?;
    // Only what lies within the coarsest neighbourhood of the bounds is context.
    let reach = bounds.inflate(settings.radius_mm() * 4.0);
    let near = |p: &CurvePath| Rect::from_points(p.points_mm.iter().copied()).is_some_and(|b| b.overlaps(&reach));
    let drawn_shapes = &drawn.shapes;
    let drawn: Vec<CurvePath> = drawn.paths.iter().filter(|p| near(p)).cloned().collect();
    // Drawn shapes like an element of the exemplar are that element, in
    // every neighbourhood; other shapes only keep new elements off them.
    let drawn_elements: Vec<PlacedElement> =
        drawn_shapes.iter().filter_map(|s| exemplar.elements.like(s)).filter(|e| reach.contains(e.centre_mm)).collect();
    let Synthesized { paths: mut synthesized, tangents, elements } = timings.time("synthesis", || {
        let fixed = (&drawn[..], &drawn_elements[..]);
        synthesize_oriented(&exemplar.paths, &exemplar.elements, (&bounds, Some(region)), fixed, settings, control)
    })?;
    if synthesized.is_empty() && elements.is_empty() && drawn.is_empty() && drawn_elements.is_empty() {
        return Err(nothing_left(exemplar, &bounds, 1.0, settings));
    }
    // A new path that stops just short of a drawn stroke's end continues it.
    join_drawn_ends(&mut synthesized, &drawn, settings.delta_mm);
    control.check()?;
    let smooth = timings.time("reconstruction", || {
        let radius = settings.radius_mm();
        let learned = SampleGraph::new(&exemplar.paths, settings.delta_mm).map(|g| g.to_paths());
        let limits = FragmentLimits::learn(&learned?, radius, FRAGMENT_FALLBACK_SPACINGS * settings.delta_mm)
            .capped(FRAGMENT_CAP_RADII * radius);
        let inner = bounds.inflate(-radius);
        // Ends near the edge go on past it, and ends on a drawn path join it: neither is loose.
        let on_drawn = |p: DVec2| drawn.iter().any(|d| d.distance_to(p) <= JOIN_TOLERANCE_MM);
        let anchored = |p: DVec2| !(p.cmpgt(inner.min).all() && p.cmplt(inner.max).all()) || on_drawn(p);
        Ok::<_, FillError>(smooth_paths_oriented(&limits.remove_from(synthesized, anchored), &tangents))
    })?;
    // Something was made, and all of it was loose.
    if smooth.is_empty() && elements.is_empty() && drawn.is_empty() && drawn_elements.is_empty() {
        return Err(nothing_left(exemplar, &bounds, 1.0, settings));
    }
    let min_mm = MIN_CLIPPED_SPACINGS * settings.delta_mm;
    let paths = timings.time("clip", || clip_paths(&smooth, region, min_mm));
    // No new line doubles one that was drawn.
    let (paths, along_drawn_cut) = cut_runs_along_drawn(paths, &drawn, settings.delta_mm, min_mm);
    // Where the exemplar's paths never pass through each other, the new
    // ones do not either, nor through what was drawn.
    let (paths, crossings_cut) = if crossings(&exemplar.paths).is_empty() {
        timings.time("crossings", || cut_crossings(paths, &drawn, settings.delta_mm, min_mm))
    } else {
        (paths, 0)
    };
    let elements = timings.time("elements", || {
        elements_within(&exemplar.elements.with_placed(elements), &exemplar.elements, region, drawn_shapes)
    });
    Ok(Prediction { paths, elements, crossings_cut, along_drawn_cut })
}

/// The shapes of `elements` that lie wholly within `region`: an element
/// is whole or absent, never cut by the region's edge. Where the
/// exemplar's elements (`learned`) never overlap, an element overlapping
/// one kept before it, or a shape already `drawn`, goes too: two berries
/// grown into one blob are no element of the exemplar.
fn elements_within(elements: &Elements, learned: &Elements, region: &Region, drawn: &[Polygon]) -> Vec<Polygon> {
    let learned_apart = {
        let shapes = learned.polygons();
        !(0..shapes.len()).any(|a| (a + 1..shapes.len()).any(|b| overlapping(&shapes[a], &shapes[b])))
    };
    let mut kept: Vec<Polygon> = Vec::new();
    for shape in elements.polygons() {
        let alone = Region::new(vec![shape.clone()]);
        let inside = difference(&alone, region).area() <= ELEMENT_OUTSIDE_SHARE * shape.area();
        if inside && !(learned_apart && kept.iter().chain(drawn).any(|k| overlapping(k, &shape))) {
            kept.push(shape);
        }
    }
    kept
}

/// Whether two shapes share area (more than rounding).
fn overlapping(a: &Polygon, b: &Polygon) -> bool {
    let (Some(ba), Some(bb)) = (Rect::from_points(a.outer.iter().copied()), Rect::from_points(b.outer.iter().copied()))
    else {
        return false;
    };
    if !ba.overlaps(&bb) {
        return false;
    }
    let shared = intersection(&Region::new(vec![a.clone()]), &Region::new(vec![b.clone()])).area();
    shared > ELEMENT_OUTSIDE_SHARE * a.area().min(b.area())
}

/// The parts of `paths` inside `region`, less stubs shorter than `min_mm`:
/// bits the region's edge cut off, and short spurs. A short path that
/// joins others at both ends (an arm between two junctions) stays:
/// dropping it would leave its neighbours' ends loose.
fn clip_paths(paths: &[CurvePath], region: &Region, min_mm: f64) -> Vec<CurvePath> {
    let polylines: Vec<_> = paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
    let ends_at = degrees(paths);
    let joined_at_both = |p: &CurvePath| {
        p.free_ends().is_some_and(|ends| ends.iter().all(|&e| ends_at.get(&key(e)).is_some_and(|&n| n >= 2)))
    };
    clip_polylines(&polylines, region)
        .into_iter()
        .map(|(points_mm, closed)| CurvePath { points_mm, closed })
        .filter(|p| p.length_mm() >= min_mm || joined_at_both(p))
        .collect()
}

/// What prints: every path drawn with a round pen and every element filled, cut to the region,
/// united with a frame along the region's edge; with `one_piece`, joined
/// by bridges. Also the number of bridges.
fn print_region(paths: &[CurvePath], elements: &[Polygon], region: &Region, settings: &Settings) -> (Region, usize) {
    let mut strokes: Vec<Region> =
        paths.iter().map(|p| brush_stroke(&p.points_mm, settings.stroke_width_mm, p.closed)).collect();
    strokes.push(Region::new(elements.to_vec()));
    let mut all: Vec<&Region> = strokes.iter().collect();
    let frame = if settings.frame_mm > 0.0 {
        difference(region, &offset(region, -settings.frame_mm))
    } else {
        Region::default()
    };
    all.push(&frame);
    let print = intersection(&union(&all), region);
    if settings.one_piece {
        let (joined, bridges) = join_parts(&print, settings.stroke_width_mm);
        (joined, bridges.len())
    } else {
        (print, 0)
    }
}

/// The paths as a pen draws them, and the frame as closed paths along its
/// middle, as wide as the frame.
fn stroked_paths(paths: Vec<CurvePath>, region: &Region, settings: &Settings) -> Vec<StrokedPath> {
    let mut stroked: Vec<StrokedPath> = paths
        .into_iter()
        .map(|p| StrokedPath { points_mm: p.points_mm, closed: p.closed, width_mm: settings.stroke_width_mm })
        .collect();
    if settings.frame_mm > 0.0 {
        let middle = offset(region, -0.5 * settings.frame_mm);
        stroked.extend(middle.rings().map(|ring| StrokedPath {
            points_mm: ring.clone(),
            closed: true,
            width_mm: settings.frame_mm,
        }));
    }
    stroked
}
