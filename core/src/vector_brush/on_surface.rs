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
use crate::mesh::{BooleanError, MeshError, difference_solids, union_solids};
use crate::product::{Fact, Facts};
use crate::report::{Timings, Warning};
use crate::surface::{
    BandOnSurface, DrawnError, EMBOSS_SINK_MM, HollowError, Sheet, SurfaceMesh, SurfaceOutput, SurfaceSettings,
    draw_on, hollow, lay_band,
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
    Boolean(#[from] BooleanError),
    /// The model could not be hollowed for carving.
    #[error(transparent)]
    Hollow(#[from] HollowError),
}

impl MaybeCancelled for SurfaceSynthesisError {
    fn is_cancelled(&self) -> bool {
        matches!(self, SurfaceSynthesisError::Synthesis(e) if e.is_cancelled())
    }
}

/// `exemplar` made along the curve `drawn` describes on `surface`, with
/// every setting of `settings`, as a shell `settings.thickness_mm` thick on
/// the surface. The product's `mesh_mm` is the shell; its `region_mm` the
/// pattern as made, flat (along `+x`, or around a circle for a closed curve).
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
    let mut mesh = timings.time("lay on surface", || lay_band(region, sheet, &band, thickness_mm, sink_mm))?;
    let band_shells = mesh.shell_count();
    match drawn.output {
        SurfaceOutput::Emboss => mesh = timings.time("emboss", || union_solids(surface.mesh(), &mesh))?,
        SurfaceOutput::Carve => {
            let shell = timings.time("hollow", || hollow(surface, drawn.wall_mm))?;
            mesh = timings.time("carve", || difference_solids(&shell, &mesh))?;
        }
        _ => {}
    }
    let shells = if drawn.output == SurfaceOutput::Pattern { band_shells } else { mesh.shell_count() };
    let mut warnings = on.warnings.clone();
    if drawn.output == SurfaceOutput::Carve && shells > 1 {
        warnings.push(Warning::CarvedApart { bodies: shells });
    }
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
    facts.push("band_shells", Fact::Count(band_shells));
    facts.push("shells", Fact::Count(shells));
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
