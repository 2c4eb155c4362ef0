//! Jump-ring loops: small rings joined to a pattern, at its ends, at its
//! top or at chosen points, so that a pendant or an earring can hang.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::PrintSettings;
use crate::Product;
use crate::geom::{
    OFFSET_ARC_TOLERANCE_MM, Polygon, Region, arc_step, closest_on_segment, count_topology, difference, disc,
    ring_contains, union,
};
use crate::mesh::extrude;
use crate::report::Warning;
use crate::setting::WORLD_EXTENT_MM;

/// The longest stem that joins a ring to the pattern, mm: a longer one
/// would bend and snap, and a ring placed farther is a mistake.
pub const MAX_STEM_MM: f64 = 25.0;

/// Where a jump ring goes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum RingAt {
    /// Beyond the start of an open curve.
    Start,
    /// Beyond the end of an open curve.
    End,
    /// Above the pattern's highest point (a pendant's loop).
    Top,
    /// Centred on a point, mm: the ring is joined to the nearest material.
    Point {
        /// `x`, mm.
        x_mm: f64,
        /// `y`, mm.
        y_mm: f64,
    },
}

/// The jump rings of one pattern.
///
/// ```
/// use tracery_core::print::{JumpRings, PrintSettings, RingAt};
/// let rings = JumpRings::at(vec![RingAt::Top]);
/// assert!(rings.validate(&PrintSettings::default()).is_ok());
/// assert!(JumpRings { hole_mm: 0.2, ..rings }.validate(&PrintSettings::default()).is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct JumpRings {
    /// Where the rings go (none by default).
    pub at: Vec<RingAt>,
    /// The hole's diameter, mm.
    pub hole_mm: f64,
    /// The ring's wall, mm.
    pub wall_mm: f64,
}

impl Default for JumpRings {
    fn default() -> Self {
        JumpRings { at: Vec::new(), hole_mm: 2.5, wall_mm: 1.2 }
    }
}

/// Why jump rings could not be added.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum JumpRingError {
    /// The hole is narrower than a nozzle prints.
    #[error("the jump ring's hole ({hole_mm} mm) must be at least the nozzle's width ({min_mm} mm)")]
    HoleTooSmall {
        /// The hole asked for, mm.
        hole_mm: f64,
        /// The smallest that prints, mm.
        min_mm: f64,
    },
    /// The wall is thinner than a nozzle prints.
    #[error("the jump ring's wall ({wall_mm} mm) must be at least the nozzle's width ({min_mm} mm)")]
    WallTooThin {
        /// The wall asked for, mm.
        wall_mm: f64,
        /// The thinnest that prints, mm.
        min_mm: f64,
    },
    /// A size is absurd.
    #[error("the jump ring's hole and wall must be at most 50 mm")]
    TooLarge,
    /// A ring's point lies off the table.
    #[error("the jump ring at ({x_mm:e}, {y_mm:e}) must lie within {WORLD_EXTENT_MM} mm of the origin (ten metres)")]
    OffTheTable {
        /// `x`, mm.
        x_mm: f64,
        /// `y`, mm.
        y_mm: f64,
    },
    /// A ring's point lies too far from the pattern for a stem to hold it.
    #[error(
        "the jump ring at ({x_mm}, {y_mm}) is {distance_mm:.1} mm from the pattern: put it within {MAX_STEM_MM} mm, where a stem can hold it"
    )]
    TooFar {
        /// `x`, mm.
        x_mm: f64,
        /// `y`, mm.
        y_mm: f64,
        /// From the pattern, mm.
        distance_mm: f64,
    },
    /// A ring at an end of a curve that has none.
    #[error("a loop has no ends: put the jump ring at the top or at a point")]
    NoEnds,
    /// Nothing to join the ring to.
    #[error("there is no pattern to join the jump ring to")]
    NoPattern,
    /// The solid could not be rebuilt.
    #[error("the pattern with its jump rings could not be made solid: {0}")]
    Mesh(String),
}

impl JumpRings {
    /// Rings at `at`, with the default hole and wall.
    pub fn at(at: Vec<RingAt>) -> Self {
        JumpRings { at, ..JumpRings::default() }
    }

    /// Checks the ring prints: hole and wall at least the nozzle's width.
    pub fn validate(&self, print: &PrintSettings) -> Result<(), JumpRingError> {
        let min_mm = print.min_width_mm();
        if self.hole_mm.is_nan() || self.hole_mm < min_mm {
            return Err(JumpRingError::HoleTooSmall { hole_mm: self.hole_mm, min_mm });
        }
        if self.wall_mm.is_nan() || self.wall_mm < min_mm {
            return Err(JumpRingError::WallTooThin { wall_mm: self.wall_mm, min_mm });
        }
        if self.hole_mm > 50.0 || self.wall_mm > 50.0 {
            return Err(JumpRingError::TooLarge);
        }
        for at in &self.at {
            if let RingAt::Point { x_mm, y_mm } = *at
                && !(x_mm.abs() <= WORLD_EXTENT_MM && y_mm.abs() <= WORLD_EXTENT_MM)
            {
                return Err(JumpRingError::OffTheTable { x_mm, y_mm });
            }
        }
        Ok(())
    }
}

/// A disc as a polygon whose chords stay within the offset tolerance.
fn fine_disc(centre: DVec2, radius: f64) -> Polygon {
    let step = arc_step(radius, OFFSET_ARC_TOLERANCE_MM);
    disc(centre, radius, ((std::f64::consts::TAU / step.max(1e-3)).ceil() as usize).clamp(16, 256))
}

/// The point of `region`'s outline nearest to `p`.
fn nearest_outline_point(region: &Region, p: DVec2) -> Option<DVec2> {
    let mut best: Option<(f64, DVec2)> = None;
    for ring in region.rings() {
        for k in 0..ring.len() {
            let (_, q) = closest_on_segment(p, ring[k], ring[(k + 1) % ring.len()]);
            let d = q.distance_squared(p);
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, q));
            }
        }
    }
    best.map(|(_, q)| q)
}

/// Adds the jump rings to a product: each ring (outer disc less its hole)
/// is united with the pattern, with a stem as wide as the wall to the
/// nearest material when the ring does not reach it, and the solid is made
/// again. The rings' holes are counted apart from the pattern's own.
///
/// ```
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::print::{JumpRings, RingAt, add_jump_rings};
/// use tracery_core::{DVec2, Product, mesh::extrude};
/// // A 20 × 10 mm plate, 2 mm thick.
/// let plate = vec![DVec2::new(0.0, 0.0), DVec2::new(20.0, 0.0), DVec2::new(20.0, 10.0), DVec2::new(0.0, 10.0)];
/// let region = Region::new(vec![Polygon { outer: plate, holes: vec![] }]);
/// let mut pendant = Product { mesh_mm: Some(extrude(&region, 2.0).unwrap()), region_mm: region, ..Product::default() };
/// pendant.topology.components = 1;
/// let with_ring = add_jump_rings(pendant.clone(), &JumpRings::at(vec![RingAt::Top])).unwrap();
/// assert_eq!(with_ring.topology.components, pendant.topology.components);
/// assert_eq!(with_ring.topology.jump_rings, 1);
/// assert_eq!(with_ring.topology.holes, pendant.topology.holes);
/// ```
pub fn add_jump_rings(mut product: Product, rings: &JumpRings) -> Result<Product, JumpRingError> {
    if rings.at.is_empty() {
        return Ok(product);
    }
    let Some(mesh) = &product.mesh_mm else { return Err(JumpRingError::NoPattern) };
    if product.region_mm.is_empty() {
        return Err(JumpRingError::NoPattern);
    }
    let thickness_mm = mesh.top_z().max(0.0);
    let inner = 0.5 * rings.hole_mm;
    let outer = inner + rings.wall_mm;
    // Ring centres sit so that the ring's wall overlaps what it hangs from by half.
    let reach = inner + 0.5 * rings.wall_mm;
    let before = count_topology(&product.region_mm);
    let mut centres = Vec::new();
    for at in &rings.at {
        let centre = match *at {
            RingAt::Start | RingAt::End => {
                let [point, away] = match (at, product.path_ends_mm.as_slice()) {
                    (RingAt::Start, [start, _]) => *start,
                    (_, [_, end]) => *end,
                    _ => return Err(JumpRingError::NoEnds),
                };
                point + away.normalize_or_zero() * reach
            }
            RingAt::Top => {
                let top = product.region_mm.rings().flatten().copied().max_by(|a, b| a.y.total_cmp(&b.y));
                top.ok_or(JumpRingError::NoPattern)? + DVec2::Y * reach
            }
            RingAt::Point { x_mm, y_mm } => DVec2::new(x_mm, y_mm),
        };
        centres.push(centre);
    }
    let mut added: Vec<Polygon> = Vec::new();
    let mut holes: Vec<Polygon> = Vec::new();
    for &centre in &centres {
        added.push(fine_disc(centre, outer));
        holes.push(fine_disc(centre, inner));
        if !product.region_mm.contains(centre)
            && let Some(m) = nearest_outline_point(&product.region_mm, centre)
            && m.distance(centre) > outer - 0.5 * rings.wall_mm
        {
            if m.distance(centre) > MAX_STEM_MM + outer {
                return Err(JumpRingError::TooFar {
                    x_mm: centre.x,
                    y_mm: centre.y,
                    distance_mm: m.distance(centre) - outer,
                });
            }
            // A stem from the ring's centre to a little inside the material.
            let dir = (m - centre).normalize_or_zero();
            let side = dir.perp() * (0.5 * rings.wall_mm);
            let end = m + dir * (0.5 * rings.wall_mm);
            added
                .push(Polygon { outer: vec![centre - side, end - side, end + side, centre + side], holes: Vec::new() });
        }
    }
    let joined = union(&[&product.region_mm, &Region::new(added)]);
    let region = difference(&joined, &Region::new(holes));
    let after = count_topology(&region);
    let mesh = extrude(&region, thickness_mm).map_err(|e| JumpRingError::Mesh(e.to_string()))?;
    let ring_holes = region
        .polygons
        .iter()
        .flat_map(|p| p.holes.iter())
        .filter(|h| centres.iter().any(|c| ring_contains(h, *c)))
        .count();
    if after.components != before.components {
        product.warnings.push(Warning::JumpRingsJoinedParts { before: before.components, after: after.components });
    }
    let t = &mut product.topology;
    t.components = after.components;
    t.jump_rings = ring_holes;
    t.holes = after.holes.saturating_sub(t.loop_openings + ring_holes);
    product.fill_mm = mesh.top_faces();
    product.mesh_mm = Some(mesh);
    product.region_mm = region;
    Ok(product)
}
