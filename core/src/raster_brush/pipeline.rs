//! The raster brush from start to end: ribbon, valid positions, search,
//! stitching ([`synthesize`]), then the textured triangles, the traced
//! outline, its solid and the figures a report shows ([`make_product`]).

use glam::DVec2;

use super::search::{Closure, EdgeTable};
use super::stitch::{SeamMap, align_seam};
use super::{
    Path, PieceSamples, Placements, RasterError, RasterExemplar, Ribbon, Settings, VARIETY_COST, lay_ribbon, search,
    textured_mesh, valid_positions, variety_bias,
};
use crate::Product;
use crate::control::Control;
use crate::curve::{Along, Curve, planar_topology};
use crate::export::{MAX_RENDER_PX, render_textured};
use crate::geom::{PixelFrame, Region, trace_opaque};
use crate::mesh::extrude;
use crate::product::{Fact, Facts, Overlays, TexturedMesh};
use crate::report::Timings;

/// The traced outline is taken from a render this many times finer than the
/// exemplar's pixels, so that its curves are smooth.
pub const TRACE_OVERSAMPLING: f64 = 2.0;

/// Everything the synthesis decided, stage by stage.
#[derive(Clone, Debug)]
pub struct RasterSynthesis {
    /// The ribbon and its pieces.
    pub ribbon: Ribbon,
    /// Where each piece samples the exemplar.
    pub samples: Vec<PieceSamples>,
    /// Each piece's valid positions.
    pub placements: Vec<Placements>,
    /// The chosen positions.
    pub path: Path,
    /// Each piece's seam with the next (none after an open curve's last piece).
    pub seams: Vec<Option<SeamMap>>,
    /// Milliseconds per stage.
    pub timings: Timings,
}

/// Synthesizes `exemplar` along `curve`, leaving `avoid_mm` empty.
pub fn synthesize(
    exemplar: &RasterExemplar,
    curve: &Curve,
    settings: &Settings,
    avoid_mm: &Region,
    control: &Control,
) -> Result<RasterSynthesis, RasterError> {
    settings.validate()?;
    let mut timings = Timings::default();
    let ribbon = timings.time("ribbon", || lay_ribbon(curve, exemplar, settings, avoid_mm))?;
    control.check()?;
    let c = ribbon.column_px;
    let samples: Vec<PieceSamples> = ribbon.pieces.iter().map(|p| PieceSamples::new(p, c)).collect();
    let amount = settings.variety * VARIETY_COST;
    let placements: Vec<Placements> = timings.time("valid positions", || {
        use rayon::prelude::*;
        (ribbon.pieces.par_iter().zip(&samples).enumerate())
            .map(|(i, (p, s))| {
                let mut placements = valid_positions(exemplar, s, &p.avoided_px, c);
                if amount > 0.0 {
                    placements.bias = variety_bias(&placements.positions, i, settings.seed, amount);
                }
                placements
            })
            .collect()
    });
    if let Some(i) = placements.iter().position(|p| p.positions.is_empty()) {
        return Err(RasterError::Unplaceable { piece: i, at_mm: ribbon.pieces[i].start_mm });
    }
    let path = timings.time("search", || search(exemplar, &samples, &placements, c, ribbon.closed, control))?;
    timings.add_ms("per_piece", timings.stage_ms("search").unwrap_or(0.0) / ribbon.pieces.len() as f64);
    let n = ribbon.pieces.len();
    let seams = timings.time("stitching", || {
        (0..n)
            .map(|i| {
                let next = (i + 1) % n;
                if next == 0 && !ribbon.closed {
                    return None;
                }
                let right = EdgeTable::right(exemplar, &[path.positions[i]], &samples[i]);
                let left = EdgeTable::left(exemplar, &[path.positions[next]], c);
                let seam = align_seam(&right, 0, &left, 0, c);
                // A remapping that does not help is not applied.
                Some(if seam.after < seam.before {
                    seam
                } else {
                    SeamMap { remap: (0..c).map(|k| k as f32).collect(), after: seam.before, ..seam }
                })
            })
            .collect()
    });
    Ok(RasterSynthesis { ribbon, samples, placements, path, seams, timings })
}

/// The opaque parts of textured triangles, traced into a region (mm) from a
/// render at [`TRACE_OVERSAMPLING`] times `px_per_mm` (the exemplar's pixels).
pub fn traced_region(mesh: &TexturedMesh, px_per_mm: f64) -> Result<Region, RasterError> {
    let bounds = crate::geom::Rect::from_points(mesh.positions_mm.iter().copied());
    let area = bounds.map_or(0.0, |b| b.width() * b.height());
    let mut px_per_mm = TRACE_OVERSAMPLING * px_per_mm;
    if area * px_per_mm * px_per_mm > MAX_RENDER_PX as f64 {
        px_per_mm = (MAX_RENDER_PX as f64 / area).sqrt() * 0.99;
    }
    let image = render_textured(mesh, px_per_mm)?;
    let alpha: Vec<u8> = image.rgba.chunks_exact(4).map(|p| p[3]).collect();
    let frame = PixelFrame {
        width_px: image.width_px as usize,
        height_px: image.height_px as usize,
        origin_mm: image.origin_mm,
        mm_per_px: image.mm_per_px,
    };
    Ok(trace_opaque(&alpha, &frame))
}

/// Runs the whole raster brush along `along` (a curve), leaving `avoid_mm`
/// empty: the textured result, its traced outline and solid, and its figures.
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::curve::Along;
/// use tracery_core::geom::Region;
/// use tracery_core::raster_brush::{Settings, builtin, make_product};
/// let along = Along::parse("wave:80").unwrap();
/// let product = make_product(&builtin("rope").unwrap(), &along, &Settings::default(), &Region::default(), &Control::default()).unwrap();
/// assert_eq!(product.topology.components, 1);
/// assert_eq!(product.mesh_mm.unwrap().shell_count(), 1);
/// ```
pub fn make_product(
    exemplar: &RasterExemplar,
    along: &Along,
    settings: &Settings,
    avoid_mm: &Region,
    control: &Control,
) -> Result<Product, RasterError> {
    let Along::Curve(curve) = along else {
        return Err(RasterError::NotACurve);
    };
    let synthesis = synthesize(exemplar, curve, settings, avoid_mm, control)?;
    let mut timings = synthesis.timings.clone();
    let textured = timings.time("textured mesh", || textured_mesh(exemplar, &synthesis, settings.stitching));
    control.check()?;
    let region = timings.time("trace", || traced_region(&textured, synthesis.ribbon.px_per_mm))?;
    control.check()?;
    let topology = planar_topology(&region, curve);
    let mesh = timings.time("mesh", || extrude(&region, settings.thickness_mm))?;
    let ribbon = &synthesis.ribbon;
    let mut overlays = Overlays { avoided_mm: ribbon.avoided_mm.clone(), ..Overlays::default() };
    let corner = |k: usize| -> Vec<DVec2> {
        let mut edge: Vec<DVec2> = ribbon.pieces.iter().map(|p| p.corners_mm[k]).collect();
        edge.extend(ribbon.pieces.last().map(|p| p.corners_mm[if k == 0 { 1 } else { 2 }]));
        edge
    };
    overlays.band_edges_mm = vec![corner(0), corner(3)];
    overlays.seams_mm = ribbon.pieces.iter().skip(1).map(|p| [p.corners_mm[0], p.corners_mm[3]]).collect();
    let (valid, tried) =
        synthesis.placements.iter().fold((0, 0), |(v, t), p| (v + p.positions.len(), t + p.candidates));
    let (before, after) = synthesis
        .seams
        .iter()
        .flatten()
        .fold((0.0, 0.0), |(b, a), s| (b + f64::from(s.before), a + f64::from(s.after)));
    let mut facts = Facts::default();
    facts.push("pieces", Fact::Count(ribbon.pieces.len()));
    facts.push("exemplar_px", Fact::Text(format!("{}x{}", exemplar.width(), exemplar.height())));
    facts.push("px_per_mm", Fact::Number(ribbon.px_per_mm));
    facts.push("column_px", Fact::Count(ribbon.column_px));
    facts.push("valid_fraction", Fact::Number(valid as f64 / tried.max(1) as f64));
    facts.push("cost", Fact::Number(synthesis.path.cost));
    facts.push(
        "closure",
        Fact::Text(match synthesis.path.closure {
            Closure::Open => "open".into(),
            Closure::Exact => "exact".into(),
            Closure::Bounded { gap } => format!("within {:.1}% of the cheapest", 100.0 * gap),
        }),
    );
    facts.push("seam_mismatch_before", Fact::Number(before));
    facts.push("seam_mismatch_after", Fact::Number(after));
    facts.push("length_mm", Fact::Number(curve.length()));
    Ok(Product {
        fill_mm: mesh.top_faces(),
        region_mm: region,
        mesh_mm: Some(mesh),
        textured_mm: Some(textured),
        path_ends_mm: curve.path_ends(),
        overlays,
        topology,
        timings,
        facts,
        ..Product::default()
    })
}
