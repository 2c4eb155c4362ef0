//! Drawing world geometry on screen.

use egui::{Color32, Pos2, Rect, Shape, Stroke};
use tracery_core::DVec2;

use super::View;

/// A polyline in world coordinates, drawn on screen.
pub fn polyline(view: &View, rect: Rect, points: &[DVec2], closed: bool, stroke: Stroke) -> Shape {
    let mut pts: Vec<Pos2> = points.iter().map(|&p| view.to_screen(rect, p)).collect();
    if closed && pts.len() > 2 {
        pts.push(pts[0]);
    }
    Shape::line(pts, stroke)
}

/// Filled triangles in world coordinates as one mesh.
pub fn fill(view: &View, rect: Rect, triangles: &[[DVec2; 3]], color: Color32) -> Shape {
    let mut mesh = egui::Mesh::default();
    for t in triangles {
        let base = mesh.vertices.len() as u32;
        for p in t {
            mesh.colored_vertex(view.to_screen(rect, *p), color);
        }
        mesh.add_triangle(base, base + 1, base + 2);
    }
    Shape::mesh(mesh)
}
