//! [`CurveExemplar`]: the curves a fill learns from, built in or read from
//! an SVG drawing.

use std::path::Path;

use super::{BUILTIN_CURVES, CurvePath, FillError, builtin_curves};
use crate::curve::svg_shapes;

/// Largest distance between an exemplar's curves and the polylines they
/// are read as, mm: far below any sample spacing.
pub const EXEMPLAR_TOLERANCE_MM: f64 = 0.01;

/// Most samples an exemplar may have at the finest spacing: enough for a
/// drawing 100 mm square of dense curves at 1.5 mm.
pub const MAX_EXEMPLAR_SAMPLES: usize = 12_000;

/// A named set of curves to learn from.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveExemplar {
    /// A built-in's name, or the file's stem.
    pub name: String,
    /// The curves, mm, `y` up.
    pub paths: Vec<CurvePath>,
}

impl CurveExemplar {
    /// The built-in `name`, or `None`.
    pub fn builtin(name: &str) -> Option<CurveExemplar> {
        builtin_curves(name).map(|paths| CurveExemplar { name: name.to_string(), paths })
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
        let paths: Vec<CurvePath> = svg_shapes(data, EXEMPLAR_TOLERANCE_MM)?
            .into_iter()
            .filter(|s| (s.stroked || s.filled) && s.points_mm.len() >= 2)
            // A fill closes every subpath, with a `Z` or without.
            .map(|s| CurvePath { closed: (s.closed || s.filled) && s.points_mm.len() > 2, points_mm: s.points_mm })
            .filter(|p| p.length_mm() > 0.0)
            .collect();
        if paths.is_empty() {
            return Err(FillError::NoStrokes);
        }
        Ok(CurveExemplar { name: name.into(), paths })
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
        CurveExemplar { name: self.name.clone(), paths }
    }

    /// Checks the exemplar has something to learn from and is not so large
    /// that sampling it at `delta_mm` would take too long.
    pub fn validate(&self, delta_mm: f64) -> Result<(), FillError> {
        let length: f64 = self.paths.iter().map(CurvePath::length_mm).sum();
        if self.paths.is_empty() || length <= 0.0 {
            return Err(FillError::NoStrokes);
        }
        let samples = (length / delta_mm).ceil() as usize;
        if samples > MAX_EXEMPLAR_SAMPLES {
            return Err(FillError::ExemplarTooLarge { samples, max: MAX_EXEMPLAR_SAMPLES });
        }
        Ok(())
    }
}
