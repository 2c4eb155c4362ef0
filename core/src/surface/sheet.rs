//! Rows of pattern made along circles, laid on a [`Shade`]: united with
//! rims on a flat *sheet*, made solid there, and bent onto the surface.
//!
//! The sheet is an annulus in the plane: the point at angle `theta` about
//! the shade's axis and `slant_mm` up its surface sits at polar radius
//! `sheet_radius_mm + slant_mm` and polar angle `-theta`. A row's loop and
//! the whole shade close on themselves there exactly as on the surface, so
//! the polygon union welds every row and rim all around, the extrusion is
//! watertight by construction, and bending it vertex by vertex onto the
//! surface (a smooth one-to-one map) keeps it so. No seam is welded by hand.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};
use serde::{Deserialize, Serialize};

use super::{Shade, ShadeError, shade::MAX_SHADE_MM};
use crate::geom::{
    PatternTopology, Polygon, Rect, Region, clip_to_rect, count_topology, intersection, refine_mapped, ring_contains,
    union,
};
use crate::mesh::{Mesh, MeshError, extrude, split_edges};

/// Longest edge of a row's outline before it is mapped onto the sheet, mm;
/// edges are then halved until they follow the map within
/// [`SHEET_TOLERANCE_MM`]. The bend onto the surface is refined apart (see
/// [`CHORD_TOLERANCE_MM`]), so the sheet needs no finer step.
pub const SHEET_STEP_MM: f64 = 4.0;

/// How far a row's mapped edge may stray from the curve it stands for on the sheet, mm.
pub const SHEET_TOLERANCE_MM: f64 = 1e-3;

/// How far the middle of an edge may stand off the curved surface it
/// stands for, mm: on a radius `r` an edge across the surface is at most
/// `sqrt(8 r tol)` long (1.8 mm on a radius of 40 mm).
pub const CHORD_TOLERANCE_MM: f64 = 0.01;

/// A shade and how its rows are laid: one settings struct for the command
/// line and the app.
///
/// ```
/// use tracery_core::surface::ShadeSettings;
/// let s = ShadeSettings::default();
/// assert!(s.validate(10.0).is_ok());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
#[non_exhaustive]
pub struct ShadeSettings {
    /// The surface.
    pub shade: Shade,
    /// Height of the solid rim at the top and at the bottom, mm (0: none).
    pub rim_mm: f64,
    /// How far each row overlaps the next and the rims, mm, so that they
    /// fuse where both hold material.
    pub row_overlap_mm: f64,
}

impl Default for ShadeSettings {
    fn default() -> Self {
        ShadeSettings { shade: Shade::default(), rim_mm: 3.0, row_overlap_mm: 1.0 }
    }
}

/// Where one row of pattern goes on a shade.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowPlace {
    /// The middle of the row, mm up the surface.
    pub centre_slant_mm: f64,
    /// The row's height across, mm.
    pub band_mm: f64,
    /// Radius of the shade at the row's middle, mm: the row is made along a
    /// circle of this radius, so its length is the shade's girth there.
    pub radius_mm: f64,
}

impl ShadeSettings {
    /// Checks the shade and that rows of about `band_mm` fit between the rims.
    pub fn validate(&self, band_mm: f64) -> Result<(), ShadeError> {
        self.rows(band_mm).map(|_| ())
    }

    /// The rows between the rims, each about `band_mm` high (adjusted so that
    /// a whole number of rows, overlapping by `row_overlap_mm`, fills the
    /// height exactly), from the bottom up.
    ///
    /// ```
    /// use tracery_core::surface::ShadeSettings;
    /// let rows = ShadeSettings::default().rows(10.0).unwrap();
    /// assert_eq!(rows.len(), 8);
    /// ```
    pub fn rows(&self, band_mm: f64) -> Result<Vec<RowPlace>, ShadeError> {
        self.shade.validate()?;
        let non_negative = |what: &'static str, value: f64| {
            if !(value.is_finite() && value >= 0.0) {
                return Err(ShadeError::Size { what, value });
            }
            if value > MAX_SHADE_MM {
                return Err(ShadeError::TooLarge { what, value, limit: MAX_SHADE_MM });
            }
            Ok(())
        };
        non_negative("rim", self.rim_mm)?;
        non_negative("row overlap", self.row_overlap_mm)?;
        let overlap = self.row_overlap_mm;
        if !(band_mm.is_finite() && band_mm > overlap) {
            return Err(ShadeError::Overlap { overlap_mm: overlap, band_mm });
        }
        let slant = self.shade.slant_height_mm();
        let (start, end) = match self.rim_mm > 0.0 {
            true => (self.rim_mm - overlap, slant - self.rim_mm + overlap),
            false => (0.0, slant),
        };
        let span = end - start;
        if span <= overlap {
            return Err(ShadeError::RimsFill { rim_mm: self.rim_mm, slant_mm: slant });
        }
        let count = ((span - overlap) / (band_mm - overlap)).round().max(1.0) as usize;
        let band = (span + (count - 1) as f64 * overlap) / count as f64;
        Ok((0..count)
            .map(|k| {
                let centre = start + k as f64 * (band - overlap) + 0.5 * band;
                RowPlace { centre_slant_mm: centre, band_mm: band, radius_mm: self.shade.radius_at(centre) }
            })
            .collect())
    }
}

/// A shade made solid.
#[derive(Clone, Debug, Default)]
pub struct Wrapped {
    /// The solid, on the surface, mm.
    pub mesh_mm: Mesh,
    /// The pattern laid flat (see [`Shade::developed`]), cut along `theta = 0`, mm.
    pub development_mm: Region,
    /// Topology counted on the sheet: a shade's top and bottom openings are
    /// its loop openings, not holes in the lace.
    pub topology: PatternTopology,
    /// Largest stretch across the rows, in percent: a row made along one
    /// circle and laid on a cone is wider than the surface at its top edge,
    /// narrower at its bottom (0 on a cylinder).
    pub stretch_percent: f64,
}

/// Why a shade could not be made solid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum WrapError {
    /// Rows and rims left nothing.
    #[error("the shade has no pattern on it")]
    Empty,
    /// The extrusion failed.
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

/// Radius of the sheet's bottom circle, mm: about the shade's own girth, and
/// never so small that the sheet's inner rows are cramped.
fn sheet_radius_mm(shade: &Shade) -> f64 {
    let slant = shade.slant_height_mm();
    (shade.radius_at(0.5 * slant) - 0.5 * slant).max(0.5 * slant)
}

/// Edge of a rim's circles on the sheet, mm: the bend onto the surface
/// splits them further where it needs to.
const RIM_STEP_MM: f64 = 2.0;

/// A ring of `rim_mm` on the sheet from `slant_mm` up.
fn sheet_band(sheet_radius: f64, from_slant_mm: f64, to_slant_mm: f64) -> Polygon {
    let (inner, outer) = (sheet_radius + from_slant_mm, sheet_radius + to_slant_mm);
    let n = ((TAU * outer / RIM_STEP_MM).ceil() as usize).max(16);
    let circle = |r: f64| -> Vec<DVec2> { (0..n).map(|i| DVec2::from_angle(TAU * i as f64 / n as f64) * r).collect() };
    let mut hole = circle(inner);
    hole.reverse();
    Polygon { outer: circle(outer), holes: vec![hole] }
}

/// A row made along a counter-clockwise circle of `place.radius_mm` about
/// the origin (the band's `v`, up, points to the centre) moved onto the sheet.
fn row_on_sheet(row_mm: &Region, place: &RowPlace, sheet_radius: f64) -> Region {
    let to_sheet = |p: DVec2| {
        let slant = place.centre_slant_mm + (place.radius_mm - p.length());
        // Both the radius and the angle turn over, so rings keep their orientation.
        DVec2::from_angle(-p.y.atan2(p.x)) * (sheet_radius + slant)
    };
    let polygons = row_mm
        .polygons
        .iter()
        .map(|poly| Polygon {
            outer: refine_mapped(&poly.outer, to_sheet, SHEET_STEP_MM, SHEET_TOLERANCE_MM),
            holes: poly.holes.iter().map(|h| refine_mapped(h, to_sheet, SHEET_STEP_MM, SHEET_TOLERANCE_MM)).collect(),
        })
        .collect();
    Region::new(polygons)
}

/// Unites `rows` (each made along a circle as [`RowPlace`] says) with the
/// rims, makes the result `thickness_mm` thick outward from the surface, and
/// lays it flat for the development.
pub fn wrap_rows(
    rows: &[(Region, RowPlace)],
    settings: &ShadeSettings,
    thickness_mm: f64,
) -> Result<Wrapped, WrapError> {
    let shade = &settings.shade;
    let slant = shade.slant_height_mm();
    let sheet_radius = sheet_radius_mm(shade);
    let mut parts: Vec<Region> = rows.iter().map(|(row, place)| row_on_sheet(row, place, sheet_radius)).collect();
    if settings.rim_mm > 0.0 {
        parts.push(Region::new(vec![sheet_band(sheet_radius, 0.0, settings.rim_mm)]));
        parts.push(Region::new(vec![sheet_band(sheet_radius, slant - settings.rim_mm, slant)]));
    }
    let united = union(&parts.iter().collect::<Vec<_>>());
    // Trimmed to the surface: a row may reach past its band by a hair.
    let sheet = intersection(&united, &Region::new(vec![sheet_band(sheet_radius, 0.0, slant)]));
    if sheet.is_empty() {
        return Err(WrapError::Empty);
    }
    let counted = count_topology(&sheet);
    let openings = sheet.polygons.iter().flat_map(|p| p.holes.iter()).filter(|h| ring_contains(h, DVec2::ZERO)).count();
    let topology = PatternTopology {
        components: counted.components,
        holes: counted.holes - openings.min(counted.holes),
        loop_openings: openings,
        jump_rings: 0,
    };

    let flat = extrude(&sheet, thickness_mm)?;
    let on_surface = |v: [f64; 3]| -> DVec3 {
        let p = DVec2::new(v[0], v[1]);
        let theta = -p.y.atan2(p.x);
        // Midpoints of the rims' chords lie a hair outside the band: they
        // are put back on the rim, so the shade stands exactly on z = 0.
        let slant_mm = (p.length() - sheet_radius).clamp(0.0, slant);
        shade.point(theta, slant_mm) + shade.outward_normal(theta) * v[2]
    };
    // An edge is bent where its middle, mapped, strays from the chord of its
    // mapped ends; edges up the surface or through its thickness stay whole.
    let fine = split_edges(&flat, |a, b| {
        let middle = on_surface([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])]);
        middle.distance(0.5 * (on_surface(a) + on_surface(b))) > CHORD_TOLERANCE_MM
    });
    let mut mesh =
        Mesh { vertices: fine.vertices.iter().map(|&v| on_surface(v).to_array()).collect(), triangles: fine.triangles };
    mesh.orient_outward();

    let development_mm = develop(&sheet, shade, sheet_radius);
    let sin_half = (shade.bottom_radius_mm - shade.top_radius_mm).abs() / slant;
    let stretch_percent = rows
        .iter()
        .map(|(_, place)| 100.0 * 0.5 * place.band_mm * sin_half / shade.radius_at(place.centre_slant_mm))
        .fold(0.0, f64::max);
    Ok(Wrapped { mesh_mm: mesh, development_mm, topology, stretch_percent })
}

/// The sheet laid flat: cut in two halves along the line `theta = 0, π`,
/// each mapped through [`Shade::developed`], and joined again along `π`.
fn develop(sheet: &Region, shade: &Shade, sheet_radius: f64) -> Region {
    let reach = 2.0 * (sheet_radius + shade.slant_height_mm());
    let below = clip_to_rect(sheet, &Rect::new(DVec2::new(-reach, -reach), DVec2::new(reach, 0.0)));
    let above = clip_to_rect(sheet, &Rect::new(DVec2::new(-reach, 0.0), DVec2::new(reach, reach)));
    // Below the line theta runs from 0 to π, above from π to 2π; on the
    // line itself the sign of a zero could go either way, and the absolute
    // value puts it on the right side.
    let lay = |p: DVec2, upper: bool| {
        let phi = p.y.atan2(p.x).abs();
        let theta = if upper { TAU - phi } else { phi };
        shade.developed(theta, p.length() - sheet_radius)
    };
    let below = below.map_points(|p| lay(p, false));
    let above = above.map_points(|p| lay(p, true));
    union(&[&below, &above])
}
