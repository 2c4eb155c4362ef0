//! The vector brush on a 3D object (section 6.3 of the paper): a curve
//! drawn on a base model ([`crate::surface::draw_on`]), a pattern made with
//! every brush setting along a line (or, for a closed curve, a circle) as
//! long as the curve, and that pattern laid on the surface along the
//! curve's band ([`crate::surface::lay_band`]) as a printable shell.

use super::{Exemplar, InvalidSetting, Settings, SynthesisError, synthesize};
use crate::Product;
use crate::control::{Control, MaybeCancelled};
use crate::curve::Curve;
use crate::geom::fill_triangles;
use crate::mesh::MeshError;
use crate::product::{Fact, Facts};
use crate::report::Timings;
use crate::surface::{
    AssemblyError, BandOnSurface, DrawnError, EMBOSS_SINK_MM, Part, PartRole, Sheet, SurfaceMesh, SurfaceOutput,
    SurfaceSettings, assemble, assemble_products, draw_on, lay_band, object_holds_model,
};

/// Why a pattern could not be put on a surface.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SurfaceSynthesisError {
    /// A vector-brush setting is out of range.
    #[error(transparent)]
    Setting(#[from] InvalidSetting),
    /// The curve could not be drawn on the surface.
    #[error(transparent)]
    Drawn(#[from] DrawnError),
    /// The pattern could not be made along the curve.
    #[error(transparent)]
    Synthesis(#[from] SynthesisError),
    /// The pattern could not be made solid on the surface.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// The pattern could not be united with the model, or cut out of it.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// A fault in Tracery itself, caught in a worker.
    #[error(transparent)]
    Internal(#[from] crate::control::Internal),
}

impl MaybeCancelled for SurfaceSynthesisError {
    fn is_cancelled(&self) -> bool {
        matches!(self, SurfaceSynthesisError::Synthesis(e) if e.is_cancelled())
    }
}

/// What an embossed or carved curve's band does to its model.
pub fn part_role(drawn: &SurfaceSettings) -> PartRole {
    match drawn.output {
        SurfaceOutput::Emboss => PartRole::Emboss,
        SurfaceOutput::Carve => PartRole::Carve { wall_mm: drawn.wall_mm },
        _ => PartRole::Add,
    }
}

/// `exemplar` made along the curve `drawn` describes on `surface`, with
/// every setting of `settings`, as a band on the surface, before it is
/// united with the model or cut out of it: lying on the surface
/// `settings.thickness_mm` thick for a pattern, sunk a little into it for
/// emboss, and reaching through the wall for carve. Give it to
/// [`crate::surface::assemble`] with [`part_role`] (as [`make_on_surface`]
/// does), alone or with the bands of other curves on the same model.
///
/// The product's `mesh_mm` is the band; its `region_mm` the pattern as
/// made, flat (along `+x`, or around a circle for a closed curve).
pub fn make_band_on_surface(
    exemplar: &Exemplar,
    surface: &SurfaceMesh,
    drawn: &SurfaceSettings,
    settings: &Settings,
    control: &Control,
) -> Result<Product, SurfaceSynthesisError> {
    settings.validate()?;
    let mut timings = Timings::default();
    let on = draw_on(surface, drawn, settings.band_mm, &mut timings)?;
    control.report(0.1);
    let length_mm = on.frames.length_mm;
    let mut brush = settings.clone();
    brush.band_mm = on.band_mm;
    let (curve, sheet) = if drawn.closed {
        let radius_mm = length_mm / std::f64::consts::TAU;
        (Curve::circle(radius_mm), Sheet::Circle { radius_mm })
    } else {
        (Curve::line(length_mm), Sheet::Line)
    };
    let curve = curve.map_err(|e| SurfaceSynthesisError::Synthesis(e.into()))?;
    brush.closed_pattern = drawn.closed;
    let synthesis = synthesize(exemplar, &curve, &brush, control)?;
    timings.absorb(&synthesis.timings);
    control.report(0.8);
    let band = BandOnSurface { surface, curve: &on.curve, frames: &on.frames, conform: drawn.twist_deg == 0.0 };
    let region = &synthesis.planar.region;
    // A carved band only has to reach through the shell, a hair past both sides.
    let (sink_mm, thickness_mm) = match drawn.output {
        SurfaceOutput::Emboss => (EMBOSS_SINK_MM, settings.thickness_mm),
        SurfaceOutput::Carve => (drawn.wall_mm + EMBOSS_SINK_MM, EMBOSS_SINK_MM),
        _ => (0.0, settings.thickness_mm),
    };
    let mesh = timings.time("lay on surface", || lay_band(region, sheet, &band, thickness_mm, sink_mm))?;
    let mut warnings = on.warnings.clone();
    warnings.extend(synthesis.warnings.iter().cloned());
    let mut facts = Facts::default();
    facts.push("curve_length_mm", Fact::Number(length_mm));
    facts.push("band_mm", Fact::Number(on.band_mm));
    facts.push("curve_points", Fact::Count(on.curve.points_mm.len()));
    facts.push("chart_triangles", Fact::Count(on.chart_triangles));
    facts.push("base_triangles", Fact::Count(surface.triangles().len()));
    facts.push("frame_turn_deg_per_mm", Fact::Number(on.frames.max_turn_deg_per_mm()));
    facts.push(
        "points_moved_mm",
        Fact::Text(on.moved_mm.iter().map(|d| format!("{d:.3}")).collect::<Vec<_>>().join(",")),
    );
    facts.push("pieces", Fact::Count(synthesis.solution.pieces.len()));
    facts.push("thickness_mm", Fact::Number(settings.thickness_mm));
    facts.push("band_shells", Fact::Count(mesh.shell_count()));
    Ok(Product {
        fill_mm: fill_triangles(region),
        region_mm: region.clone(),
        mesh_mm: Some(mesh),
        topology: synthesis.topology,
        warnings,
        timings,
        facts,
        ..Product::default()
    })
}

/// `exemplar` made along the curve `drawn` describes on `surface`, with
/// every setting of `settings`, made into what `drawn.output` asks: a
/// shell `settings.thickness_mm` thick on the surface, or that united
/// with the model, or cut out of the model hollowed. The product's
/// `mesh_mm` is that solid; its `region_mm` the pattern as made, flat.
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::surface::{SurfaceMesh, SurfaceSettings, builtin_base};
/// use tracery_core::vector_brush::{Settings, builtin, make_on_surface};
/// let egg = SurfaceMesh::new(builtin_base("egg").unwrap()).unwrap();
/// let mut drawn = SurfaceSettings::default();
/// drawn.points_mm = SurfaceSettings::parse_points("30,0,30; 0,30,30; -30,0,30; 0,-30,30").unwrap();
/// drawn.closed = true;
/// let mut settings = Settings::default();
/// settings.band_mm = 8.0;
/// let product = make_on_surface(&builtin("chain").unwrap(), &egg, &drawn, &settings, &Control::default()).unwrap();
/// let shell = product.mesh_mm.unwrap();
/// assert!(shell.sanity_check().is_ok());
/// assert_eq!(shell.shell_count(), product.topology.components);
/// ```
pub fn make_on_surface(
    exemplar: &Exemplar,
    surface: &SurfaceMesh,
    drawn: &SurfaceSettings,
    settings: &Settings,
    control: &Control,
) -> Result<Product, SurfaceSynthesisError> {
    let mut product = make_band_on_surface(exemplar, surface, drawn, settings, control)?;
    let Some(band) = product.mesh_mm.take() else { return Ok(product) };
    let part = Part { solid_mm: &band, role: part_role(drawn) };
    let object = assemble(Some(surface), false, &[part], &mut product.timings)?;
    product.warnings.extend(object.warnings);
    product.facts.push("shells", Fact::Count(object.bodies));
    product.mesh_mm = Some(object.mesh_mm);
    Ok(product)
}

/// Several curves on one model, each made as [`make_band_on_surface`]
/// does (with the seed moved on by one for each next curve, so that equal
/// curves differ), combined with the model once by
/// [`crate::surface::assemble`]: a multi-curve lamp in one object. Where
/// any curve is embossed or carved, the object holds the model, and a
/// curve asked as a pattern is embossed ([`SurfaceSettings::in_object`]).
///
/// The product's `mesh_mm` is the object, and its `region_mm` the flat
/// patterns laid one above the other, the first at the bottom; its
/// topology is theirs, summed. The facts give the object's `shells`.
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::surface::{SurfaceMesh, SurfaceOutput, SurfaceSettings, builtin_base};
/// use tracery_core::vector_brush::{Settings, builtin, make_object_on_surface};
/// let vase = SurfaceMesh::new(builtin_base("vase").unwrap()).unwrap();
/// let ring = |z: f64| {
///     let mut drawn = SurfaceSettings::default();
///     drawn.points_mm = SurfaceSettings::parse_points(&format!("30,0,{z}; 0,30,{z}; -30,0,{z}; 0,-30,{z}")).unwrap();
///     drawn.closed = true;
///     drawn.output = SurfaceOutput::Emboss;
///     drawn
/// };
/// let mut settings = Settings::default();
/// settings.band_mm = 6.0;
/// let lamp = make_object_on_surface(&builtin("chain").unwrap(), &vase, &[ring(20.0), ring(35.0)], &settings, &Control::default()).unwrap();
/// let mesh = lamp.mesh_mm.unwrap();
/// assert!(mesh.sanity_check().is_ok());
/// assert_eq!(mesh.shell_count(), 1);
/// ```
pub fn make_object_on_surface(
    exemplar: &Exemplar,
    surface: &SurfaceMesh,
    curves: &[SurfaceSettings],
    settings: &Settings,
    control: &Control,
) -> Result<Product, SurfaceSynthesisError> {
    if let [drawn] = curves {
        return make_on_surface(exemplar, surface, drawn, settings, control);
    }
    let holds_model = object_holds_model(curves.iter().map(|c| c.output), false);
    let mut bands = Vec::new();
    for (k, drawn) in curves.iter().enumerate() {
        let mut brush = settings.clone();
        brush.seed = settings.seed.wrapping_add(k as u64);
        let drawn = drawn.in_object(holds_model);
        bands.push((make_band_on_surface(exemplar, surface, &drawn, &brush, &control.silent())?, part_role(&drawn)));
        control.report(0.8 * (k + 1) as f32 / curves.len() as f32);
    }
    let parts: Vec<(&Product, PartRole)> = bands.iter().map(|(band, role)| (band, *role)).collect();
    let mut product = assemble_products(Some(surface), false, &parts)?;
    product.facts.push("base_triangles", Fact::Count(surface.triangles().len()));
    product.facts.push("thickness_mm", Fact::Number(settings.thickness_mm));
    Ok(product)
}
