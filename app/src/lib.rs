//! Tracery's desktop app and command line.
//!
//! The app ([`TraceryApp`]) holds a [`document::Document`] of curves, each
//! with its mode's settings, and asks a background [`worker::Worker`] for
//! their products; it never synthesizes on the UI thread.

mod app;
pub mod canvas;
pub mod cli;
pub mod command;
mod command_handling;
pub mod dialogs;
pub mod document;
mod files;
pub mod live;
pub mod model;
pub mod modes;
pub mod panels;
pub mod predictions;
pub mod solutions;
pub mod state;
pub mod tools;
pub mod view3d;
pub mod worker;

pub use app::TraceryApp;
pub use tools::Tool;
