//! Modes as the app shows them: a [`ModeUi`] per mode (its name, its
//! settings UI, its overlays and the job it hands the worker), and the
//! registry of them. Each mode lives in its own file and knows no other.

pub mod pen;
pub mod raster_brush;
pub mod region_fill;
pub mod vector_brush;

use std::sync::Arc;

use egui::{Color32, Stroke};
use tracery_core::Product;
use tracery_core::control::{Control, MaybeCancelled};
use tracery_core::curve::Curve;
use tracery_core::print::{JumpRingError, JumpRings, PrintSettings, add_jump_rings, finish};

use crate::canvas::{View, polyline};
use crate::command::Command;
use crate::document::{Document, DocumentError, ModeSettings};
use crate::solutions::Solutions;
use crate::state::Caches;
use crate::worker::Job;

/// Which overlays the person wants drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OverlayToggles {
    /// The band's edges.
    pub band: bool,
    /// Seams between pieces.
    pub seams: bool,
    /// Where a pattern may not go (the raster brush's fold-overs and avoided areas).
    pub invalid: bool,
}

/// The product's band edges and seams, as the toggles ask.
pub fn band_and_seams_ui(
    painter: &egui::Painter,
    view: &View,
    rect: egui::Rect,
    product: &Product,
    toggles: OverlayToggles,
) {
    if toggles.band {
        for edge in &product.overlays.band_edges_mm {
            let stroke = Stroke::new(1.0, Color32::from_rgba_unmultiplied(90, 140, 230, 120));
            painter.add(polyline(view, rect, edge, false, stroke));
        }
    }
    if toggles.seams {
        for s in &product.overlays.seams_mm {
            painter.line_segment(
                [view.to_screen(rect, s[0]), view.to_screen(rect, s[1])],
                Stroke::new(1.0, Color32::from_rgb(230, 70, 70)),
            );
        }
    }
}

/// What a mode's settings UI may use besides the settings it edits.
pub struct ModeEnv<'a> {
    /// The document (imported exemplars, for pickers).
    pub doc: &'a Document,
    /// Loaded exemplars and their pictures.
    pub caches: &'a mut Caches,
    /// Commands to run once the frame's layout is done (an import, say).
    pub commands: &'a mut Vec<Command>,
}

/// A mode as the app shows it.
pub trait ModeUi: Sync {
    /// Its name in the mode picker.
    fn name(&self) -> &'static str;

    /// The settings a new curve of this mode starts with.
    fn default_settings(&self) -> ModeSettings;

    /// Whether `settings` belong to this mode.
    fn owns(&self, settings: &ModeSettings) -> bool;

    /// The controls for `settings`.
    fn settings_ui(&self, ui: &mut egui::Ui, settings: &mut ModeSettings, env: &mut ModeEnv<'_>);

    /// Drawn over a result on the canvas; by default the product's band
    /// edges and seams.
    fn overlays_ui(
        &self,
        painter: &egui::Painter,
        view: &View,
        rect: egui::Rect,
        product: &Product,
        toggles: OverlayToggles,
    ) {
        band_and_seams_ui(painter, view, rect, product, toggles);
    }

    /// The job that computes a curve's pattern.
    fn job(
        &self,
        curve: &Arc<Curve>,
        settings: &ModeSettings,
        doc: &Document,
        caches: &mut Caches,
    ) -> Result<ModeJob, DocumentError>;
}

/// Whether two shared values are equal: the same pointer first, which is
/// how a job asked for again each frame usually compares (curves and
/// exemplars are immutable once made), then by value.
pub fn same<T: PartialEq + ?Sized>(a: &Arc<T>, b: &Arc<T>) -> bool {
    Arc::ptr_eq(a, b) || a == b
}

/// Every mode, in picker order.
pub static REGISTRY: &[&dyn ModeUi] =
    &[&vector_brush::VectorBrushUi, &raster_brush::RasterBrushUi, &region_fill::RegionFillUi, &pen::PenUi];

/// The mode that owns `settings`.
pub fn mode_ui(settings: &ModeSettings) -> &'static dyn ModeUi {
    REGISTRY.iter().copied().find(|m| m.owns(settings)).unwrap_or(REGISTRY[0])
}

/// A job of any mode, as the worker runs it.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ModeJob {
    /// The vector brush along a curve.
    VectorBrush(vector_brush::VectorBrushJob),
    /// The raster brush along a curve.
    RasterBrush(raster_brush::RasterBrushJob),
    /// A region filled inside a closed curve.
    RegionFill(region_fill::RegionFillJob),
    /// A pen stroke.
    Pen(pen::PenJob),
}

/// Why a job failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum JobError {
    /// The vector brush failed.
    #[error(transparent)]
    VectorBrush(#[from] tracery_core::vector_brush::SynthesisError),
    /// The raster brush failed.
    #[error(transparent)]
    RasterBrush(#[from] tracery_core::raster_brush::RasterError),
    /// The region could not be filled, or the pen stroke drawn.
    #[error(transparent)]
    RegionFill(#[from] tracery_core::region_fill::FillError),
    /// The jump rings could not be added.
    #[error(transparent)]
    JumpRing(#[from] JumpRingError),
    /// A fault in Tracery itself, caught in a worker.
    #[error(transparent)]
    Internal(#[from] tracery_core::control::Internal),
}

impl MaybeCancelled for JobError {
    fn is_cancelled(&self) -> bool {
        match self {
            JobError::VectorBrush(e) => e.is_cancelled(),
            JobError::RasterBrush(e) => e.is_cancelled(),
            JobError::RegionFill(e) => e.is_cancelled(),
            JobError::JumpRing(_) | JobError::Internal(_) => false,
        }
    }
}

impl ModeJob {
    /// Runs the mode.
    pub fn run(&self, control: &Control) -> Result<Product, JobError> {
        match self {
            ModeJob::VectorBrush(job) => Ok(job.run(control)?),
            ModeJob::RasterBrush(job) => Ok(job.run(control)?),
            ModeJob::RegionFill(job) => Ok(job.run(control)?),
            ModeJob::Pen(job) => Ok(job.run()?),
        }
    }

    /// The mode's alternatives for the gallery, the best first (a mode
    /// without alternatives gives its one result).
    pub fn alternatives(&self, control: &Control) -> Result<Vec<Product>, JobError> {
        match self {
            ModeJob::VectorBrush(job) => Ok(job.alternatives(control)?),
            // One result (the app asks no gallery of these; see `ModeSettings::has_alternatives`).
            ModeJob::RasterBrush(_) | ModeJob::RegionFill(_) | ModeJob::Pen(_) => Ok(vec![self.run(control)?]),
        }
    }

    /// The same job asking for the best result rather than an alternative
    /// (so that choosing from the gallery does not compute the gallery again).
    pub fn best(&self) -> ModeJob {
        match self {
            ModeJob::VectorBrush(job) => ModeJob::VectorBrush(job.best()),
            ModeJob::RasterBrush(_) | ModeJob::RegionFill(_) | ModeJob::Pen(_) => self.clone(),
        }
    }
}

/// The gallery of a curve: its mode's alternatives, each with its jump rings
/// and checked against the printer, as the curve's own result is.
#[derive(Clone, Debug, PartialEq)]
pub struct GalleryJob {
    /// The curve's job (asking for the best result).
    pub job: CurveJob,
    /// Whether the curve is a loop (alternatives are compared at every rotation).
    pub closed: bool,
}

impl Job for GalleryJob {
    type Output = Solutions;
    type Error = JobError;

    fn run(&self, control: &Control) -> Result<Solutions, JobError> {
        let CurveJob { mode, jump_rings, print } = &self.job;
        jump_rings.validate(print)?;
        let products = mode
            .alternatives(control)?
            .into_iter()
            .map(|p| Ok(finish(add_jump_rings(p, jump_rings)?, print)))
            .collect::<Result<Vec<Product>, JobError>>()?;
        Ok(Solutions::new(products, self.closed))
    }
}

/// What the worker computes for a curve: its mode's job, then the
/// printability check against the document's printer (shared by every mode).
#[derive(Clone, Debug, PartialEq)]
pub struct CurveJob {
    /// The mode's job.
    pub mode: ModeJob,
    /// Jump rings added to the result.
    pub jump_rings: JumpRings,
    /// The printer the result is checked against (and thickened for).
    pub print: PrintSettings,
}

impl Job for CurveJob {
    type Output = Product;
    type Error = JobError;

    fn run(&self, control: &Control) -> Result<Product, JobError> {
        let product = self.mode.run(control)?;
        self.jump_rings.validate(&self.print)?;
        Ok(finish(add_jump_rings(product, &self.jump_rings)?, &self.print))
    }
}
