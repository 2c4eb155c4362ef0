//! [`trim_to_area`]: long elements, a weave's threads, cut off flat at the
//! edge of a planar area, so the quilt ends on the area's sides instead of
//! threads overhanging it by up to half a swatch. Compact elements (a link,
//! a rivet, a scale) stay whole: half a link is an open ring that would
//! fall out of the mail, and half a rivet a loose crumb.

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use super::Element;
use super::foot::cuboid;
use crate::mesh::{BooleanError, Mesh, difference_solids, is_boolean_solid};

/// An element this many times as long as it is wide, seen from above, is a
/// thread: it is cut at the edge.
pub const THREAD_ASPECT: f64 = 3.0;

/// How far past the area's edge an element may reach and still be left
/// alone, mm: rounding, not overhang.
pub const EDGE_TOLERANCE_MM: f64 = 1e-6;

/// What [`trim_to_area`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EdgeTrimmed {
    /// Threads cut at the edge.
    pub cut: usize,
    /// Pieces of cut threads left out: smaller than `min_volume_mm3`, or
    /// not a solid the booleans take.
    pub crumbs: usize,
}

/// What is kept of one element at the edge: its pieces, whether it was
/// cut, and how many crumbs the cut left.
type TrimmedElement = (Vec<Element>, bool, usize);

/// Cuts every thread (an element at least [`THREAD_ASPECT`] times as long
/// as wide) that reaches past the area from `(0, 0)` to
/// `(width_mm, depth_mm)` off flat at its sides, each side a boolean
/// difference with a box beyond it, so each piece stays closed. Pieces
/// under `min_volume_mm3` are left out. A thread cut in two becomes two
/// elements.
///
/// ```
/// use glam::DVec3;
/// use tracery_core::mesh_quilt::{trim_to_area, tube};
/// // A thread from x = -5 to x = 15 across a 10 mm square, and a short rod
/// // past its corner.
/// let thread = tube(&[DVec3::new(-5.0, 5.0, 1.0), DVec3::new(15.0, 5.0, 1.0)], 0.5, 12, false);
/// let rod = tube(&[DVec3::new(9.0, 9.0, 1.0), DVec3::new(11.0, 11.0, 1.0)], 0.5, 12, false);
/// let mut elements = vec![thread, rod.clone()];
/// let trimmed = trim_to_area(&mut elements, 10.0, 10.0, 0.1).unwrap();
/// assert_eq!(trimmed.cut, 1);
/// assert!(elements[0].is_closed());
/// let (lo, hi) = elements[0].bounds();
/// assert!(lo.x >= -1e-9 && hi.x <= 10.0 + 1e-9);
/// assert!(elements.contains(&rod));
/// ```
pub fn trim_to_area(
    elements: &mut Vec<Element>,
    width_mm: f64,
    depth_mm: f64,
    min_volume_mm3: f64,
) -> Result<EdgeTrimmed, BooleanError> {
    let area = (DVec2::ZERO, DVec2::new(width_mm, depth_mm));
    // Each element is cut on its own, so elements go to every core; the
    // pieces keep the elements' order.
    let trim = |e: Element| -> Result<TrimmedElement, BooleanError> {
        let (lo, hi) = e.bounds();
        let size = (hi - lo).truncate();
        let outside = lo.x < area.0.x - EDGE_TOLERANCE_MM
            || lo.y < area.0.y - EDGE_TOLERANCE_MM
            || hi.x > area.1.x + EDGE_TOLERANCE_MM
            || hi.y > area.1.y + EDGE_TOLERANCE_MM;
        if !outside || size.max_element() < THREAD_ASPECT * size.min_element() {
            return Ok((vec![e], false, 0));
        }
        // Boxes wider than the element on every side, so no face of a box
        // meets one of the element's but the edge it stands for.
        let m = 1.0 + (hi - lo).max_element();
        let (below, above) = (lo.z - m, hi.z + m);
        let beyond = [
            (lo.x < area.0.x, DVec3::new(lo.x - m, lo.y - m, below), DVec3::new(area.0.x, hi.y + m, above)),
            (hi.x > area.1.x, DVec3::new(area.1.x, lo.y - m, below), DVec3::new(hi.x + m, hi.y + m, above)),
            (lo.y < area.0.y, DVec3::new(lo.x - m, lo.y - m, below), DVec3::new(hi.x + m, area.0.y, above)),
            (hi.y > area.1.y, DVec3::new(lo.x - m, area.1.y, below), DVec3::new(hi.x + m, hi.y + m, above)),
        ];
        let mut mesh = e.to_mesh();
        for (_, from, to) in beyond.into_iter().filter(|side| side.0) {
            mesh = difference_solids(&mesh, &cuboid(from, to))?;
        }
        let (pieces, crumbs) = solid_pieces(&mesh, min_volume_mm3);
        Ok((pieces, true, crumbs))
    };
    let results: Vec<Result<TrimmedElement, BooleanError>> =
        std::mem::take(elements).into_par_iter().map(trim).collect();
    let mut trimmed = EdgeTrimmed::default();
    for result in results {
        let (pieces, cut, crumbs) = result?;
        trimmed.cut += usize::from(cut);
        trimmed.crumbs += crumbs;
        elements.extend(pieces);
    }
    Ok(trimmed)
}

/// The parts of `mesh`, a cut element, that are kept: those of at least
/// `min_volume_mm3` that the booleans take as solids; with how many others
/// (crumbs) there were.
pub(super) fn solid_pieces(mesh: &Mesh, min_volume_mm3: f64) -> (Vec<Element>, usize) {
    let (pieces, crumbs): (Vec<Element>, Vec<Element>) =
        Element::from_mesh(mesh).parts().into_iter().filter(|p| !p.triangles.is_empty()).partition(|p| {
            let m = p.to_mesh();
            m.signed_volume() >= min_volume_mm3 && is_boolean_solid(&m)
        });
    (pieces, crumbs.len())
}
