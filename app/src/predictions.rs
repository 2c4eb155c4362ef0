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
use tracery_core::region_fill::{
    CurveExemplar, CurvePath, Drawn, FillError, Prediction, Settings, corner_vertices, predict,
};

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

/// How far either side of a vertex a path's turn is measured to find its
/// corners, mm.
const CORNER_REACH_MM: f64 = 0.5;

/// A vertex where an accepted path turns by more than this (radians, about
/// 30°, within [`CORNER_REACH_MM`] either side) keeps a control point. Lower
/// than the synthesis's [`tracery_core::region_fill::CORNER_TURN`]: a stalk leaving its stem at 45°
/// is a corner to keep, and a control point on a vertex of a smooth turn
/// (a spiral's centre) costs nothing.
const ACCEPTED_CORNER_TURN: f64 = 0.5;

/// The control points an accepted path keeps: about every
/// [`ACCEPTED_SPACING_MM`], and on every corner sharper than
/// [`ACCEPTED_CORNER_TURN`], so that where a stalk turns onto its stem, or a fret's
/// key turns, the pen stroke turns too. Spaced evenly alone, the points
/// stepped over such corners, and the accepted stroke rounded a stalk's V
/// into a U. A piece too short to space points along (a berry's stalk)
/// keeps its own points rather than being lost.
pub fn accepted_control_points(path: &CurvePath) -> Vec<DVec2> {
    let points = &path.points_mm;
    let corners = corner_vertices(path, CORNER_REACH_MM, ACCEPTED_CORNER_TURN);
    // Each piece keeps both its ends, even one that comes back to its start
    // (which `stroke_to_control_points` reads as a loop and drops).
    let spaced = |piece: &[DVec2]| match stroke_to_control_points(piece, ACCEPTED_SPACING_MM, 0.0) {
        Some((mut spaced, closed)) => {
            if closed {
                spaced.push(spaced[0]);
            }
            spaced
        }
        None => piece.to_vec(),
    };
    // Cut at the corners: a loop from its first corner (or its start) round
    // to it again.
    let (along, stops): (Vec<DVec2>, Vec<usize>) = if path.closed {
        let first = corners.first().copied().unwrap_or(0);
        let along = points[first..].iter().chain(&points[..=first]).copied().collect();
        let mut stops: Vec<usize> = corners.iter().map(|&c| c - first).collect();
        if stops.is_empty() {
            stops.push(0);
        }
        stops.push(points.len());
        (along, stops)
    } else {
        let stops = std::iter::once(0).chain(corners).chain(std::iter::once(points.len() - 1)).collect();
        (points.clone(), stops)
    };
    let mut out: Vec<DVec2> = Vec::new();
    for w in stops.windows(2) {
        let piece = spaced(&along[w[0]..=w[1]]);
        let skip = usize::from(!out.is_empty());
        out.extend(piece.into_iter().skip(skip));
    }
    // A loop's last point is its first again.
    if path.closed && out.len() > 3 && out[0].distance(out[out.len() - 1]) <= 1e-9 {
        out.pop();
    }
    out
}

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
                    self.doc.add_curve(accepted_control_points(path), path.closed, ModeSettings::Pen(pen.clone()));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_accepted_path_keeps_its_corners_as_control_points() {
        // A stalk's V: 2.3 mm up to the stem, then 12 mm along it.
        let corner = DVec2::new(2.0, 0.0);
        let v = CurvePath { points_mm: vec![DVec2::new(0.5, 1.7), corner, DVec2::new(14.0, 0.0)], closed: false };
        let points = accepted_control_points(&v);
        assert!(points.contains(&corner), "the corner is lost: {points:?}");
        assert_eq!((points[0], *points.last().unwrap()), (v.points_mm[0], v.points_mm[2]));
        let gaps: Vec<f64> = points.windows(2).map(|w| w[0].distance(w[1])).collect();
        assert!(gaps.iter().all(|&g| g <= 2.0 * ACCEPTED_SPACING_MM), "points too far apart: {gaps:?}");
        // A square loop keeps its four corners, and no point twice.
        let square = CurvePath {
            points_mm: vec![DVec2::ZERO, DVec2::new(8.0, 0.0), DVec2::new(8.0, 8.0), DVec2::new(0.0, 8.0)],
            closed: true,
        };
        let points = accepted_control_points(&square);
        assert!(square.points_mm.iter().all(|c| points.contains(c)), "{points:?}");
        assert!(points.len() >= 16 && points.first() != points.last());
        // A ring has no corner and is spaced evenly all round.
        let ring: Vec<DVec2> =
            (0..90).map(|k| DVec2::from_angle(k as f64 / 90.0 * std::f64::consts::TAU) * 6.0).collect();
        let points = accepted_control_points(&CurvePath { points_mm: ring, closed: true });
        assert!(
            (20..=30).contains(&points.len()) && points[0].distance(*points.last().unwrap()) > 0.5,
            "{}",
            points.len()
        );
    }
}
