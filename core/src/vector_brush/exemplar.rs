//! Exemplars: the ornaments patterns are cut from, and their loading from SVG.
//!
//! # Axes and units
//!
//! An exemplar lives in *exemplar units*, the SVG's user units. `u` runs along
//! the pattern (SVG `x`, to the right) and `v` across it, **up** (SVG `-y`),
//! so that the band's `v` axis is the curve's left normal. After loading, the
//! exemplar is moved so that its bounding box starts at `u = 0` and is centred
//! on `v = 0`.

use std::path::Path;

use glam::DVec2;

use usvg::tiny_skia_path;

use super::ExemplarError;
use crate::geom::flatten::flatten;
use crate::geom::{FillRule, Rect, Region, resolve_contours, union, without_needles};

/// The flattening tolerance is at least this fraction of the drawing's
/// diagonal: on a drawing 50 times wider than high, a tolerance of 1e-3 of
/// its height would otherwise need 50 times the vertices.
const MIN_TOLERANCE_OF_DIAGONAL: f64 = 2e-5;

/// Options for [`Exemplar::from_svg_str`].
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct LoadOptions {
    /// Largest distance between a curve and its flattened polyline, as a
    /// fraction of the drawing's height: the height is fitted to the band,
    /// so the default, 1e-3, is 0.01 mm on a 10 mm band, whatever the
    /// drawing's width. (At least 2e-5 of the diagonal, so that a drawing
    /// far wider than high stays within `max_vertices`.)
    pub relative_tolerance: f64,
    /// Smallest accepted extent of the drawing, in user units.
    pub min_size: f64,
    /// Largest accepted extent of the drawing, in user units.
    pub max_size: f64,
    /// Most vertices accepted after flattening.
    pub max_vertices: usize,
    /// Spikes of an outline narrower than this at their base, as a
    /// fraction of the drawing's height, are dropped, and so are parts and
    /// holes that are nothing but such spikes: 1e-4, a tenth of the
    /// flattening's error, is a micrometre on a 10 mm band.
    pub relative_needle_width: f64,
}

impl Default for LoadOptions {
    fn default() -> Self {
        LoadOptions {
            relative_tolerance: 1e-3,
            min_size: 1e-3,
            max_size: 1e6,
            max_vertices: 200_000,
            relative_needle_width: 1e-4,
        }
    }
}

/// An exemplar: a planar region in exemplar units (see the module docs for axes).
#[derive(Clone, Debug, PartialEq)]
pub struct Exemplar {
    /// A name for people.
    pub name: String,
    /// The filled geometry, clean: polygons with holes, not overlapping.
    pub region: Region,
    /// Bounding box of `region`: `min.x == 0`, centred on `v = 0`.
    pub bounds: Rect,
}

impl Exemplar {
    /// Builds an exemplar from a clean region, moving it to the standard placement.
    pub fn from_region(name: impl Into<String>, region: Region) -> Result<Self, ExemplarError> {
        Self::from_region_with(name, region, &LoadOptions::default())
    }

    fn from_region_with(name: impl Into<String>, region: Region, options: &LoadOptions) -> Result<Self, ExemplarError> {
        let Some(bounds) = region.bounds() else {
            return Err(ExemplarError::ZeroArea);
        };
        let size = bounds.size();
        if !size.is_finite() || size.max_element() > options.max_size || size.max_element() < options.min_size {
            return Err(ExemplarError::AbsurdSize {
                width: size.x,
                height: size.y,
                min: options.min_size,
                max: options.max_size,
            });
        }
        if region.area() <= size.max_element() * size.max_element() * 1e-9 {
            return Err(ExemplarError::ZeroArea);
        }
        for ring in region.rings() {
            if ring.len() < 3 || crate::geom::signed_area(ring).abs() <= 0.0 {
                return Err(ExemplarError::NotSimple("a ring has fewer than three corners or no area".into()));
            }
        }
        let shift = DVec2::new(-bounds.min.x, -bounds.center().y);
        let region = region.translated(shift);
        let bounds = Rect { min: bounds.min + shift, max: bounds.max + shift };
        Ok(Exemplar { name: name.into(), region, bounds })
    }

    /// Loads an exemplar from SVG text.
    ///
    /// Fills are resolved with their fill rule, strokes become their outlines,
    /// transforms and groups are applied, and everything is merged with a
    /// polygon union. Text, images, clip paths and masks are ignored.
    ///
    /// ```
    /// use tracery_core::vector_brush::{Exemplar, LoadOptions};
    /// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 4">
    ///   <path d="M0 0 H10 V4 H0 Z M2 1 H4 V3 H2 Z" fill-rule="evenodd"/>
    /// </svg>"#;
    /// let ex = Exemplar::from_svg_str("frame", svg, &LoadOptions::default()).unwrap();
    /// assert_eq!(ex.region.hole_count(), 1);
    /// assert_eq!(ex.bounds.width(), 10.0);
    /// ```
    pub fn from_svg_str(name: impl Into<String>, svg: &str, options: &LoadOptions) -> Result<Self, ExemplarError> {
        Self::from_svg_data(name, svg.as_bytes(), options)
    }

    /// Loads an exemplar from SVG bytes (see [`Exemplar::from_svg_str`]).
    pub fn from_svg_data(name: impl Into<String>, data: &[u8], options: &LoadOptions) -> Result<Self, ExemplarError> {
        let tree = crate::svg_input::parse(data).map_err(ExemplarError::NotSvg)?;
        let bbox = tree.root().abs_bounding_box();
        let diagonal = f64::from(bbox.width()).hypot(f64::from(bbox.height()));
        if !diagonal.is_finite() || diagonal > options.max_size * 2.0 {
            return Err(ExemplarError::AbsurdSize {
                width: f64::from(bbox.width()),
                height: f64::from(bbox.height()),
                min: options.min_size,
                max: options.max_size,
            });
        }
        // The height is what the band's height is fitted to, so a tolerance
        // relative to it is one in printed millimetres: 1e-3 of a 10 mm band
        // is 0.01 mm, whatever the drawing's width. A floor relative to the
        // diagonal keeps a drawing far wider than high within the vertex cap.
        let height = f64::from(bbox.height());
        let tolerance = (height * options.relative_tolerance).max(diagonal * MIN_TOLERANCE_OF_DIAGONAL).max(1e-9);
        let mut parts = Vec::new();
        let mut painted = false;
        let mut vertices = 0;
        collect_group(tree.root(), tolerance, &mut parts, &mut painted, &mut vertices, options.max_vertices)?;
        if !painted {
            return Err(ExemplarError::NothingFilled);
        }
        let refs: Vec<&Region> = parts.iter().collect();
        let mut region = union(&refs);
        // Where strokes were joined, an outline can run out and back along
        // nearly one line, and a stroke can leave a sliver of no area as a
        // part of its own. A spike far narrower at its base than the
        // flattening's error is not a feature of the drawing, and once bent
        // along a curve it can fold across itself by less than a file can
        // store. Wider tips and cracks, however slender, are the drawing's.
        let needle = height * options.relative_needle_width;
        // A ring that was nothing but such spikes goes with them.
        let kept = |ring: &Vec<DVec2>| ring.len() >= 3 && crate::geom::signed_area(ring).abs() > needle * needle;
        for polygon in &mut region.polygons {
            without_needles(&mut polygon.outer, needle);
            polygon.holes.iter_mut().for_each(|hole| without_needles(hole, needle));
            polygon.holes.retain(kept);
        }
        region.polygons.retain(|p| kept(&p.outer));
        if region.is_empty() {
            return Err(ExemplarError::ZeroArea);
        }
        Self::from_region_with(name, region, options)
    }

    /// Loads an exemplar from an SVG file, named after the file.
    pub fn from_svg_file(path: &Path, options: &LoadOptions) -> Result<Self, ExemplarError> {
        let data = std::fs::read(path).map_err(|source| ExemplarError::Io { path: path.to_path_buf(), source })?;
        let name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "exemplar".into());
        Self::from_svg_data(name, &data, options)
    }

    /// Width along `u`, in exemplar units.
    pub fn width(&self) -> f64 {
        self.bounds.width()
    }

    /// Height along `v`, in exemplar units.
    pub fn height(&self) -> f64 {
        self.bounds.height()
    }
}

fn collect_group(
    group: &usvg::Group,
    tolerance: f64,
    parts: &mut Vec<Region>,
    painted: &mut bool,
    vertices: &mut usize,
    max_vertices: usize,
) -> Result<(), ExemplarError> {
    for node in group.children() {
        match node {
            usvg::Node::Group(g) => collect_group(g, tolerance, parts, painted, vertices, max_vertices)?,
            usvg::Node::Path(path) if path.is_visible() => {
                let transform = path.abs_transform();
                if let Some(fill) = path.fill() {
                    *painted = true;
                    let contours = flatten(path.data(), transform, tolerance);
                    *vertices += contours.iter().map(Vec::len).sum::<usize>();
                    check_vertices(*vertices, max_vertices)?;
                    parts.push(resolve_contours(&contours, fill.rule().into()));
                }
                if let Some(stroke) = path.stroke() {
                    *painted = true;
                    let mut data = path.data().clone();
                    if let Some(dashes) = stroke.dasharray()
                        && let Some(dash) = tiny_skia_path::StrokeDash::new(dashes.to_vec(), stroke.dashoffset())
                    {
                        data = data.dash(&dash, 1.0).unwrap_or(data);
                    }
                    let scale = transform.get_scale();
                    let resolution = (f64::from(scale.0.max(scale.1)) / tolerance).clamp(1.0, 1e4) as f32;
                    if let Some(outline) = data.stroke(&stroke.to_tiny_skia(), resolution) {
                        let contours = flatten(&outline, transform, tolerance);
                        *vertices += contours.iter().map(Vec::len).sum::<usize>();
                        check_vertices(*vertices, max_vertices)?;
                        parts.push(resolve_contours(&contours, FillRule::NonZero));
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}

fn check_vertices(vertices: usize, limit: usize) -> Result<(), ExemplarError> {
    if vertices > limit { Err(ExemplarError::TooComplex { vertices, limit }) } else { Ok(()) }
}
