//! [`CurveExemplar`]: the curves a fill learns from, built in or read from
//! an SVG drawing.

use std::path::Path;

use super::builtin::builtin_strokes;
use super::{BUILTIN_CURVES, CurvePath, Elements, FillError, builtin_shapes, is_element_sized};
use crate::curve::svg_shapes;
use crate::geom::{Polygon, centre_lines, resolve_contours};

/// Largest distance between an exemplar's curves and the polylines they
/// are read as, mm: far below any sample spacing.
pub const EXEMPLAR_TOLERANCE_MM: f64 = 0.01;

/// Most samples an exemplar may have at the finest spacing: enough for a
/// drawing 100 mm square of dense curves at 1.5 mm.
pub const MAX_EXEMPLAR_SAMPLES: usize = 12_000;

/// A filled shape is read as its centre lines when most of it is a band
/// no wider than this many sample spacings: its two outlines would be
/// closer than the sampling can keep apart.
pub const BAND_MAX_WIDTH_SPACINGS: f64 = 1.5;

/// The share of a shape's centre lines that must be band-wide: what is
/// left is corners and junctions, where chords run wider.
const BAND_SHARE: f64 = 0.8;

/// The outlines of a filled shape are resampled this many spacings apart
/// to find its centre lines: fine enough to follow a band's bends.
const CENTRE_LINE_STEP_SPACINGS: f64 = 0.2;

/// A named set of curves to learn from.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveExemplar {
    /// A built-in's name, or the file's stem.
    pub name: String,
    /// The curves, mm, `y` up: stroked paths, and the outlines of filled
    /// shapes.
    pub paths: Vec<CurvePath>,
    /// The filled shapes, whose outlines are among `paths`.
    pub shapes: Vec<FilledShape>,
    /// Discrete elements learned whole, apart from `paths` (made by
    /// [`CurveExemplar::curves`] from the small filled shapes).
    pub elements: Elements,
}

/// A filled shape of an exemplar: one polygon of a filled SVG path.
#[derive(Clone, Debug, PartialEq)]
pub struct FilledShape {
    /// The shape, mm.
    pub polygon: Polygon,
    /// Its rings are `paths[first_path..]` of the exemplar, the outer first.
    pub first_path: usize,
}

impl CurveExemplar {
    /// An exemplar of `paths` alone, with no filled shapes.
    pub fn from_paths(name: impl Into<String>, paths: Vec<CurvePath>) -> CurveExemplar {
        CurveExemplar { name: name.into(), paths, shapes: Vec::new(), elements: Elements::default() }
    }

    /// The same exemplar with filled `shapes` (mm) added, each
    /// polygon's outer ring also among its paths.
    ///
    /// ```
    /// use tracery_core::DVec2;
    /// use tracery_core::geom::disc;
    /// use tracery_core::region_fill::CurveExemplar;
    /// let dots = CurveExemplar::from_paths("dots", vec![])
    ///     .with_shapes(vec![disc(DVec2::ZERO, 1.0, 16), disc(DVec2::new(4.0, 0.0), 1.0, 16)]);
    /// assert_eq!((dots.paths.len(), dots.shapes.len()), (2, 2));
    /// assert_eq!(dots.curves(0.5).elements.kinds.len(), 1, "two dots alike");
    /// ```
    pub fn with_shapes(mut self, shapes: Vec<Polygon>) -> CurveExemplar {
        for polygon in shapes {
            let first_path = self.paths.len();
            self.paths.push(CurvePath { points_mm: polygon.outer.clone(), closed: true });
            self.shapes.push(FilledShape { polygon, first_path });
        }
        self
    }

    /// The built-in `name`, or `None`.
    pub fn builtin(name: &str) -> Option<CurveExemplar> {
        Some(CurveExemplar::from_paths(name, builtin_strokes(name)?).with_shapes(builtin_shapes(name)))
    }

    /// Every subpath of an SVG drawing's stroked paths, and the outline of
    /// each filled shape (a discrete element drawn filled; closed, as fills
    /// are, whether or not it ends with a `Z`), sized in millimetres as `--along svg:` sizes drawings.
    ///
    /// ```
    /// use tracery_core::region_fill::CurveExemplar;
    /// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40">
    ///   <path d="M0,20 Q10,0 20,20 T40,20" fill="none" stroke="black"/></svg>"#;
    /// let e = CurveExemplar::from_svg_data("wave", svg.as_bytes()).unwrap();
    /// assert_eq!(e.paths.len(), 1);
    /// // A filled shape without a `Z` is still a closed outline.
    /// let open_fill = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40"><path d="M0,0 L30,0 L30,30"/></svg>"#;
    /// assert!(CurveExemplar::from_svg_data("fill", open_fill.as_bytes()).unwrap().paths[0].closed);
    /// assert!(CurveExemplar::from_svg_data("empty", br#"<svg xmlns="http://www.w3.org/2000/svg"/>"#).is_err());
    /// ```
    pub fn from_svg_data(name: impl Into<String>, data: &[u8]) -> Result<CurveExemplar, FillError> {
        let svg = svg_shapes(data, EXEMPLAR_TOLERANCE_MM)?;
        let mut paths: Vec<CurvePath> = svg
            .iter()
            .filter(|s| s.stroked && s.points_mm.len() >= 2)
            .map(|s| CurvePath { closed: s.closed && s.points_mm.len() > 2, points_mm: s.points_mm.clone() })
            .filter(|p| p.length_mm() > 0.0)
            .collect();
        // The subpaths of one filled path make its shapes together, by its
        // fill rule: a subpath inside another may be a hole.
        let mut shapes = Vec::new();
        let filled: Vec<_> = svg.iter().filter(|s| s.filled && !s.stroked && s.points_mm.len() > 2).collect();
        for element in filled.chunk_by(|a, b| a.element == b.element) {
            let rings: Vec<_> = element.iter().map(|s| s.points_mm.clone()).collect();
            for polygon in resolve_contours(&rings, element[0].fill_rule).polygons {
                let first_path = paths.len();
                paths.extend(polygon.rings().map(|r| CurvePath { points_mm: r.clone(), closed: true }));
                shapes.push(FilledShape { polygon, first_path });
            }
        }
        if paths.is_empty() {
            return Err(FillError::NoStrokes);
        }
        Ok(CurveExemplar { name: name.into(), paths, shapes, elements: Elements::default() })
    }

    /// The curves the fill learns from at sample spacing `delta_mm`: each
    /// filled shape small enough to sit within a neighbourhood
    /// ([`ELEMENT_MAX_SPACINGS`](super::ELEMENT_MAX_SPACINGS)) is a discrete element, learned whole; one
    /// that is mostly a band no wider than [`BAND_MAX_WIDTH_SPACINGS`]
    /// spacings is read as its centre lines, the line it was drawn along;
    /// other shapes as their outlines.
    ///
    /// ```
    /// use tracery_core::region_fill::CurveExemplar;
    /// // A ring 1 mm wide, filled: at 1.5 mm spacing, one closed centre line.
    /// let svg = br#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="-20 -20 40 40">
    ///   <path fill-rule="evenodd" d="M-10.5,0 A10.5,10.5 0 1 0 10.5,0 A10.5,10.5 0 1 0 -10.5,0 Z M-9.5,0 A9.5,9.5 0 1 0 9.5,0 A9.5,9.5 0 1 0 -9.5,0 Z"/></svg>"#;
    /// let ring = CurveExemplar::from_svg_data("ring", svg).unwrap();
    /// assert_eq!(ring.paths.len(), 2, "two outlines");
    /// let curves = ring.curves(1.5);
    /// assert_eq!(curves.paths.len(), 1);
    /// assert!(curves.paths[0].closed && (curves.paths[0].length_mm() - 20.0 * std::f64::consts::PI).abs() < 1.0);
    /// // At 0.5 mm spacing the two outlines are far enough apart to keep.
    /// assert_eq!(ring.curves(0.5).paths.len(), 2);
    /// // At 5 mm spacing the ring fits within a neighbourhood: an element.
    /// let coarse = ring.curves(5.0);
    /// assert!(coarse.paths.is_empty() && coarse.elements.placed.len() == 1);
    /// ```
    pub fn curves(&self, delta_mm: f64) -> CurveExemplar {
        if self.shapes.is_empty() {
            return self.clone();
        }
        let mut outline = vec![false; self.paths.len()];
        let mut lines = Vec::new();
        let mut elements = self.elements.clone();
        for shape in &self.shapes {
            let rings = shape.polygon.rings().count();
            let span = shape.first_path..(shape.first_path + rings).min(self.paths.len());
            if is_element_sized(&shape.polygon, delta_mm) {
                outline[span].fill(true);
                elements.add(&shape.polygon);
                continue;
            }
            let Some(centre) = centre_lines(&shape.polygon, CENTRE_LINE_STEP_SPACINGS * delta_mm) else { continue };
            if centre.paths.is_empty() || centre.width_at(BAND_SHARE) > BAND_MAX_WIDTH_SPACINGS * delta_mm {
                continue;
            }
            outline[span].fill(true);
            lines.extend(centre.paths.into_iter().map(|(points_mm, closed)| CurvePath { points_mm, closed }));
        }
        let paths =
            self.paths.iter().zip(&outline).filter(|(_, out)| !**out).map(|(p, _)| p.clone()).chain(lines).collect();
        CurveExemplar { elements, ..CurveExemplar::from_paths(self.name.clone(), paths) }
    }

    /// A built-in by name, or an SVG file.
    pub fn load(spec: &str) -> Result<CurveExemplar, FillError> {
        if let Some(e) = CurveExemplar::builtin(spec) {
            return Ok(e);
        }
        let path = Path::new(spec);
        if !path.exists() {
            return Err(FillError::Read {
                path: spec.to_string(),
                message: format!(
                    "no such file, and no built-in curve exemplar of that name ({})",
                    BUILTIN_CURVES.join(", ")
                ),
            });
        }
        let data =
            std::fs::read(path).map_err(|e| FillError::Read { path: spec.to_string(), message: e.to_string() })?;
        let name = path.file_stem().map_or_else(|| spec.to_string(), |s| s.to_string_lossy().into_owned());
        CurveExemplar::from_svg_data(name, &data)
    }

    /// The exemplar drawn `factor` times larger, about the origin.
    ///
    /// ```
    /// use tracery_core::region_fill::CurveExemplar;
    /// let waves = CurveExemplar::builtin("waves").unwrap();
    /// let half = waves.scaled(0.5);
    /// assert!((half.paths[0].length_mm() - 0.5 * waves.paths[0].length_mm()).abs() < 1e-9);
    /// ```
    pub fn scaled(&self, factor: f64) -> CurveExemplar {
        let paths = self
            .paths
            .iter()
            .map(|p| CurvePath { points_mm: p.points_mm.iter().map(|q| *q * factor).collect(), closed: p.closed })
            .collect();
        let shapes = self
            .shapes
            .iter()
            .map(|s| FilledShape { polygon: s.polygon.map_points(|q| q * factor), first_path: s.first_path })
            .collect();
        CurveExemplar { name: self.name.clone(), paths, shapes, elements: self.elements.scaled(factor) }
    }

    /// Checks the exemplar has something to learn from and is not so large
    /// that sampling it at `delta_mm` would take too long.
    pub fn validate(&self, delta_mm: f64) -> Result<(), FillError> {
        let length: f64 = self.paths.iter().map(CurvePath::length_mm).sum();
        if (self.paths.is_empty() || length <= 0.0) && self.elements.is_empty() {
            return Err(FillError::NoStrokes);
        }
        let samples = (length / delta_mm).ceil() as usize + self.elements.placed.len();
        if samples > MAX_EXEMPLAR_SAMPLES {
            return Err(FillError::ExemplarTooLarge { samples, max: MAX_EXEMPLAR_SAMPLES });
        }
        Ok(())
    }
}
