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

/// A region (mm) shaded with `fill_colour` over its `triangles` and outlined
/// in `edge`, one point wide.
pub fn shaded_region(
    painter: &egui::Painter,
    view: &View,
    rect: Rect,
    region: &tracery_core::geom::Region,
    triangles: &[[DVec2; 3]],
    fill_colour: Color32,
    edge: Color32,
) {
    painter.add(fill(view, rect, triangles, fill_colour));
    for ring in region.rings() {
        painter.add(polyline(view, rect, ring, true, Stroke::new(1.0, edge)));
    }
}

/// Textured triangles in world coordinates, tinted (white shows the picture
/// as it is); without a texture, drawn in the tint.
pub fn textured(
    view: &View,
    rect: Rect,
    textured: &tracery_core::product::TexturedMesh,
    texture: Option<egui::TextureId>,
    tint: Color32,
) -> Shape {
    let mut mesh = egui::Mesh::with_texture(texture.unwrap_or_default());
    let size =
        textured.texture.as_ref().map_or(DVec2::ONE, |t| DVec2::new(f64::from(t.width_px), f64::from(t.height_px)));
    for (p, uv) in textured.positions_mm.iter().zip(&textured.uvs_px) {
        let uv = if texture.is_some() { *uv / size } else { DVec2::ZERO };
        mesh.vertices.push(egui::epaint::Vertex {
            pos: view.to_screen(rect, *p),
            uv: egui::pos2(uv.x as f32, uv.y as f32),
            color: tint,
        });
    }
    mesh.indices.extend(textured.triangles.iter().flatten());
    Shape::mesh(mesh)
}

/// Filled triangles in millimetres fitted into `rect` (a thumbnail).
pub fn fill_fitted(rect: Rect, bounds: tracery_core::geom::Rect, triangles: &[[DVec2; 3]], color: Color32) -> Shape {
    let scale = (f64::from(rect.width()) / bounds.width()).min(f64::from(rect.height()) / bounds.height());
    let centre = bounds.center();
    let to_screen = |p: DVec2| {
        let q = (p - centre) * scale;
        rect.center() + egui::vec2(q.x as f32, -q.y as f32)
    };
    let mut mesh = egui::Mesh::default();
    for t in triangles {
        let base = mesh.vertices.len() as u32;
        for p in t {
            mesh.colored_vertex(to_screen(*p), color);
        }
        mesh.add_triangle(base, base + 1, base + 2);
    }
    Shape::mesh(mesh)
}

/// Thin features (red), narrow gaps (blue) and weak bridges (orange): each
/// narrow cross-section drawn across, and a ring where each flaw is
/// narrowest, large enough to find at any zoom. Bridges get no ring: on a
/// fine ornament every seam crosses many, and their rings would hide it.
pub fn print_flaws(painter: &egui::Painter, view: &View, rect: Rect, found: &tracery_core::print::Printability) {
    const THIN: Color32 = Color32::from_rgb(230, 40, 40);
    const GAP: Color32 = Color32::from_rgb(40, 120, 240);
    const BRIDGE: Color32 = Color32::from_rgb(245, 150, 0);
    let ring = |at: DVec2, colour: Color32| {
        painter.circle_stroke(view.to_screen(rect, at), 9.0, Stroke::new(2.0, colour));
    };
    for (flaws, colour) in [(&found.thin_features, THIN), (&found.narrow_gaps, GAP)] {
        for flaw in flaws {
            for [a, b] in &flaw.spans_mm {
                painter.line_segment([view.to_screen(rect, *a), view.to_screen(rect, *b)], Stroke::new(1.5, colour));
            }
            ring(flaw.at_mm, colour);
        }
    }
    for bridge in &found.weak_bridges {
        let [a, b] = bridge.ends_mm;
        painter.line_segment([view.to_screen(rect, a), view.to_screen(rect, b)], Stroke::new(3.0, BRIDGE));
    }
}
