//! The model workspace's middle: the model and the patterns on it; a click
//! on the model adds a point to the selected curve (or starts one).

use egui::Color32;
use glam::DVec3;
use tracery_core::surface::{SurfaceMesh, SurfaceOutput};

use crate::TraceryApp;
use crate::panels::preview_3d::PATTERN_RGBA;
use crate::view3d::{Draw, View3dOutput, view_3d_ui};

/// The model's colour (sRGB).
const MODEL_RGBA: [f32; 4] = [0.62, 0.64, 0.68, 1.0];
/// A band to be cut out of the model, until the object is made (sRGB).
const CARVE_RGBA: [f32; 4] = [0.25, 0.22, 0.22, 1.0];
/// The selected curve's pattern (sRGB).
const SELECTED_RGBA: [f32; 4] = [0.95, 0.62, 0.25, 1.0];

/// Radius of a picked point's mark, points.
const MARK_RADIUS: f32 = 4.0;

/// Where `points_mm` fall on the screen, each with whether the model
/// hides it.
fn marks(out: &View3dOutput, surface: &SurfaceMesh, points_mm: &[[f64; 3]]) -> Vec<(egui::Pos2, bool)> {
    let eye = out.camera.eye_mm.as_dvec3();
    points_mm
        .iter()
        .map(|p| {
            let p = DVec3::from(*p);
            let to_point = p - eye;
            // Hidden when the model is hit before the point (a hair's
            // tolerance, since the point lies on the model).
            let hidden = surface
                .ray_hit(eye, to_point.normalize())
                .is_some_and(|hit| hit.position_mm.distance(eye) < to_point.length() - 1e-3 * surface.size_mm());
            (out.to_screen(p.as_vec3()), hidden)
        })
        .collect()
}

/// The selected curve's picked points over the view, joined in order; those
/// the model hides are drawn faint.
fn points_ui(ui: &egui::Ui, out: &View3dOutput, surface: &SurfaceMesh, points_mm: &[[f64; 3]]) {
    let painter = ui.painter_at(out.response.rect);
    let marks = marks(out, surface, points_mm);
    let line = egui::Stroke::new(1.0, Color32::from_rgba_unmultiplied(90, 150, 240, 140));
    for pair in marks.windows(2) {
        painter.line_segment([pair[0].0, pair[1].0], line);
    }
    for (k, (at, hidden)) in marks.iter().enumerate() {
        // The first point is green: a closed curve returns to it.
        let color = if k == 0 { Color32::from_rgb(80, 200, 120) } else { Color32::from_rgb(90, 150, 240) };
        let (color, outline) =
            if *hidden { (color.gamma_multiply(0.3), Color32::TRANSPARENT) } else { (color, Color32::BLACK) };
        painter.circle(*at, MARK_RADIUS, color, egui::Stroke::new(1.0, outline));
    }
}

/// The guides that are not selected, which have no pattern to show them:
/// each a line through its points, faint where the model hides it.
fn guides_ui(ui: &egui::Ui, out: &View3dOutput, surface: &SurfaceMesh, guides_mm: &[Vec<[f64; 3]>]) {
    let painter = ui.painter_at(out.response.rect);
    let seen = Color32::from_rgb(80, 200, 120);
    for guide in guides_mm {
        for pair in marks(out, surface, guide).windows(2) {
            let color = if pair[0].1 || pair[1].1 { seen.gamma_multiply(0.3) } else { seen };
            painter.line_segment([pair[0].0, pair[1].0], egui::Stroke::new(2.0, color));
        }
    }
}

/// What the view shows: the model with each band and shade on it, each in
/// its colour; or, once a curve is carved, the object itself (the carved
/// openings are only in it), in the model's colour. Embossed bands and
/// shades drawn over the model look as their union does, and drawing both
/// the object and its parts would make their equal depths flicker.
fn model_draws(app: &mut TraceryApp, model_view: &std::sync::Arc<crate::view3d::ViewMesh>) -> Vec<Draw> {
    let carved = app.doc.model.drawn_curves().any(|c| c.surface.output == SurfaceOutput::Carve);
    if let Some(mesh) = app.model_object().filter(|_| carved).and_then(|o| app.caches.view_mesh(&o)) {
        return vec![Draw { mesh, rgba: MODEL_RGBA }];
    }
    let mut draws = vec![Draw { mesh: model_view.clone(), rgba: MODEL_RGBA }];
    for item in &app.doc.model.curves {
        let Some(band) = app.surface_worker.output(item.id).cloned() else { continue };
        let Some(mesh) = app.caches.view_mesh(&band) else { continue };
        let selected = app.selected_surface == Some(item.id);
        let rgba = match (item.surface.output, selected) {
            (_, true) => SELECTED_RGBA,
            (SurfaceOutput::Carve, false) => CARVE_RGBA,
            (SurfaceOutput::Emboss, false) => MODEL_RGBA,
            _ => PATTERN_RGBA,
        };
        draws.push(Draw { mesh, rgba });
    }
    for item in &app.doc.model.shades {
        let Some(shade) = app.shade_worker.output(item.id).cloned() else { continue };
        let Some(mesh) = app.caches.view_mesh(&shade) else { continue };
        let rgba = if app.selected_surface == Some(item.id) { SELECTED_RGBA } else { PATTERN_RGBA };
        draws.push(Draw { mesh, rgba });
    }
    let texture = app.doc.model.texture.on.then(|| app.texture_worker.output(super::TEXTURE).cloned()).flatten();
    if let Some(mesh) = texture.and_then(|t| app.caches.view_mesh(&t)) {
        draws.push(Draw { mesh, rgba: PATTERN_RGBA });
    }
    draws
}

/// The 3D view of the model workspace.
pub fn model_view_ui(app: &mut TraceryApp, ui: &mut egui::Ui) {
    let base = app.doc.model.base.clone();
    let model = match app.caches.model(&app.doc.model, &base) {
        Ok(model) => model,
        Err(e) => {
            ui.centered_and_justified(|ui| ui.colored_label(Color32::from_rgb(220, 60, 60), e));
            return;
        }
    };
    let draws = model_draws(app, &model.view);
    // Framed round the model and the shades over it; not round the bands,
    // whose few millimetres would move the camera at every change.
    let shades = app.doc.model.shades.iter().filter_map(|c| app.shade_worker.output(c.id));
    let frame = shades.filter_map(|p| app.caches.view_mesh(p)).fold(model.view.bounds, |b, m| b.union(&m.bounds));
    let out = view_3d_ui(ui, "model", app.gpu_format, &draws, Some(frame), &mut app.state.model_orbit);
    let guides: Vec<Vec<[f64; 3]>> = (app.doc.model.curves.iter())
        .filter(|c| c.guide && app.selected_surface != Some(c.id))
        .map(|c| c.path_mm())
        .collect();
    guides_ui(ui, &out, &model.surface, &guides);
    let points = app.selected_surface.and_then(|id| app.doc.model.curve(id)).map(|c| c.surface.points_mm.clone());
    points_ui(ui, &out, &model.surface, &points.unwrap_or_default());
    let Some((origin, direction)) = out.clicked_ray else { return };
    let Some(hit) = model.surface.ray_hit(origin.as_dvec3(), direction.as_dvec3()) else {
        app.message = Some(("Click on the model to add a point".into(), false));
        return;
    };
    let id = match app.selected_surface.filter(|id| app.doc.model.curve(*id).is_some()) {
        Some(id) => id,
        None => {
            let id = app.doc.add_surface_curve(&app.state.new_surface_curve);
            app.selected_surface = Some(id);
            id
        }
    };
    if let Some(item) = app.doc.model.curve_mut(id) {
        item.surface.points_mm.push(hit.position_mm.to_array());
        let n = item.surface.points_mm.len();
        let hint = if n < 2 { "; click again for the next point" } else { "" };
        app.message = Some((format!("Curve {id}: point {n} picked{hint}"), false));
    }
}
