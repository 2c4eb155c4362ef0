//! Autocomplete and clone in a region fill: suggested paths and elements,
//! ghosted on the canvas until the person accepts them (all, or those
//! clicked), or rejects them. Accepted paths become pen strokes, and
//! accepted elements filled pen shapes, editable as any curve.
//!
//! Autocomplete suggests, after each pen stroke in a fill that is not
//! filled automatically, paths and elements in a window around the stroke
//! that continue what was drawn (like the fill's exemplar). Clone copies
//! what was drawn in a source rectangle to a target rectangle: the
//! source's paths and filled shapes are the exemplar, and what the target
//! holds already is kept and continued.

use std::sync::Arc;

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::geom::{Polygon, Rect, Region, clip_polylines, intersection};
use tracery_core::region_fill::{CurveExemplar, CurvePath, Drawn, FillError, Prediction, Settings, predict};

use crate::document::{ModeSettings, PenItem, RegionFillItem};
use crate::modes::{region_fill, same};
use crate::state::Caches;
use crate::tools::draw::stroke_to_control_points;
use crate::worker::Job;
use crate::{TraceryApp, document::Document};

/// The worker slot of the predictions (there is one set at a time).
pub const PREDICTION_ID: u64 = 0;
/// The side of the square around a new pen stroke that autocomplete fills, mm.
pub const AUTOCOMPLETE_WINDOW_MM: f64 = 40.0;
/// Spacing of the control points an accepted path keeps, mm: close enough
/// to keep a spiral's turns, few enough to edit.
pub const ACCEPTED_SPACING_MM: f64 = 1.5;

/// Suggested paths in a window of a fill.
#[derive(Clone, Debug)]
pub struct PredictJob {
    /// What the paths should look like.
    pub exemplar: Arc<CurveExemplar>,
    /// Where they go, mm: the window cut to the fill's region.
    pub window: Arc<Region>,
    /// What is drawn there already, mm.
    pub drawn: Arc<Drawn>,
    /// The fill's settings.
    pub settings: Settings,
}

impl PartialEq for PredictJob {
    fn eq(&self, other: &Self) -> bool {
        same(&self.exemplar, &other.exemplar)
            && same(&self.window, &other.window)
            && same(&self.drawn, &other.drawn)
            && self.settings == other.settings
    }
}

impl Job for PredictJob {
    type Output = Prediction;
    type Error = FillError;

    fn run(&self, control: &Control) -> Result<Prediction, FillError> {
        predict(&self.exemplar, &self.window, &self.drawn, &self.settings, control)
    }
}

/// Which tool asked for the predictions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PredictionKind {
    /// Around a new pen stroke.
    Autocomplete,
    /// From a source rectangle to a target.
    Clone,
}

/// The predictions on screen: the fill they belong to, the job, and which
/// of its paths the person picked.
#[derive(Clone, Debug)]
pub struct Predictions {
    /// The fill's curve id.
    pub fill: u64,
    /// Autocomplete or clone.
    pub kind: PredictionKind,
    /// The job that makes them.
    pub job: PredictJob,
    /// What was picked for "accept selected", by index: the paths first,
    /// then the elements ([`suggestion`]).
    pub picked: Vec<usize>,
}

/// One suggestion of a prediction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Suggestion<'a> {
    /// A path.
    Path(&'a CurvePath),
    /// An element's shape.
    Element(&'a Polygon),
}

/// Suggestion `k` of `prediction`: its paths, then its elements.
pub fn suggestion(prediction: &Prediction, k: usize) -> Option<Suggestion<'_>> {
    match prediction.paths.get(k) {
        Some(path) => Some(Suggestion::Path(path)),
        None => prediction.elements.get(k - prediction.paths.len()).map(Suggestion::Element),
    }
}

/// How many suggestions `prediction` holds.
pub fn suggestions(prediction: &Prediction) -> usize {
    prediction.paths.len() + prediction.elements.len()
}

/// The fill with curve `id`, its settings and its region, or why not.
fn fill_of(doc: &Document, caches: &Caches, id: u64) -> Result<(RegionFillItem, Region, Drawn), String> {
    let item = doc.curve(id).ok_or("the fill is gone")?;
    let ModeSettings::RegionFill(fill) = &item.mode else { return Err("not a region fill".into()) };
    let outline = caches.smoothed(id).ok_or("the fill's outline is too short")?;
    let region =
        tracery_core::region_fill::region_from_outlines(&[outline.points().to_vec()]).map_err(|e| e.to_string())?;
    Ok((fill.clone(), region, region_fill::drawn_in(outline.points(), doc, caches)))
}

impl TraceryApp {
    /// The fill whose region holds `p`, the last drawn first.
    pub fn fill_at(&self, p: DVec2) -> Option<u64> {
        self.doc.curves.iter().rev().find_map(|c| {
            let outline = self.caches.smoothed(c.id)?;
            (matches!(c.mode, ModeSettings::RegionFill(_)) && tracery_core::geom::ring_contains(outline.points(), p))
                .then_some(c.id)
        })
    }

    /// Adds a pen stroke, as wide as the strokes of the fill it is drawn in;
    /// in a fill not filled automatically, asks for autocomplete around it.
    pub fn add_pen_stroke(&mut self, points: Vec<DVec2>, closed: bool) {
        let fill = points.get(points.len() / 2).and_then(|&p| self.fill_at(p));
        let fill_item = fill.and_then(|id| self.doc.curve(id)).map(|c| c.mode.clone());
        let pen = match &fill_item {
            Some(ModeSettings::RegionFill(f)) => PenItem::for_fill(&f.settings),
            _ => PenItem::default(),
        };
        let bounds = Rect::from_points(points.iter().copied());
        self.doc.add_curve(points, closed, ModeSettings::Pen(pen));
        // The fill stays selected, so its controls and the predictions stay in view.
        self.selected = fill;
        self.caches.refresh_smoothed(&self.doc.curves);
        if let (Some(id), Some(ModeSettings::RegionFill(f)), Some(b)) = (fill, fill_item, bounds)
            && !f.fill_automatically
        {
            let window = Rect::new(
                b.center() - DVec2::splat(0.5 * AUTOCOMPLETE_WINDOW_MM),
                b.center() + DVec2::splat(0.5 * AUTOCOMPLETE_WINDOW_MM),
            );
            self.ask_predictions(id, PredictionKind::Autocomplete, None, &window);
        }
    }

    /// Clones what was drawn in `source` into `target` (both mm), in the fill holding the target's centre.
    pub fn clone_region(&mut self, source: &Rect, target: &Rect) {
        let Some(id) = self.fill_at(target.center()) else {
            self.message = Some(("Clone into a region fill: drag the target inside one".into(), true));
            return;
        };
        self.ask_predictions(id, PredictionKind::Clone, Some(source), target);
    }

    /// Asks for predictions in `window` of fill `id`: like the fill's
    /// exemplar, or with `source`, like what was drawn there.
    fn ask_predictions(&mut self, id: u64, kind: PredictionKind, source: Option<&Rect>, window: &Rect) {
        let result = (|| {
            let (fill, region, drawn) = fill_of(&self.doc, &self.caches, id)?;
            let exemplar = match source {
                None => self.caches.curve_exemplar(&self.doc, &fill.exemplar).map_err(|e| e.to_string())?,
                Some(source) => {
                    let all: Vec<(Vec<DVec2>, bool)> =
                        drawn.paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
                    let source_region = Region::rectangle(source);
                    let paths: Vec<CurvePath> = clip_polylines(&all, &source_region)
                        .into_iter()
                        .map(|(points_mm, closed)| CurvePath { points_mm, closed })
                        .collect();
                    // Shapes are copied whole: those wholly in the source.
                    let shapes: Vec<Polygon> = (drawn.shapes.iter())
                        .filter(|s| s.outer.iter().all(|p| source_region.contains(*p)))
                        .cloned()
                        .collect();
                    let exemplar = CurveExemplar::from_paths("clone source", paths).with_shapes(shapes);
                    exemplar
                        .validate(fill.settings.delta_mm)
                        .map_err(|e| format!("Nothing to clone in the source rectangle: {e}"))?;
                    Arc::new(exemplar)
                }
            };
            let window = intersection(&Region::rectangle(window), &region);
            let mut settings = fill.settings;
            if source.is_some() {
                // What was drawn is in mm already: the clone copies it at its own size.
                settings.exemplar_scale = 1.0;
            }
            let job = PredictJob { exemplar, window: Arc::new(window), drawn: Arc::new(drawn), settings };
            Ok::<_, String>(Predictions { fill: id, kind, job, picked: Vec::new() })
        })();
        match result {
            Ok(predictions) => {
                self.predictions = Some(predictions);
                self.message = None;
            }
            Err(e) => self.message = Some((e, true)),
        }
    }

    /// The predictions, once made.
    pub fn predicted(&self) -> Option<&Arc<Prediction>> {
        self.predictions
            .as_ref()
            .and(self.predictor.output(PREDICTION_ID))
            .filter(|_| !self.predictor.is_stale(PREDICTION_ID))
    }

    /// Picks or unpicks the predicted path within `tolerance_mm` of `p`, or
    /// the element there; returns whether there was one.
    pub fn pick_prediction_at(&mut self, p: DVec2, tolerance_mm: f64) -> bool {
        let Some(prediction) = self.predicted().cloned() else { return false };
        let distance = |k: usize| match suggestion(&prediction, k) {
            Some(Suggestion::Path(path)) => path.distance_to(p),
            Some(Suggestion::Element(shape)) if shape.contains(p) => 0.0,
            Some(Suggestion::Element(shape)) => shape.outline_distance(p),
            None => f64::MAX,
        };
        let nearest = (0..suggestions(&prediction))
            .map(|k| (k, distance(k)))
            .filter(|&(_, d)| d <= tolerance_mm)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let (Some((k, _)), Some(predictions)) = (nearest, self.predictions.as_mut()) else { return false };
        match predictions.picked.iter().position(|&j| j == k) {
            Some(at) => {
                predictions.picked.remove(at);
            }
            None => predictions.picked.push(k),
        }
        true
    }

    /// Makes the predicted paths pen strokes, and the predicted elements
    /// filled pen shapes (only the picked ones with `picked_only`), then
    /// forgets the predictions.
    pub fn accept_predictions(&mut self, picked_only: bool) {
        let (Some(prediction), Some(predictions)) = (self.predicted().cloned(), self.predictions.take()) else {
            self.message = Some(("No predictions to accept yet".into(), true));
            return;
        };
        let pen = PenItem::for_fill(&predictions.job.settings);
        let (mut paths, mut elements) = (0, 0);
        for k in 0..suggestions(&prediction) {
            if picked_only && !predictions.picked.contains(&k) {
                continue;
            }
            match suggestion(&prediction, k) {
                Some(Suggestion::Path(path)) if path.points_mm.len() >= 2 => {
                    // A path too short to space control points along (a
                    // berry's stalk) keeps its own points rather than being lost.
                    let points = stroke_to_control_points(&path.points_mm, ACCEPTED_SPACING_MM, 0.0)
                        .map_or_else(|| path.points_mm.clone(), |(points, _)| points);
                    self.doc.add_curve(points, path.closed, ModeSettings::Pen(pen.clone()));
                    paths += 1;
                }
                Some(Suggestion::Element(shape)) => {
                    // Every corner kept: an element is small, and its shape is what makes it one.
                    let filled = PenItem { filled: true, ..pen.clone() };
                    self.doc.add_curve(shape.outer.clone(), true, ModeSettings::Pen(filled));
                    elements += 1;
                }
                _ => {}
            }
        }
        self.predictor.retain(&[]);
        let shapes = if elements > 0 { format!(" and {elements} element(s) as filled shapes") } else { String::new() };
        self.message = Some((format!("Accepted {paths} path(s) as pen strokes{shapes}"), false));
    }

    /// Forgets the predictions.
    pub fn reject_predictions(&mut self) {
        self.predictions = None;
        self.predictor.retain(&[]);
    }
}
