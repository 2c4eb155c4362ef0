//! The pan tool (and secondary or middle drags with any tool): the view
//! follows the pointer.

use egui::Vec2;

use crate::canvas::View;

/// A pan in progress.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pan;

impl Pan {
    /// The pointer moved by `delta` screen points.
    pub fn drag(&self, view: &mut View, delta: Vec2) {
        view.pan(delta);
    }
}
