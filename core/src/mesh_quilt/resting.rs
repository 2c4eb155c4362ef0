//! Which elements of a quilt over a model stay in the print: those resting
//! on the model, and, where the swatch has elements floating by design
//! (a chain mail's flat rings, held up by the standing links through
//! them), those hanging from an element that rests.

use glam::DVec3;

use super::faces::Faces;
use super::zones::boxes_overlap;
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
/// in the swatch), come within `hold_mm` of an element that rests, and, if
/// it is a ring, have such an element pass through its opening.
/// Returns how many were left out.
///
/// Near is not held: of 78 flat rings kept near a resting link on the
/// vase, one had none through it and printed loose (one on the cylinder,
/// the egg and the vase at half scale as well).
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
            let resting: Vec<&Element> = elements.iter().zip(&rests).filter(|(_, r)| **r).map(|(e, _)| e).collect();
            let resting_faces = Faces::new(resting.iter().copied());
            let resting_bounds: Vec<(DVec3, DVec3)> = resting.iter().map(|e| e.bounds()).collect();
            elements
                .iter()
                .zip(&rests)
                .map(|(e, &sunk)| {
                    !sunk
                        && clearance_mm(e, surface) >= least_mm
                        && e.vertices.iter().any(|&p| resting_faces.closest_within(p, hold_mm).is_some())
                        && Hole::of(e).is_none_or(|hole| {
                            let bounds = e.bounds();
                            resting
                                .iter()
                                .zip(&resting_bounds)
                                .any(|(o, &o_bounds)| boxes_overlap(o_bounds, bounds) && hole.threaded_by(o))
                        })
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

/// The opening of a ring: the disk its inner edge bounds.
#[derive(Clone, Copy, Debug)]
struct Hole {
    centre_mm: DVec3,
    normal: DVec3,
    radius_mm: f64,
}

impl Hole {
    /// The hole of `element` if it is a ring: the plane of its two widest
    /// spreads through its centre, and the largest disk there round the
    /// centre that none of its vertices lies within (measured across the
    /// plane). None when the element has no such opening (a rivet, a disk).
    fn of(element: &Element) -> Option<Hole> {
        let (centre_mm, covariance) = element.spread()?;
        let eigen = covariance.self_adjoint_eigen(faer::Side::Lower).ok()?;
        let u = eigen.U();
        let normal = DVec3::new(u[(0, 0)], u[(1, 0)], u[(2, 0)]).normalize_or_zero();
        let across = |v: DVec3| (v - centre_mm).reject_from_normalized(normal).length();
        let radius_mm = element.vertices.iter().map(|&v| across(v)).fold(f64::INFINITY, f64::min);
        let outer_mm = element.vertices.iter().map(|&v| across(v)).fold(0.0, f64::max);
        (radius_mm > 0.25 * outer_mm).then_some(Hole { centre_mm, normal, radius_mm })
    }

    /// Whether an edge of `other` passes through the hole.
    fn threaded_by(&self, other: &Element) -> bool {
        let side = |v: DVec3| (v - self.centre_mm).dot(self.normal);
        other.triangles.iter().any(|t| {
            (0..3).any(|k| {
                let (a, b) = (other.vertices[t[k] as usize], other.vertices[t[(k + 1) % 3] as usize]);
                let (sa, sb) = (side(a), side(b));
                if sa * sb > 0.0 || sa == sb {
                    return false;
                }
                let hit = a + (b - a) * (sa / (sa - sb));
                hit.distance(self.centre_mm) < self.radius_mm
            })
        })
    }
}
