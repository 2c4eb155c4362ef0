//! The vector brush's [`Product`]: the pattern, its solid, overlays and facts.

use glam::DVec2;

use super::{
    Exemplar, Settings, Synthesis, SynthesisError, Target, synthesize, synthesize_alternatives, synthesize_rectangle,
};
use crate::Product;
use crate::control::Control;
use crate::curve::Along;
use crate::geom::{Region, fill_triangles};
use crate::mesh::extrude;
use crate::product::{Fact, Facts, Overlays};
use crate::quality::seam_kinks_deg;

/// Samples per millimetre of the band's edges drawn on the canvas.
const BAND_EDGE_SAMPLES_PER_MM: f64 = 1.0;

fn target_text(t: Target) -> String {
    match t {
        Target::Exactly(n) => n.to_string(),
        Target::Any => "any".into(),
    }
}

/// Runs the whole vector brush: synthesis along `along`, then the solid
/// (`settings.thickness_mm`), overlays and the figures a report shows.
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::curve::Along;
/// use tracery_core::vector_brush::{Settings, builtin, make_product};
/// let along = Along::parse("circle:25").unwrap();
/// let product = make_product(&builtin("lace").unwrap(), &along, &Settings::default(), &Control::default()).unwrap();
/// assert_eq!(product.topology.components, 1);
/// assert_eq!(product.mesh_mm.unwrap().shell_count(), 1);
/// ```
pub fn make_product(
    exemplar: &Exemplar,
    along: &Along,
    settings: &Settings,
    control: &Control,
) -> Result<Product, SynthesisError> {
    let synthesis = match along {
        Along::Curve(curve) => synthesize(exemplar, curve, settings, control)?,
        Along::Rectangle { width_mm, height_mm } => {
            synthesize_rectangle(exemplar, *width_mm, *height_mm, settings, control)?
        }
    };
    to_product(synthesis, along, settings, true)
}

/// The first `count` alternatives along `along` as products (see
/// [`Settings::alternative`]): the gallery's choices, the best first. Along
/// a curve they share one analysis and one chain of searches.
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::curve::Along;
/// use tracery_core::vector_brush::{Settings, builtin, make_alternatives};
/// let along = Along::parse("line:100").unwrap();
/// let all = make_alternatives(&builtin("vine").unwrap(), &along, &Settings::default(), 4, &Control::default()).unwrap();
/// assert_eq!(all.len(), 4);
/// assert!(all.iter().all(|p| p.topology.components == 1));
/// ```
pub fn make_alternatives(
    exemplar: &Exemplar,
    along: &Along,
    settings: &Settings,
    count: u32,
    control: &Control,
) -> Result<Vec<Product>, SynthesisError> {
    match along {
        Along::Curve(curve) => synthesize_alternatives(exemplar, curve, settings, count, control)?
            .into_iter()
            .map(|s| to_product(s, along, settings, true))
            .collect(),
        Along::Rectangle { .. } => (0..count)
            .map(|k| {
                let mut one = settings.clone();
                one.alternative = k;
                make_product(exemplar, along, &one, control)
            })
            .collect(),
    }
}

/// A synthesis as a product: its solid (unless `solid` is false, for a
/// preview: then only triangles to draw it), overlays and the figures a
/// report shows.
pub(crate) fn to_product(
    synthesis: Synthesis,
    along: &Along,
    settings: &Settings,
    solid: bool,
) -> Result<Product, SynthesisError> {
    let Synthesis {
        scale_mm_per_unit,
        piece_count,
        solution,
        band,
        planar,
        curve: followed,
        topology,
        mut timings,
        warnings,
        shape_classes,
        ..
    } = synthesis;
    let mesh = match solid {
        true => Some(timings.time("mesh", || extrude(&planar.region, settings.thickness_mm))?),
        false => None,
    };
    let fill_mm = match &mesh {
        Some(mesh) => mesh.top_faces(),
        None => timings.time("fill", || fill_triangles(&planar.region)),
    };
    let mut overlays = Overlays::default();
    let mut path_ends_mm = Vec::new();
    let length_mm = match along {
        Along::Curve(_) => {
            let curve = &followed;
            let half = 0.5 * settings.band_mm;
            let steps = ((curve.length() * BAND_EDGE_SAMPLES_PER_MM).ceil() as usize).clamp(2, 5000);
            let edge = |side: f64| -> Vec<DVec2> {
                (0..=steps).map(|k| curve.map(curve.length() * k as f64 / steps as f64, side * half)).collect()
            };
            overlays.band_edges_mm = vec![edge(1.0), edge(-1.0)];
            path_ends_mm = curve.path_ends();
            overlays.seams_mm = band
                .seams
                .iter()
                .map(|&u| [curve.map(u * scale_mm_per_unit, -half), curve.map(u * scale_mm_per_unit, half)])
                .collect();
            band.length * scale_mm_per_unit
        }
        Along::Rectangle { .. } => planar.region.bounds().map_or(0.0, |b| b.width()),
    };
    let mut facts = Facts::default();
    facts.push("target_components", Fact::Text(target_text(settings.components)));
    facts.push("target_holes", Fact::Text(target_text(settings.holes)));
    facts.push("target_length_mm", Fact::Number(along.length_mm()));
    facts.push("length_mm", Fact::Number(length_mm));
    facts.push("synthesized_length_mm", Fact::Number(solution.length * scale_mm_per_unit));
    facts.push("scale_mm_per_unit", Fact::Number(scale_mm_per_unit));
    facts.push("cost", Fact::Number(solution.cost));
    facts.push("pieces", Fact::Count(solution.pieces.len()));
    facts.push("piece_sequence", Fact::Indices(solution.pieces.clone()));
    facts.push("shape_sequence", Fact::Indices(shape_classes));
    facts.push("alternative", Fact::Count(settings.alternative as usize));
    facts.push("pieces_in_exemplar", Fact::Count(piece_count));
    facts.push("dp_states", Fact::Count(solution.states));
    // Which search answered: past the state cap, one that drops dominated
    // partial patterns, then one that keeps the cheapest of each length.
    let search = match (solution.bounded, solution.dominance) {
        (Some(_), _) => "bounded",
        (None, true) => "dominance",
        (None, false) => "exact",
    };
    facts.push("search", Fact::Text(search.into()));
    // Measured on the stitched pattern, before it is bent along the curve:
    // how much the outline turns at a seam beyond its turn around it.
    let kinks = timings.time("seam check", || seam_kinks_deg(&band.region, &band.seams, 1e-6 * band.length));
    facts.push("seam_kink_max_deg", Fact::Number(kinks.into_iter().fold(0.0, f64::max)));
    // The pieces' worst deformation by stitching, in band space too.
    facts.push("piece_stretch_max", Fact::Number(band.distortion.stretch_max()));
    facts.push("piece_shear_max_deg", Fact::Number(band.distortion.shear_max_deg()));
    // How far apart the worst seam's endpoints were before stitching closed
    // them, in exemplar heights.
    facts.push("seam_gap_max", Fact::Number(band.seam_gap_max()));
    Ok(Product {
        fill_mm,
        region_mm: planar.region,
        paths_mm: Vec::new(),
        filled_mm: Region::default(),
        path_ends_mm,
        mesh_mm: mesh,
        image: None,
        textured_mm: None,
        overlays,
        topology,
        warnings,
        timings,
        facts,
        printability: None,
    })
}
