//! The drawing canvas: view transforms, grid, painting and hit testing, with
//! the tools (see `tools/`) driving what a drag does.

mod grid;
mod paint;
mod view;

pub use grid::grid_ui;
pub use paint::{fill, fill_fitted, polyline, shaded_region};
/// Distance from a point to a polyline (hit testing).
pub use tracery_core::geom::polyline_distance as distance_to;
pub use view::{MAX_POINTS_PER_MM, MIN_POINTS_PER_MM, View};

use egui::{Color32, PointerButton, Sense, Stroke};
use tracery_core::DVec2;
use tracery_core::geom::{Rect, Region, fill_triangles};

use crate::TraceryApp;
use crate::modes;
use crate::predictions::{Suggestion, suggestion, suggestions};
use crate::tools::avoid::painted;
use crate::tools::edit::{EditDrag, PICK_RADIUS_POINTS};
use crate::tools::{Gesture, Tool, draw, pan};

/// Wheel scroll to zoom factor: `exp(scroll * WHEEL_ZOOM)`.
const WHEEL_ZOOM: f32 = 0.0015;
/// Click radius for selecting a curve, in screen points.
const SELECT_RADIUS_POINTS: f64 = 6.0;

/// Areas painted with the avoidance brush.
pub const AVOIDED: Color32 = Color32::from_rgba_premultiplied(110, 20, 20, 60);

/// The clone tool's source rectangle.
pub const CLONE_SOURCE: Color32 = Color32::from_rgb(220, 60, 60);
/// Where predictions go.
pub const PREDICTION_WINDOW: Color32 = Color32::from_rgb(230, 190, 40);
/// Predicted paths, ghosted.
pub const GHOST: Color32 = Color32::from_rgba_premultiplied(40, 110, 230, 110);
/// Predicted paths picked for "accept picked".
pub const PICKED: Color32 = Color32::from_rgb(240, 130, 20);

/// The selected curve's colour.
pub const SELECTION: Color32 = Color32::from_rgb(40, 140, 255);

/// The curve whose smoothed path passes within `tolerance_mm` of `p` (or
/// within half its band), nearest first.
pub fn curve_at(app: &TraceryApp, p: DVec2, tolerance_mm: f64) -> Option<u64> {
    app.doc
        .curves
        .iter()
        .filter_map(|c| {
            let half = 0.5 * c.mode.band_mm();
            let d = distance_to(app.caches.smoothed(c.id)?.points(), false, p);
            (d <= tolerance_mm.max(half)).then_some((d, c.id))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, id)| id)
}

/// The canvas: input for the current tool, then patterns, curves and overlays.
pub fn canvas_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    app.caches.refresh_smoothed(&app.doc.curves);
    let (response, painter) = ui.allocate_painter(ui.available_size(), Sense::click_and_drag());
    let rect = response.rect;
    app.canvas_rect = Some(rect);
    let dark = ui.visuals().dark_mode;
    painter.rect_filled(rect, 0.0, if dark { Color32::from_gray(24) } else { Color32::from_gray(250) });
    grid_ui(&painter, rect, &app.state.view, dark);

    if response.hovered() {
        let (scroll, zoom) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
        if let Some(pointer) = response.hover_pos() {
            let factor = zoom * (scroll * WHEEL_ZOOM).exp();
            if factor != 1.0 {
                app.state.view.zoom_at(rect, pointer, factor);
            }
        }
    }
    handle_gestures(app, ui, &response);
    let view = app.state.view;
    if response.clicked()
        && let Some(p) = response.interact_pointer_pos().map(|p| view.from_screen(rect, p))
    {
        let tolerance_mm = PICK_RADIUS_POINTS / f64::from(view.points_per_mm);
        if app.pick_prediction_at(p, tolerance_mm) {
            // A click on a predicted path picks it for "accept picked".
        } else if app.state.tool == Tool::Clone {
            // With a source, a click places a target of its size there.
            if let Some(source) = app.clone_source {
                let half = 0.5 * source.size();
                app.clone_region(&source, &Rect::new(p - half, p + half));
            }
        } else if app.state.tool == Tool::Ring {
            app.add_jump_ring_at(p);
        } else if app.state.tool == Tool::Avoid {
            app.doc.avoid.push(painted(&draw::Stroke::begin(p), app.state.avoid_width_mm));
        } else {
            app.selected = curve_at(app, p, SELECT_RADIUS_POINTS / f64::from(view.points_per_mm));
        }
    }
    paint_document(app, ui, &painter, rect);
}

/// The areas painted with the avoidance brush, hatched in red, so a person
/// sees them whatever the mode.
fn paint_avoided(app: &mut TraceryApp, painter: &egui::Painter, rect: egui::Rect) {
    if app.doc.avoid.is_empty() {
        return;
    }
    let view = app.state.view;
    let avoided = app.caches.avoided(&app.doc.avoid);
    let edge = Color32::from_rgb(200, 60, 60);
    paint::shaded_region(painter, &view, rect, &avoided.region, &avoided.triangles, AVOIDED, edge);
}

fn handle_gestures(app: &mut TraceryApp, ui: &egui::Ui, response: &egui::Response) {
    let rect = response.rect;
    let view = app.state.view;
    let world = |p: egui::Pos2| view.from_screen(rect, p);
    let pointer = response.interact_pointer_pos();
    let moves = ui.input(moves_this_frame);
    if response.drag_started_by(PointerButton::Middle) || response.drag_started_by(PointerButton::Secondary) {
        app.gesture = Some(Gesture::Pan(pan::Pan));
    } else if response.drag_started_by(PointerButton::Primary)
        // Start where the button went down, not where the drag was recognised.
        && let Some(p) = ui.input(|i| i.pointer.press_origin()).or(pointer).map(world)
    {
        // The moves made before egui saw a drag are the stroke's start.
        let trail = std::mem::take(&mut app.press_trail);
        let stroke_from = |p| {
            let mut stroke = draw::Stroke::begin(p);
            trail.iter().for_each(|&q| stroke.extend(world(q)));
            stroke
        };
        let tolerance_mm = PICK_RADIUS_POINTS / f64::from(view.points_per_mm);
        app.gesture = match app.state.tool {
            Tool::Draw => {
                app.begin_live_stroke();
                Some(Gesture::Stroke(stroke_from(p)))
            }
            Tool::Pan => Some(Gesture::Pan(pan::Pan)),
            // The ring tool acts on clicks only.
            Tool::Ring => None,
            Tool::Avoid => Some(Gesture::Avoid(stroke_from(p))),
            Tool::Pen => Some(Gesture::Pen(stroke_from(p))),
            Tool::Clone => Some(Gesture::Clone(p, p)),
            Tool::Edit => {
                let found =
                    EditDrag::begin(&app.doc, app.selected, p, tolerance_mm, |q| curve_at(app, q, tolerance_mm));
                if let Some(drag) = &found {
                    app.selected = Some(drag.curve());
                }
                found.map(Gesture::Edit)
            }
        };
    }
    if response.dragged() {
        match &mut app.gesture {
            Some(Gesture::Pan(pan)) => pan.drag(&mut app.state.view, response.drag_delta()),
            Some(Gesture::Clone(_, to)) => {
                if let Some(p) = pointer.map(world) {
                    *to = p;
                }
            }
            Some(Gesture::Stroke(stroke) | Gesture::Avoid(stroke) | Gesture::Pen(stroke)) => {
                // Every move of a busy frame, not only where the pointer ended.
                for p in moves.iter().copied().chain(pointer).map(world) {
                    stroke.extend(p);
                }
            }
            Some(Gesture::Edit(drag)) => {
                if let Some(p) = pointer.map(world) {
                    drag.drag(&mut app.doc, p);
                }
            }
            None => {}
        }
    }
    if app.gesture.is_some() || !response.is_pointer_button_down_on() {
        app.press_trail.clear();
    } else {
        app.press_trail.extend_from_slice(&moves);
    }
    if response.drag_stopped() {
        // The moves of the frame the button came up in are the stroke's end.
        if let Some(Gesture::Stroke(stroke) | Gesture::Avoid(stroke) | Gesture::Pen(stroke)) = &mut app.gesture {
            moves.iter().for_each(|&p| stroke.extend(world(p)));
        }
        match app.gesture.take() {
            Some(Gesture::Stroke(stroke)) => {
                if let Some((points, closed)) = stroke.finish(view.points_per_mm) {
                    app.add_curve(points, closed);
                }
            }
            Some(Gesture::Avoid(stroke)) => app.doc.avoid.push(painted(&stroke, app.state.avoid_width_mm)),
            Some(Gesture::Pen(stroke)) => {
                if let Some((points, closed)) = stroke.finish_every(view.points_per_mm, draw::PEN_SPACING_MM) {
                    app.add_pen_stroke(points, closed);
                }
            }
            Some(Gesture::Clone(from, to)) => {
                let dragged = Rect::from_points([from, to]).filter(|r| r.width() > 1.0 && r.height() > 1.0);
                match (dragged, app.clone_source) {
                    (Some(rect), None) => {
                        app.clone_source = Some(rect);
                        app.message = Some(("Now drag or click where the copy goes".into(), false));
                    }
                    (Some(rect), Some(source)) => app.clone_region(&source, &rect),
                    (None, _) => {}
                }
            }
            _ => {}
        }
        app.gesture = None;
    }
}

/// Each place the pointer moved to this frame, in order. A busy frame
/// gets several moves and `interact_pointer_pos` tells only the last, so a
/// stroke drawn from it alone cuts chords across the rest. Where the
/// primary button went down this frame, only the moves after that; where it
/// came up, only the moves before.
fn moves_this_frame(input: &egui::InputState) -> Vec<egui::Pos2> {
    let mut moves = Vec::new();
    for event in &input.events {
        match event {
            egui::Event::PointerButton { button: PointerButton::Primary, pressed: true, .. } => moves.clear(),
            egui::Event::PointerButton { button: PointerButton::Primary, pressed: false, .. } => break,
            egui::Event::PointerMoved(p) => moves.push(*p),
            _ => {}
        }
    }
    moves
}

fn paint_document(app: &mut TraceryApp, ui: &egui::Ui, painter: &egui::Painter, rect: egui::Rect) {
    let view = app.state.view;
    let dark = ui.visuals().dark_mode;
    let ink = if dark { Color32::from_rgb(230, 200, 140) } else { Color32::from_rgb(40, 40, 48) };
    let toggles = modes::OverlayToggles {
        band: app.state.show_band,
        seams: app.state.show_seams,
        invalid: app.state.show_invalid,
    };
    paint_avoided(app, painter, rect);
    for item in &app.doc.curves {
        let selected = app.selected == Some(item.id);
        if let Some(product) = app.worker.output(item.id) {
            let stale = app.worker.is_stale(item.id);
            let color = if stale { ink.gamma_multiply(0.45) } else { ink };
            match &product.textured_mm {
                Some(textured) => {
                    let tint = if stale { Color32::WHITE.gamma_multiply(0.45) } else { Color32::WHITE };
                    let texture = textured.texture.as_ref().map(|t| app.caches.texture(ui.ctx(), t));
                    painter.add(paint::textured(&view, rect, textured, texture, tint));
                }
                None => {
                    painter.add(fill(&view, rect, &product.fill_mm, color));
                }
            }
            modes::mode_ui(&item.mode).overlays_ui(painter, &view, rect, product, toggles);
            if app.state.show_print_flaws
                && let Some(found) = &product.printability
            {
                paint::print_flaws(painter, &view, rect, found);
            }
        }
        if let Some(curve) = app.caches.smoothed(item.id) {
            let color = if selected { SELECTION } else { SELECTION.gamma_multiply(0.43) };
            let width = if selected { 2.0 } else { 1.0 };
            painter.add(polyline(&view, rect, curve.points(), curve.is_closed(), Stroke::new(width, color)));
        }
        if selected && app.state.tool == Tool::Edit {
            for p in item.control_points() {
                painter.circle(view.to_screen(rect, p), 4.0, Color32::WHITE, Stroke::new(1.5, SELECTION));
            }
        }
    }
    if let Some(Gesture::Avoid(stroke)) = &app.gesture {
        let width = (app.state.avoid_width_mm as f32 * view.points_per_mm).max(1.0);
        let mut points: Vec<egui::Pos2> = stroke.points.iter().map(|&p| view.to_screen(rect, p)).collect();
        if points.len() == 1 {
            points.push(points[0]);
        }
        painter.add(egui::Shape::line(points, Stroke::new(width, AVOIDED)));
    }
    predictions_ui(app, painter, rect);
    if let Some(Gesture::Pen(stroke)) = &app.gesture {
        painter.add(polyline(&view, rect, &stroke.points, false, Stroke::new(2.0, ink)));
    }
    if let Some(Gesture::Clone(from, to)) = app.gesture {
        let color = if app.clone_source.is_none() { CLONE_SOURCE } else { PREDICTION_WINDOW };
        painter.rect_stroke(
            egui::Rect::from_two_pos(view.to_screen(rect, from), view.to_screen(rect, to)),
            0.0,
            Stroke::new(1.5, color),
            egui::StrokeKind::Middle,
        );
    }
    if let Some(Gesture::Stroke(stroke)) = &app.gesture {
        if let Some(product) = app.live_output() {
            painter.add(fill(&view, rect, &product.fill_mm, ink.gamma_multiply(0.8)));
        }
        painter.add(polyline(&view, rect, &stroke.points, false, Stroke::new(2.0, SELECTION)));
    }
    painter.text(
        rect.right_bottom() + egui::vec2(-8.0, -8.0),
        egui::Align2::RIGHT_BOTTOM,
        format!("{:.1} px/mm", view.points_per_mm),
        egui::FontId::proportional(11.0),
        ui.visuals().weak_text_color(),
    );
}

/// The predictions, ghosted (picked ones in orange), the window they fill,
/// and the clone tool's source.
fn predictions_ui(app: &TraceryApp, painter: &egui::Painter, rect: egui::Rect) {
    let view = app.state.view;
    if let Some(source) = app.clone_source.filter(|_| app.state.tool == Tool::Clone) {
        paint_rect_mm(painter, &view, rect, &source, CLONE_SOURCE);
    }
    let Some(predictions) = &app.predictions else { return };
    for ring in predictions.job.window.rings() {
        let stroke = Stroke::new(1.0, PREDICTION_WINDOW);
        painter.add(polyline(&view, rect, ring, true, stroke));
    }
    let Some(prediction) = app.predicted() else { return };
    let width = (predictions.job.settings.stroke_width_mm as f32 * view.points_per_mm).max(1.5);
    for k in 0..suggestions(prediction) {
        let color = if predictions.picked.contains(&k) { PICKED } else { GHOST };
        match suggestion(prediction, k) {
            Some(Suggestion::Path(path)) => {
                painter.add(polyline(&view, rect, &path.points_mm, path.closed, Stroke::new(width, color)));
            }
            Some(Suggestion::Element(shape)) => {
                painter.add(fill(&view, rect, &fill_triangles(&Region::new(vec![shape.clone()])), color));
            }
            None => {}
        }
    }
}

/// A rectangle given in mm, outlined.
fn paint_rect_mm(painter: &egui::Painter, view: &View, rect: egui::Rect, r: &Rect, color: Color32) {
    painter.add(polyline(view, rect, &r.corners(), true, Stroke::new(1.5, color)));
}
