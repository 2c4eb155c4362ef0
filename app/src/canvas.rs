//! The drawing canvas: a view in millimetres, strokes, selection and editing.

use egui::{Color32, Pos2, Rect, Sense, Shape, Stroke, Vec2};
use serde::{Deserialize, Serialize};
use tracery_core::DVec2;

/// Pan and zoom of the canvas. World coordinates are millimetres, `y` up.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct View {
    /// World point at the centre of the canvas.
    pub center_mm: [f64; 2],
    /// Screen points per millimetre.
    pub points_per_mm: f32,
}

impl Default for View {
    fn default() -> Self {
        View { center_mm: [0.0, 0.0], points_per_mm: 4.0 }
    }
}

// `to_screen` / `from_screen` are the names egui's own transforms use.
#[allow(clippy::wrong_self_convention)]
impl View {
    /// World (mm) to screen.
    pub fn to_screen(&self, rect: Rect, p: DVec2) -> Pos2 {
        let c = rect.center();
        Pos2::new(
            c.x + ((p.x - self.center_mm[0]) as f32) * self.points_per_mm,
            c.y - ((p.y - self.center_mm[1]) as f32) * self.points_per_mm,
        )
    }

    /// Screen to world (mm).
    pub fn from_screen(&self, rect: Rect, p: Pos2) -> DVec2 {
        let c = rect.center();
        DVec2::new(
            self.center_mm[0] + f64::from((p.x - c.x) / self.points_per_mm),
            self.center_mm[1] - f64::from((p.y - c.y) / self.points_per_mm),
        )
    }

    /// Zooms by `factor` keeping the world point under `anchor` fixed.
    pub fn zoom_at(&mut self, rect: Rect, anchor: Pos2, factor: f32) {
        let before = self.from_screen(rect, anchor);
        self.points_per_mm = (self.points_per_mm * factor).clamp(0.2, 80.0);
        let after = self.from_screen(rect, anchor);
        self.center_mm[0] += before.x - after.x;
        self.center_mm[1] += before.y - after.y;
    }

    /// Moves the view by a screen delta.
    pub fn pan(&mut self, delta: Vec2) {
        self.center_mm[0] -= f64::from(delta.x / self.points_per_mm);
        self.center_mm[1] += f64::from(delta.y / self.points_per_mm);
    }
}

/// Draws the millimetre grid: fine lines every 1, 5 or 10 mm depending on
/// zoom, stronger every 10 times that.
pub fn grid_ui(painter: &egui::Painter, rect: Rect, view: &View, dark: bool) {
    let step =
        [1.0, 5.0, 10.0, 50.0, 100.0].into_iter().find(|s| *s as f32 * view.points_per_mm >= 12.0).unwrap_or(100.0);
    let min = view.from_screen(rect, rect.left_bottom());
    let max = view.from_screen(rect, rect.right_top());
    let (fine, strong) = if dark {
        (Color32::from_gray(38), Color32::from_gray(60))
    } else {
        (Color32::from_gray(232), Color32::from_gray(205))
    };
    let mut x = (min.x / step).floor() * step;
    while x <= max.x {
        let strongline = (x / (step * 10.0)).round() * step * 10.0 == x;
        let sx = view.to_screen(rect, DVec2::new(x, 0.0)).x;
        painter.line_segment(
            [Pos2::new(sx, rect.top()), Pos2::new(sx, rect.bottom())],
            Stroke::new(1.0, if strongline { strong } else { fine }),
        );
        x += step;
    }
    let mut y = (min.y / step).floor() * step;
    while y <= max.y {
        let strongline = (y / (step * 10.0)).round() * step * 10.0 == y;
        let sy = view.to_screen(rect, DVec2::new(0.0, y)).y;
        painter.line_segment(
            [Pos2::new(rect.left(), sy), Pos2::new(rect.right(), sy)],
            Stroke::new(1.0, if strongline { strong } else { fine }),
        );
        y += step;
    }
}

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

/// Distance from `p` to a polyline.
pub fn distance_to(points: &[DVec2], closed: bool, p: DVec2) -> f64 {
    let n = points.len();
    if n == 1 {
        return points[0].distance(p);
    }
    let segments = if closed { n } else { n - 1 };
    (0..segments)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            let t = ((p - a).dot(b - a) / (b - a).length_squared().max(1e-12)).clamp(0.0, 1.0);
            p.distance(a.lerp(b, t))
        })
        .fold(f64::INFINITY, f64::min)
}

/// Turns a raw stroke into control points: evenly spaced, about every
/// `spacing_mm`, and whether it closes into a loop (its end came back near
/// its start, within `close_mm`).
pub fn stroke_to_control_points(raw: &[DVec2], spacing_mm: f64, close_mm: f64) -> Option<(Vec<DVec2>, bool)> {
    let length: f64 = raw.windows(2).map(|w| w[0].distance(w[1])).sum();
    if raw.len() < 2 || length < 3.0 * spacing_mm.min(2.0) {
        return None;
    }
    let closed = raw.len() > 8 && raw[0].distance(*raw.last()?) <= close_mm && length > 4.0 * close_mm;
    let curve = tracery_core::Curve::from_polyline(raw, closed).ok()?;
    let count = ((curve.length() / spacing_mm).round() as usize).max(if closed { 4 } else { 2 });
    let mut points: Vec<DVec2> = (0..=count).map(|k| curve.point(curve.length() * k as f64 / count as f64)).collect();
    if closed {
        points.pop();
    }
    Some((points, closed))
}

/// The canvas's interaction area.
pub fn allocate(ui: &mut egui::Ui) -> (egui::Response, egui::Painter) {
    ui.allocate_painter(ui.available_size(), Sense::click_and_drag())
}
