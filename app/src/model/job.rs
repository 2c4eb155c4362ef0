//! The job of a curve on the model: the vector brush along it, made into a
//! shell on the surface, embossed or carved, and checked for printing.

use std::sync::Arc;

use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::print::{PrintSettings, check_solid};
use tracery_core::surface::{SurfaceMesh, SurfaceSettings};
use tracery_core::vector_brush::{Exemplar, Settings, SurfaceSynthesisError, make_on_surface};

use crate::modes::same;
use crate::worker::Job;

/// A pattern along a curve on the model.
// Not `Debug`: the model's BVH has no useful text form.
#[derive(Clone)]
pub struct SurfaceJob {
    /// The model (shared with the app's cache; compared by identity).
    pub surface: Arc<SurfaceMesh>,
    /// The exemplar.
    pub exemplar: Arc<Exemplar>,
    /// The vector brush's settings.
    pub settings: Settings,
    /// The curve's points and what is made.
    pub drawn: SurfaceSettings,
    /// The printer the result is checked against.
    pub print: PrintSettings,
}

impl PartialEq for SurfaceJob {
    fn eq(&self, other: &Self) -> bool {
        // A model is loaded once per base: the same model is the same pointer.
        Arc::ptr_eq(&self.surface, &other.surface)
            && self.settings == other.settings
            && self.drawn == other.drawn
            && self.print == other.print
            && same(&self.exemplar, &other.exemplar)
    }
}

impl Job for SurfaceJob {
    type Output = Product;
    type Error = SurfaceSynthesisError;

    fn run(&self, control: &Control) -> Result<Product, SurfaceSynthesisError> {
        let product = make_on_surface(&self.exemplar, &self.surface, &self.drawn, &self.settings, control)?;
        Ok(check_solid(product, &self.print, self.settings.thickness_mm))
    }
}
