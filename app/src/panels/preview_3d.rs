//! The 3D preview: the products' meshes, shaded, orbited by dragging.

use egui::{Color32, Pos2, Sense, Shape};
use serde::{Deserialize, Serialize};
use tracery_core::mesh::Mesh;

/// Camera of the preview.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Orbit {
    /// Rotation about the vertical axis, radians.
    pub yaw: f32,
    /// Tilt, radians.
    pub pitch: f32,
    /// Zoom factor.
    pub zoom: f32,
}

impl Default for Orbit {
    fn default() -> Self {
        Orbit { yaw: 0.6, pitch: 0.9, zoom: 1.0 }
    }
}

/// Draws `meshes` and lets the person orbit with a drag and zoom with the wheel.
pub fn preview_ui(ui: &mut egui::Ui, meshes: &[&Mesh], orbit: &mut Orbit) {
    let size = ui.available_size().max(egui::vec2(200.0, 200.0));
    let (response, painter) = ui.allocate_painter(size, Sense::drag());
    let rect = response.rect;
    if response.dragged() {
        let d = response.drag_delta();
        orbit.yaw -= d.x * 0.01;
        orbit.pitch = (orbit.pitch - d.y * 0.01).clamp(-1.5, 1.5);
    }
    if response.hovered() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        orbit.zoom = (orbit.zoom * (1.0 + scroll * 0.002)).clamp(0.2, 10.0);
    }
    painter.rect_filled(rect, 4.0, ui.visuals().extreme_bg_color);
    let mut min = [f64::INFINITY; 3];
    let mut max = [f64::NEG_INFINITY; 3];
    for m in meshes {
        for v in &m.vertices {
            for k in 0..3 {
                min[k] = min[k].min(v[k]);
                max[k] = max[k].max(v[k]);
            }
        }
    }
    if !min[0].is_finite() {
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            "No pattern yet",
            Default::default(),
            ui.visuals().weak_text_color(),
        );
        return;
    }
    let center = [(min[0] + max[0]) / 2.0, (min[1] + max[1]) / 2.0, (min[2] + max[2]) / 2.0];
    let extent = (0..3).map(|k| max[k] - min[k]).fold(1e-6, f64::max) as f32;
    let scale = 0.8 * rect.width().min(rect.height()) / extent * orbit.zoom;
    let (sy, cy) = orbit.yaw.sin_cos();
    let (sp, cp) = orbit.pitch.sin_cos();
    let project = |v: &[f64; 3]| -> (Pos2, f32) {
        let (x, y, z) = ((v[0] - center[0]) as f32, (v[1] - center[1]) as f32, (v[2] - center[2]) as f32);
        // Yaw about z, then pitch about the screen's x axis.
        let (x1, y1) = (x * cy - y * sy, x * sy + y * cy);
        let (y2, z2) = (y1 * cp - z * sp, y1 * sp + z * cp);
        (Pos2::new(rect.center().x + x1 * scale, rect.center().y - z2 * scale), y2)
    };
    let light = [0.3f32, -0.5, 0.8];
    let norm = (light[0] * light[0] + light[1] * light[1] + light[2] * light[2]).sqrt();
    let mut triangles: Vec<(f32, [Pos2; 3], Color32)> = Vec::new();
    for m in meshes {
        let projected: Vec<(Pos2, f32)> = m.vertices.iter().map(project).collect();
        for t in &m.triangles {
            let [a, b, c] = t.map(|i| projected[i as usize]);
            // Back faces point away: skip them.
            let cross = (b.0 - a.0).x * (c.0 - a.0).y - (b.0 - a.0).y * (c.0 - a.0).x;
            if cross > 0.0 {
                continue;
            }
            let [pa, pb, pc] = t.map(|i| m.vertices[i as usize]);
            let u = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
            let w = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
            let n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt().max(1e-12);
            let lambert = ((n[0] as f32 * light[0] + n[1] as f32 * light[1] + n[2] as f32 * light[2])
                / (len as f32 * norm))
                .abs();
            let shade = (60.0 + 170.0 * lambert) as u8;
            let color = Color32::from_rgb(shade, (f32::from(shade) * 0.85) as u8, (f32::from(shade) * 0.6) as u8);
            triangles.push(((a.1 + b.1 + c.1) / 3.0, [a.0, b.0, c.0], color));
        }
    }
    // Far to near: the nearest triangles are painted last.
    triangles.sort_by(|x, y| y.0.total_cmp(&x.0));
    let mut mesh = egui::Mesh::default();
    for (_, pts, color) in triangles {
        let base = mesh.vertices.len() as u32;
        for p in pts {
            mesh.colored_vertex(p, color);
        }
        mesh.add_triangle(base, base + 1, base + 2);
    }
    painter.with_clip_rect(rect).add(Shape::mesh(mesh));
    painter.text(
        rect.left_bottom() + egui::vec2(6.0, -6.0),
        egui::Align2::LEFT_BOTTOM,
        "drag to orbit, scroll to zoom",
        egui::FontId::proportional(11.0),
        ui.visuals().weak_text_color(),
    );
}

/// The preview panel: the selected curve's solid, or every curve's.
pub fn preview_panel_ui(app: &mut crate::TraceryApp, ui: &mut egui::Ui) {
    ui.label(egui::RichText::new("3D preview").strong());
    let ids: Vec<u64> = match app.selected {
        Some(id) => vec![id],
        None => app.doc.curves.iter().map(|c| c.id).collect(),
    };
    let products: Vec<_> = ids.iter().filter_map(|id| app.worker.output(*id)).cloned().collect();
    let meshes: Vec<&Mesh> = products.iter().filter_map(|p| p.mesh_mm.as_ref()).collect();
    preview_ui(ui, &meshes, &mut app.state.orbit);
}
