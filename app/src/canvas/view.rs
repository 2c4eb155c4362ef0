//! The canvas's view: world millimetres (`y` up) to screen points and back.

use egui::{Pos2, Rect, Vec2};
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
        self.points_per_mm = (self.points_per_mm * factor).clamp(MIN_POINTS_PER_MM, MAX_POINTS_PER_MM);
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

/// Most zoomed out, screen points per millimetre.
pub const MIN_POINTS_PER_MM: f32 = 0.2;
/// Most zoomed in, screen points per millimetre.
pub const MAX_POINTS_PER_MM: f32 = 80.0;
