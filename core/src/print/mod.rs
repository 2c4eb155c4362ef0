//! Printability: what a nozzle can lay down, checked on the final planar
//! geometry of any mode, and fixed where the person asks.
//!
//! - [`narrow_places`]: local widths by the shrinking-ball method, inside
//!   the material (thin features) and outside it (narrow gaps).
//! - [`check`]: those grouped into flaws with a place and a width, and the
//!   bridges across seams between pieces that are weaker than a limit.
//! - [`thicken`]: thin features grown to the nozzle's width.
//! - [`add_jump_rings`]: rings for hanging a pendant or an earring.
//! - [`finish`]: all of it applied to a [`Product`], with the topology
//!   counted again after thickening.

mod check;
mod edge_grid;
mod jump_ring;
mod settings;
mod thicken;
mod thickness;

pub use check::{Bridge, Flaw, Printability, check};
pub use jump_ring::{JumpRingError, JumpRings, RingAt, add_jump_rings};
pub use settings::{PrintSettings, PrintSettingsError};
pub use thicken::thicken;
pub use thickness::{Narrow, Side, narrow_places};

use crate::Product;
use crate::geom::count_topology;
use crate::mesh::extrude;
use crate::report::Warning;

/// Checks a product against `settings` and, when asked, thickens its thin
/// features, rebuilds its solid and counts its topology again. Products
/// without planar geometry are returned as they are.
///
/// ```
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::print::{PrintSettings, finish};
/// use tracery_core::{DVec2, Product, mesh::extrude};
/// // A 10 mm bar 0.2 mm wide: thinner than a 0.4 mm nozzle.
/// let bar = vec![DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0), DVec2::new(10.0, 0.2), DVec2::new(0.0, 0.2)];
/// let region = Region::new(vec![Polygon { outer: bar, holes: vec![] }]);
/// let product = Product { mesh_mm: Some(extrude(&region, 2.0).unwrap()), region_mm: region, ..Product::default() };
/// let checked = finish(product.clone(), &PrintSettings::default());
/// assert!((checked.printability.unwrap().thinnest_feature_mm.unwrap() - 0.2).abs() < 1e-9);
/// let thick = finish(product, &PrintSettings::default().with_thicken(true));
/// assert!(thick.printability.unwrap().thin_features.is_empty());
/// ```
pub fn finish(mut product: Product, settings: &PrintSettings) -> Product {
    let Some(mesh) = &product.mesh_mm else { return product };
    if product.region_mm.is_empty() {
        return product;
    }
    let thickness_mm = mesh.top_z().max(0.0);
    let seams = product.overlays.seams_mm.clone();
    let mut found = product.timings.time("print check", || check(&product.region_mm, &seams, settings, thickness_mm));
    if settings.thicken && !found.thin_features.is_empty() {
        let before = count_topology(&product.region_mm);
        // Discs joined to other material can leave a new, shorter neck
        // beside them: a few passes settle it.
        let mut thick = product.region_mm.clone();
        let mut checked = found.clone();
        for _ in 0..THICKEN_PASSES {
            thick =
                product.timings.time("thicken", || thicken(&thick, &checked.thin_features, settings.min_width_mm()));
            checked = product.timings.time("print check", || check(&thick, &seams, settings, thickness_mm));
            if checked.thin_features.is_empty() {
                break;
            }
        }
        match product.timings.time("mesh", || extrude(&thick, thickness_mm)) {
            Ok(mesh) => {
                let after = count_topology(&thick);
                if after != before {
                    product.warnings.push(Warning::ThickeningChangedTopology {
                        components: (before.components, after.components),
                        holes: (before.holes, after.holes),
                    });
                }
                let t = &mut product.topology;
                t.components = after.components;
                t.holes = after.holes.saturating_sub(t.loop_openings + t.jump_rings);
                product.fill_mm = mesh.top_faces();
                product.mesh_mm = Some(mesh);
                product.region_mm = thick;
                // The last pass checked the region as it now is.
                found = checked;
                found.thickened = true;
            }
            Err(e) => product.warnings.push(Warning::ThickeningFailed { reason: e.to_string() }),
        }
    }
    warn(product, found, settings)
}

/// Checks a product whose solid is not its region extruded (a shade bent
/// onto a surface), against `settings`: its region is the pattern laid flat
/// without stretching, printed `thickness_mm` thick. Nothing is thickened.
pub fn check_solid(mut product: Product, settings: &PrintSettings, thickness_mm: f64) -> Product {
    if product.region_mm.is_empty() {
        return product;
    }
    let seams = product.overlays.seams_mm.clone();
    let found = product.timings.time("print check", || check(&product.region_mm, &seams, settings, thickness_mm));
    warn(product, found, settings)
}

/// Adds the warnings `found` calls for, and the printability itself.
fn warn(mut product: Product, found: Printability, settings: &PrintSettings) -> Product {
    if let Some(width_mm) = found.thinnest_feature_mm {
        product.warnings.push(Warning::ThinFeatures {
            count: found.thin_features.len(),
            width_mm,
            nozzle_mm: settings.nozzle_mm,
        });
    }
    if let Some(width_mm) = found.narrowest_gap_mm {
        product.warnings.push(Warning::NarrowGaps {
            count: found.narrow_gaps.len(),
            width_mm,
            nozzle_mm: settings.nozzle_mm,
        });
    }
    if let Some(weakest) = found.weak_bridges.first() {
        product.warnings.push(Warning::WeakBridges {
            count: found.weak_bridges.len(),
            width_mm: weakest.width_mm,
            limit_mm: settings.min_bridge_mm(),
        });
    }
    if found.layers < MIN_LAYERS {
        product.warnings.push(Warning::FewLayers { layers: found.layers });
    }
    product.printability = Some(found);
    product
}

/// Thickening passes at most.
const THICKEN_PASSES: usize = 3;

/// Fewer layers than this make a fragile print.
const MIN_LAYERS: f64 = 3.0;
