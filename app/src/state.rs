//! What the app remembers between runs ([`Persisted`]) and what it can
//! always compute again ([`Caches`]); the document is autosaved on its own.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use serde::{Deserialize, Serialize};
use tracery_core::curve::Curve;
use tracery_core::export::SvgOptions;
use tracery_core::vector_brush::{Exemplar, SlicingMode};

use crate::canvas::View;
use crate::document::{CurveItem, Document, DocumentError, ExemplarRef, ModeSettings};
use crate::panels::preview_3d::Orbit;
use crate::tools::Tool;

/// Remembered between runs through eframe's storage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Persisted {
    /// Pan and zoom of the canvas.
    pub view: View,
    /// The mode and settings new curves take when nothing is selected.
    pub new_curve: ModeSettings,
    /// What a primary drag does.
    pub tool: Tool,
    /// Draw the band's edges.
    pub show_band: bool,
    /// Draw the seams between pieces.
    pub show_seams: bool,
    /// Show the 3D preview.
    pub show_3d: bool,
    /// Highlight thin features, narrow gaps and weak bridges on the canvas.
    pub show_print_flaws: bool,
    /// Show the selected curve's alternative solutions under the canvas.
    pub show_gallery: bool,
    /// Export only the selected curve.
    pub export_selected_only: bool,
    /// Where "Quick export" writes, for desktops without file dialogs.
    pub export_folder: PathBuf,
    /// What an exported SVG is for (engrave or cut) and the laser's kerf.
    pub svg: SvgOptions,
    /// The 3D preview's camera.
    pub orbit: Orbit,
    /// The project file, once saved or opened.
    pub project_path: Option<PathBuf>,
}

impl Default for Persisted {
    fn default() -> Self {
        Persisted {
            view: View::default(),
            new_curve: ModeSettings::default(),
            tool: Tool::Draw,
            show_band: true,
            show_seams: false,
            show_3d: false,
            show_print_flaws: true,
            show_gallery: true,
            export_selected_only: false,
            export_folder: default_export_folder(),
            svg: SvgOptions::default(),
            orbit: Orbit::default(),
            project_path: None,
        }
    }
}

fn default_export_folder() -> PathBuf {
    std::env::var_os("HOME").map_or_else(|| PathBuf::from("."), |h| PathBuf::from(h).join("Tracery"))
}

/// A drawing of an exemplar for the side panel: filled triangles per piece,
/// and the cut lines.
pub struct ExemplarPicture {
    /// The exemplar's bounds, exemplar units.
    pub bounds: tracery_core::geom::Rect,
    /// Triangles of each piece, exemplar units.
    pub pieces: Vec<Vec<[tracery_core::DVec2; 3]>>,
    /// Cut positions along `u`.
    pub cuts: Vec<f64>,
}

/// A curve smoothed through its control points, and what it was made from.
struct Smoothed {
    points: Vec<[f64; 2]>,
    closed: bool,
    /// Shared with the jobs made from it, so that asking the worker again
    /// each frame neither copies nor compares the dense polyline.
    curve: Option<Arc<Curve>>,
}

/// Everything derived from the document that is kept to avoid recomputing it.
#[derive(Default)]
pub struct Caches {
    exemplars: HashMap<ExemplarRef, Arc<Exemplar>>,
    pictures: HashMap<(ExemplarRef, SlicingMode), Option<ExemplarPicture>>,
    /// Smoothing runs when a curve changes, not on every frame.
    smoothed: HashMap<u64, Smoothed>,
}

impl Caches {
    /// The exemplar a reference names, loaded once.
    pub fn exemplar(&mut self, doc: &Document, r: &ExemplarRef) -> Result<Arc<Exemplar>, DocumentError> {
        if let Some(e) = self.exemplars.get(r) {
            return Ok(e.clone());
        }
        let e = Arc::new(doc.exemplar(r)?);
        self.exemplars.insert(r.clone(), e.clone());
        Ok(e)
    }

    /// The picture of an exemplar cut with `slicing`, made once.
    pub fn picture(&mut self, doc: &Document, r: &ExemplarRef, slicing: SlicingMode) -> Option<&ExemplarPicture> {
        let key = (r.clone(), slicing);
        if !self.pictures.contains_key(&key) {
            let picture = self.exemplar(doc, r).ok().and_then(|e| crate::panels::exemplar_picker::picture(&e, slicing));
            self.pictures.insert(key.clone(), picture);
        }
        self.pictures.get(&key).and_then(Option::as_ref)
    }

    /// Forgets imported exemplars (the document changed under them).
    pub fn forget_imported(&mut self) {
        self.exemplars.retain(|r, _| matches!(r, ExemplarRef::Builtin(_)));
        self.pictures.retain(|(r, _), _| matches!(r, ExemplarRef::Builtin(_)));
    }

    /// Brings the smoothed curves up to date with the document.
    pub fn refresh_smoothed(&mut self, curves: &[CurveItem]) {
        self.smoothed.retain(|id, _| curves.iter().any(|c| c.id == *id));
        for item in curves {
            let fresh = self.smoothed.get(&item.id).is_some_and(|s| s.points == item.points && s.closed == item.closed);
            if !fresh {
                let smoothed =
                    Smoothed { points: item.points.clone(), closed: item.closed, curve: item.curve().map(Arc::new) };
                self.smoothed.insert(item.id, smoothed);
            }
        }
    }

    /// The smoothed curve of item `id`, if it is long enough to be one.
    pub fn smoothed(&self, id: u64) -> Option<&Arc<Curve>> {
        self.smoothed.get(&id).and_then(|s| s.curve.as_ref())
    }
}
