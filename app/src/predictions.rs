//! Autocomplete and clone in a region fill: suggested paths, ghosted on the
//! canvas until the person accepts them (all, or those clicked), or
//! rejects them. Accepted paths become pen strokes, editable as any curve.
//!
//! Autocomplete suggests, after each pen stroke in a fill that is not
//! filled automatically, paths in a window around the stroke that continue
//! what was drawn (like the fill's exemplar). Clone copies what was drawn
//! in a source rectangle to a target rectangle: the source's paths are the
//! exemplar, and the target's own strokes are kept and continued.

use std::sync::Arc;

use tracery_core::DVec2;
use tracery_core::control::Control;
use tracery_core::geom::{Rect, Region, clip_polylines, intersection};
use tracery_core::region_fill::{CurveExemplar, CurvePath, FillError, Settings, predict};

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
    pub drawn: Arc<Vec<CurvePath>>,
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
    type Output = Vec<CurvePath>;
    type Error = FillError;

    fn run(&self, control: &Control) -> Result<Vec<CurvePath>, FillError> {
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
    /// The paths picked for "accept selected", by index.
    pub picked: Vec<usize>,
}

/// The fill with curve `id`, its settings and its region, or why not.
fn fill_of(doc: &Document, caches: &Caches, id: u64) -> Result<(RegionFillItem, Region, Vec<CurvePath>), String> {
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
                    let all: Vec<(Vec<DVec2>, bool)> = drawn.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
                    let paths: Vec<CurvePath> = clip_polylines(&all, &Region::rectangle(source))
                        .into_iter()
                        .map(|(points_mm, closed)| CurvePath { points_mm, closed })
                        .collect();
                    let exemplar = CurveExemplar::from_paths("clone source", paths);
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

    /// The predicted paths, once made.
    pub fn predicted(&self) -> Option<&Arc<Vec<CurvePath>>> {
        self.predictions
            .as_ref()
            .and(self.predictor.output(PREDICTION_ID))
            .filter(|_| !self.predictor.is_stale(PREDICTION_ID))
    }

    /// Picks or unpicks the predicted path within `tolerance_mm` of `p`; returns whether there was one.
    pub fn pick_prediction_at(&mut self, p: DVec2, tolerance_mm: f64) -> bool {
        let Some(paths) = self.predicted().cloned() else { return false };
        let nearest = paths
            .iter()
            .enumerate()
            .map(|(k, path)| (k, path.distance_to(p)))
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

    /// Makes the predicted paths pen strokes (only the picked ones with
    /// `picked_only`), then forgets the predictions.
    pub fn accept_predictions(&mut self, picked_only: bool) {
        let (Some(paths), Some(predictions)) = (self.predicted().cloned(), self.predictions.take()) else {
            self.message = Some(("No predictions to accept yet".into(), true));
            return;
        };
        let pen = PenItem::for_fill(&predictions.job.settings);
        let mut accepted = 0;
        for (k, path) in paths.iter().enumerate() {
            if picked_only && !predictions.picked.contains(&k) {
                continue;
            }
            let Some((points, _)) = stroke_to_control_points(&path.points_mm, ACCEPTED_SPACING_MM, 0.0) else {
                continue;
            };
            self.doc.add_curve(points, path.closed, ModeSettings::Pen(pen.clone()));
            accepted += 1;
        }
        self.predictor.retain(&[]);
        self.message = Some((format!("Accepted {accepted} path(s) as pen strokes"), false));
    }

    /// Forgets the predictions.
    pub fn reject_predictions(&mut self) {
        self.predictions = None;
        self.predictor.retain(&[]);
    }
}
