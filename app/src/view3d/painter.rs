//! The 3D view without wgpu (a renderer such as kittest's default one):
//! triangles sorted far to near and painted by egui. Enough for small
//! scenes; larger ones are drawn in part, and say so.

use egui::{Color32, Pos2, Rect, Shape};
use glam::Vec3;

use super::camera::Camera;
use super::gpu::Draw;

/// The most triangles painted this way.
const MAX_PAINTED_TRIANGLES: usize = 60_000;

/// Paints `draws` into `rect`; returns whether all of them fit.
pub fn paint_sorted(painter: &egui::Painter, rect: Rect, camera: &Camera, draws: &[Draw]) -> bool {
    let to_screen = |ndc: Vec3| {
        Pos2::new(rect.center().x + ndc.x * rect.width() / 2.0, rect.center().y - ndc.y * rect.height() / 2.0)
    };
    let light = camera.light_dir();
    let mut triangles: Vec<(f32, [Pos2; 3], Color32)> = Vec::new();
    let mut complete = true;
    for draw in draws {
        let projected: Vec<Vec3> = draw.mesh.positions.iter().map(|&p| camera.project(Vec3::from(p))).collect();
        for t in draw.mesh.indices.chunks_exact(3) {
            if triangles.len() >= MAX_PAINTED_TRIANGLES {
                complete = false;
                break;
            }
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| Vec3::from(draw.mesh.positions[i as usize]));
            let n = (b - a).cross(c - a).normalize_or_zero();
            let to_eye = (camera.eye_mm - a).normalize_or_zero();
            let n = if n.dot(to_eye) < 0.0 { -n } else { n };
            let shade = 0.25 + 0.45 * n.dot(light).max(0.0) + 0.3 * n.dot(to_eye).max(0.0);
            let [r, g, bl, _] = draw.rgba.map(|c| (c * shade * 255.0).clamp(0.0, 255.0) as u8);
            let [pa, pb, pc] = [t[0], t[1], t[2]].map(|i| projected[i as usize]);
            triangles.push(((pa.z + pb.z + pc.z) / 3.0, [pa, pb, pc].map(to_screen), Color32::from_rgb(r, g, bl)));
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
    complete
}
