//! The millimetre grid.

use egui::{Color32, Pos2, Rect, Stroke};
use tracery_core::DVec2;

use super::View;

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
