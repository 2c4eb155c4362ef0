//! The jobs of the model workspace: each curve's band (the vector brush
//! along it, laid on the surface and checked for printing), and the
//! object (every band united with the model once, or cut out of it).

use std::sync::Arc;

use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::print::{PrintSettings, check_solid};
use tracery_core::surface::{AssemblyError, PartRole, ShadeSettings, SurfaceMesh, SurfaceSettings, assemble_products};
use tracery_core::vector_brush::{
    Exemplar, Settings, ShadeSynthesisError, SurfaceSynthesisError, make_band_on_surface, make_shade,
};

use crate::modes::same;
use crate::worker::Job;

/// A pattern along a curve on the model, as a band before it is united
/// with the model or cut out of it (see [`AssemblyJob`]).
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
        let product = make_band_on_surface(&self.exemplar, &self.surface, &self.drawn, &self.settings, control)?;
        Ok(check_solid(product, &self.print, self.settings.thickness_mm))
    }
}

/// A lamp shade on the model's axis.
#[derive(Clone, Debug)]
pub struct ShadeJob {
    /// The exemplar of its rows.
    pub exemplar: Arc<Exemplar>,
    /// The vector brush's settings.
    pub settings: Settings,
    /// The shade's shape and rows.
    pub shade: ShadeSettings,
    /// Height of its bottom rim, mm.
    pub lift_mm: f64,
    /// The printer the result is checked against.
    pub print: PrintSettings,
}

impl PartialEq for ShadeJob {
    fn eq(&self, other: &Self) -> bool {
        self.settings == other.settings
            && self.shade == other.shade
            && self.lift_mm == other.lift_mm
            && self.print == other.print
            && same(&self.exemplar, &other.exemplar)
    }
}

impl Job for ShadeJob {
    type Output = Product;
    type Error = ShadeSynthesisError;

    fn run(&self, control: &Control) -> Result<Product, ShadeSynthesisError> {
        let mut product = make_shade(&self.exemplar, &self.shade, &self.settings, control)?;
        if let Some(mesh) = &mut product.mesh_mm {
            for v in &mut mesh.vertices {
                v[2] += self.lift_mm;
            }
        }
        Ok(check_solid(product, &self.print, self.settings.thickness_mm))
    }
}

/// The assembly worker's one slot.
pub const ASSEMBLY: u64 = 0;

/// The object made of every finished band on the model: what the view
/// shows once it is ready, and what is exported.
#[derive(Clone)]
pub struct AssemblyJob {
    /// The model.
    pub surface: Arc<SurfaceMesh>,
    /// Each band (a curve job's output) and what it does to the model.
    pub parts: Vec<(Arc<Product>, PartRole)>,
    /// Whether the object holds the model even where no band is embossed.
    pub with_model: bool,
}

impl PartialEq for AssemblyJob {
    fn eq(&self, other: &Self) -> bool {
        // A band is the same band while its job's output is the same `Arc`.
        Arc::ptr_eq(&self.surface, &other.surface)
            && self.with_model == other.with_model
            && self.parts.len() == other.parts.len()
            && self.parts.iter().zip(&other.parts).all(|(a, b)| Arc::ptr_eq(&a.0, &b.0) && a.1 == b.1)
    }
}

impl Job for AssemblyJob {
    type Output = Product;
    type Error = AssemblyError;

    fn run(&self, _control: &Control) -> Result<Product, AssemblyError> {
        let parts: Vec<(&Product, PartRole)> = self.parts.iter().map(|(p, role)| (p.as_ref(), *role)).collect();
        assemble_products(Some(&self.surface), self.with_model, &parts)
    }
}
