//! The 3D view: meshes drawn by wgpu through an egui paint callback, with a
//! depth buffer and shading; orbit, pan and zoom; and the ray under a click
//! for picking points on a model.
//!
//! Where the renderer has no wgpu (kittest's default), the same scene is
//! painted by egui instead ([`painter`]).

pub mod camera;
pub mod gpu;
mod painter;
pub mod view_mesh;

use egui::Sense;
use glam::{Vec2, Vec3};

pub use camera::{Camera, Orbit};
pub use gpu::{Draw, Frame3d, Renderer3d, View3dCallback};
pub use view_mesh::{Bounds, ViewMesh};

/// What the view gives back.
pub struct View3dOutput {
    /// The view's response (hovered, clicked...).
    pub response: egui::Response,
    /// The camera it was drawn with.
    pub camera: Camera,
    /// A click that was not a drag: the ray under it (origin mm, unit direction).
    pub clicked_ray: Option<(Vec3, Vec3)>,
}

impl View3dOutput {
    /// Where a point (mm) is drawn on the screen, for marks over the view.
    pub fn to_screen(&self, p_mm: Vec3) -> egui::Pos2 {
        let rect = self.response.rect;
        let n = self.camera.project(p_mm);
        egui::pos2(rect.center().x + n.x * rect.width() / 2.0, rect.center().y - n.y * rect.height() / 2.0)
    }
}

/// Draws `draws` and lets the person orbit (drag), pan (right or middle
/// drag, or shift and drag) and zoom (scroll); a double-click frames the
/// scene again. `target_format` is egui's wgpu target, or `None` to paint
/// without wgpu. The camera frames `frame_bounds`, or all of `draws`.
pub fn view_3d_ui(
    ui: &mut egui::Ui,
    id_salt: &str,
    target_format: Option<eframe::wgpu::TextureFormat>,
    draws: &[Draw],
    frame_bounds: Option<Bounds>,
    orbit: &mut Orbit,
) -> View3dOutput {
    let size = ui.available_size().max(egui::vec2(200.0, 200.0));
    let (rect, response) = ui.allocate_exact_size(size, Sense::click_and_drag());
    // Named for screen readers (and for tests that find the view).
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Canvas, true, "3D view"));
    let bounds = frame_bounds.unwrap_or_else(|| draws.iter().fold(Bounds::EMPTY, |b, d| b.union(&d.mesh.bounds)));
    let aspect = rect.width() / rect.height().max(1.0);
    let camera = orbit.camera(&bounds, aspect);
    let delta = Vec2::new(response.drag_delta().x, response.drag_delta().y);
    let panning = response.dragged_by(egui::PointerButton::Secondary)
        || response.dragged_by(egui::PointerButton::Middle)
        || (response.dragged_by(egui::PointerButton::Primary) && ui.input(|i| i.modifiers.shift));
    if panning {
        orbit.pan(&camera, delta, rect.height());
    } else if response.dragged_by(egui::PointerButton::Primary) {
        orbit.turn(delta);
    }
    if response.hovered() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            orbit.zoom_by((scroll * 0.002).exp());
        }
    }
    if response.double_clicked() {
        *orbit = Orbit { yaw: orbit.yaw, pitch: orbit.pitch, ..Orbit::default() };
    }
    // Input changed the camera: draw with the new one.
    let camera = orbit.camera(&bounds, aspect);
    let ndc = |p: egui::Pos2| {
        Vec2::new((p.x - rect.center().x) / (rect.width() / 2.0), (rect.center().y - p.y) / (rect.height() / 2.0))
    };
    let clicked_ray = response.clicked().then(|| response.interact_pointer_pos()).flatten().map(|p| camera.ray(ndc(p)));

    let painter = ui.painter_at(rect);
    let background = ui.visuals().extreme_bg_color;
    painter.rect_filled(rect, 4.0, background);
    if draws.is_empty() {
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            "Nothing to show yet",
            Default::default(),
            ui.visuals().weak_text_color(),
        );
        return View3dOutput { response, camera, clicked_ray };
    }
    let mut note = "drag to orbit · right-drag to pan · scroll to zoom";
    match target_format {
        Some(target_format) => {
            let ppp = ui.ctx().pixels_per_point();
            let frame = Frame3d {
                view_id: egui::Id::unique(id_salt).value(),
                size_px: [(rect.width() * ppp).round() as u32, (rect.height() * ppp).round() as u32],
                clip_from_world: camera.clip_from_world,
                eye_mm: camera.eye_mm,
                light: camera.light_dir(),
                background: background.to_array().map(|c| f32::from(c) / 255.0),
                draws: draws.to_vec(),
                antialias: !response.dragged(),
            };
            painter.add(eframe::egui_wgpu::Callback::new_paint_callback(rect, View3dCallback { frame, target_format }));
        }
        None => {
            if !painter::paint_sorted(&painter, rect, &camera, draws) {
                note = "too many triangles to paint without wgpu: part of the scene is shown";
            }
        }
    }
    painter.text(
        rect.left_bottom() + egui::vec2(6.0, -6.0),
        egui::Align2::LEFT_BOTTOM,
        note,
        egui::FontId::proportional(11.0),
        ui.visuals().weak_text_color(),
    );
    View3dOutput { response, camera, clicked_ray }
}
