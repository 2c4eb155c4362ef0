//! Tracery's desktop app and command line.
//!
//! The app ([`TraceryApp`]) holds a [`document::Document`] of curves and asks a
//! background [`worker::Worker`] for patterns; it never synthesizes on the UI thread.

mod app;
mod canvas;
pub mod cli;
pub mod dialogs;
pub mod document;
mod files;
mod preview;
pub mod worker;

pub use app::{Tool, TraceryApp};
