//! The panels around the canvas. Each is a function of the app and a `Ui`,
//! so it can be shown, and snapshot-tested, on its own.

pub mod exemplar_picker;
pub mod files;
pub mod gallery;
pub mod jump_rings;
pub mod preview_3d;
pub mod printer;
pub mod side_panel;
pub mod status;
pub mod top_bar;
