//! Which elements of a quilt over a model stay in the print: those resting
//! on the model, and, where the swatch has elements floating by design
//! (a chain mail's flat rings, held up by the standing links through
//! them), those hanging from an element that rests.

use glam::DVec3;

use super::faces::Faces;
use super::{Element, Swatch};
use crate::surface::SurfaceMesh;

/// How far above the model, mm, a point lies (negative where it is sunk
/// into it), measured along the model's normal at the closest point.
fn height_mm(p: DVec3, surface: &SurfaceMesh) -> f64 {
    let on = surface.closest_point(p.to_array());
    (p - on.position_mm).dot(surface.normal(on.face, on.barycentric))
}

/// How far above the model, mm, the lowest point of `element` lies
/// (negative where it is sunk into it).
fn clearance_mm(element: &Element, surface: &SurfaceMesh) -> f64 {
    element.vertices.iter().map(|&p| height_mm(p, surface)).fold(f64::INFINITY, f64::min)
}

/// Whether some vertex of `element` is sunk at least `depth_mm` into the
/// model: it rests on it.
pub(super) fn rests_on(element: &Element, surface: &SurfaceMesh, depth_mm: f64) -> bool {
    element.vertices.iter().any(|&p| height_mm(p, surface) <= -depth_mm)
}

/// Leaves out of `elements` those that would print loose: an element must
/// sink at least `rest_depth_mm` into `surface`, or, where `swatch` has
/// elements floating by design, float at least half as high over the model
/// as the lowest of those does (they lie `sink_mm` lower in the print than
/// in the swatch) and come within `hold_mm` of an element that rests.
/// Returns how many were left out.
///
/// Merging can lift a resting element off the model (two rivets by the
/// vase's foot, 0.1 and 0.6 mm above it): it would print as a loose body
/// beside the model, or fall off, and is left out. Before floating
/// elements were told apart, every flat ring of chain mail over a model
/// was left out this way, and only its standing links were printed.
pub(super) fn keep_held(
    elements: &mut Vec<Element>,
    surface: &SurfaceMesh,
    swatch: &Swatch,
    sink_mm: f64,
    rest_depth_mm: f64,
    hold_mm: f64,
) -> usize {
    let before = elements.len();
    let rests: Vec<bool> = elements.iter().map(|e| rests_on(e, surface, rest_depth_mm)).collect();
    // Floating by design: as high as the swatch's floating elements, less
    // what lifts or sinks them in merging and the shell.
    let least_float_mm = swatch.least_float_mm().map(|h| 0.5 * (h - sink_mm)).filter(|&h| h > 0.0);
    let hangs: Vec<bool> = match least_float_mm {
        Some(least_mm) => {
            let resting = Faces::new(elements.iter().zip(&rests).filter(|(_, r)| **r).map(|(e, _)| e));
            elements
                .iter()
                .zip(&rests)
                .map(|(e, &rests)| {
                    !rests
                        && clearance_mm(e, surface) >= least_mm
                        && e.vertices.iter().any(|&p| resting.closest_within(p, hold_mm).is_some())
                })
                .collect()
        }
        None => vec![false; elements.len()],
    };
    let mut k = 0;
    elements.retain(|_| {
        let keep = rests[k] || hangs[k];
        k += 1;
        keep
    });
    before - elements.len()
}
