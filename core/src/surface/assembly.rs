//! Several solids made on one model combined into one object: the bands
//! of every curve embossed on it, cut out of it or lying on it, and any
//! other solid (a lamp shade), so that a multi-curve lamp is one body in
//! one file, with the model in it once.

use glam::DVec2;

use super::{HollowError, SurfaceMesh, hollow};
use crate::Product;
use crate::geom::fill_triangles;
use crate::mesh::{BooleanError, Mesh, difference_solids, union_solids};
use crate::product::Fact;
use crate::report::{Timings, Warning};

/// What one part does to the object.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum PartRole {
    /// Added as it is (a pattern lying on the model, a shade): the model
    /// is not part of the object unless another part needs it.
    Add,
    /// Added to the model: the object holds the whole model.
    Emboss,
    /// Cut out of the model hollowed to a shell `wall_mm` thick.
    Carve {
        /// The shell's wall, mm.
        wall_mm: f64,
    },
}

/// One solid to combine, closed and facing out, in the model's space, mm.
#[derive(Clone, Copy, Debug)]
pub struct Part<'a> {
    /// The solid.
    pub solid_mm: &'a Mesh,
    /// What it does.
    pub role: PartRole,
}

/// The parts combined.
#[derive(Clone, Debug, Default)]
pub struct Assembly {
    /// The object, closed and facing out, mm.
    pub mesh_mm: Mesh,
    /// Its separate bodies (shells): 1 for a lamp that prints as one piece.
    pub bodies: usize,
    /// The shell the carved parts were cut from, when any was, mm.
    pub wall_mm: Option<f64>,
    /// Slivers the booleans left, removed (see [`CRUMB_MM3`]).
    pub crumbs: usize,
    /// Pockets of air sealed inside the object, filled (none when a part
    /// is carved).
    pub cavities: usize,
    /// What the person should know.
    pub warnings: Vec<Warning>,
}

/// Why parts could not be combined.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum AssemblyError {
    /// Nothing to combine.
    #[error("there is nothing to combine: make a pattern first")]
    Empty,
    /// A part needs the model, and none was given.
    #[error("an embossed or carved pattern needs the model it was made on")]
    NoModel,
    /// The model could not be hollowed for carving.
    #[error(transparent)]
    Hollow(#[from] HollowError),
    /// A boolean failed.
    #[error(transparent)]
    Boolean(#[from] BooleanError),
    /// A fault in Tracery itself, caught in a worker.
    #[error(transparent)]
    Internal(#[from] crate::control::Internal),
}

/// Bodies smaller than this after the booleans are slivers they left
/// where two surfaces nearly touch (a thread grazing the model), not part
/// of the object, mm³: far below anything a printer makes.
pub const CRUMB_MM3: f64 = 0.01;

/// Combines `parts` made on `model` into one object.
///
/// The object starts empty, or as the whole model when a part is
/// embossed or `with_model` asks for it (the model as a lamp's foot), or
/// as the model hollowed to the largest wall asked when a
/// part is carved. Every added and embossed part is then united with it,
/// and every carved part cut out of it, in that order: a pattern cut out
/// of the model cuts through whatever was embossed where it runs. Slivers
/// are then removed, and, unless a part is carved, sealed pockets of air
/// filled.
///
/// ```
/// use tracery_core::mesh::{Mesh, extrude};
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::surface::{Part, PartRole, assemble};
/// use tracery_core::DVec2;
/// let square = |x: f64| extrude(&Region::new(vec![Polygon {
///     outer: vec![DVec2::new(x, 0.0), DVec2::new(x + 2.0, 0.0), DVec2::new(x + 2.0, 2.0), DVec2::new(x, 2.0)],
///     holes: vec![],
/// }]), 1.0).unwrap();
/// let (a, b, c) = (square(0.0), square(1.0), square(5.0));
/// let parts: Vec<Part> = [&a, &b, &c].iter().map(|m| Part { solid_mm: m, role: PartRole::Add }).collect();
/// let object = assemble(None, false, &parts, &mut Default::default()).unwrap();
/// assert!(object.mesh_mm.sanity_check().is_ok());
/// assert_eq!(object.bodies, 2);
/// ```
pub fn assemble(
    model: Option<&SurfaceMesh>,
    with_model: bool,
    parts: &[Part<'_>],
    timings: &mut Timings,
) -> Result<Assembly, AssemblyError> {
    let walls = parts.iter().filter_map(|p| match p.role {
        PartRole::Carve { wall_mm } => Some(wall_mm),
        _ => None,
    });
    let wall_mm = walls.clone().reduce(f64::max);
    let embossed = with_model || parts.iter().any(|p| p.role == PartRole::Emboss);
    let mut warnings = Vec::new();
    let mut object: Option<Mesh> = match (wall_mm, embossed) {
        (None, false) => None,
        (Some(wall), _) => {
            let model = model.ok_or(AssemblyError::NoModel)?;
            if let Some(thinnest) = walls.clone().reduce(f64::min).filter(|&w| w < wall) {
                warnings.push(Warning::CarveWallsDiffer { shell_mm: wall, thinnest_mm: thinnest });
            }
            Some(timings.time("hollow", || hollow(model, wall))?)
        }
        (None, true) => Some(model.ok_or(AssemblyError::NoModel)?.mesh().clone()),
    };
    // Added parts first, carved ones last: see the doc comment.
    let mut order: Vec<&Part> = parts.iter().filter(|p| !matches!(p.role, PartRole::Carve { .. })).collect();
    order.extend(parts.iter().filter(|p| matches!(p.role, PartRole::Carve { .. })));
    for part in order {
        if part.solid_mm.triangles.is_empty() {
            continue;
        }
        object = Some(match (object, part.role) {
            (None, _) => part.solid_mm.clone(),
            (Some(o), PartRole::Carve { .. }) => timings.time("carve", || difference_solids(&o, part.solid_mm))?,
            (Some(o), _) => timings.time("unite", || union_solids(&o, part.solid_mm))?,
        });
    }
    let mut mesh_mm = object.ok_or(AssemblyError::Empty)?;
    let crumbs = mesh_mm.remove_crumbs(CRUMB_MM3);
    // Parts that together enclose some air (a scale arching over an
    // embossed ring) leave a sealed pocket, whose wall is a shell of its
    // own. Filled, the object is the same outside and one body. A carved
    // object keeps its hollow: there an inner shell is the hollowed model's
    // inside, which no pattern reached through.
    let cavities = if wall_mm.is_none() { mesh_mm.fill_cavities() } else { 0 };
    let bodies = mesh_mm.shell_count();
    if wall_mm.is_some() && bodies > 1 {
        warnings.push(Warning::CarvedApart { bodies });
    }
    Ok(Assembly { mesh_mm, bodies, wall_mm, crumbs, cavities, warnings })
}

/// Room left between the flat patterns of several parts laid one above
/// the other in a product's `region_mm`, mm: wide enough that no print
/// check mistakes it for a narrow gap.
const FLAT_SPACING_MM: f64 = 5.0;

/// [`assemble`] for the products of several modes made on one model (the
/// bands of curves on it, shades), into one product.
///
/// Its `mesh_mm` is the object; its `region_mm` the parts' flat patterns
/// laid one above the other, the first at the bottom, and its topology
/// theirs, summed. Warnings are gathered once each, timings summed, and the
/// facts give the number of `parts`, the object's `shells`, the
/// `crumbs_removed` and the `cavities_filled`.
pub fn assemble_products(
    model: Option<&SurfaceMesh>,
    with_model: bool,
    parts: &[(&Product, PartRole)],
) -> Result<Product, AssemblyError> {
    let mut product = Product::default();
    let mut bottom_mm = 0.0;
    for (part, _) in parts {
        if let Some(bounds) = part.region_mm.bounds() {
            let lift = DVec2::new(0.0, bottom_mm - bounds.min.y);
            product.region_mm.polygons.extend(part.region_mm.map_points(|p| p + lift).polygons);
            bottom_mm += bounds.max.y - bounds.min.y + FLAT_SPACING_MM;
        }
        product.topology.components += part.topology.components;
        product.topology.holes += part.topology.holes;
        product.topology.loop_openings += part.topology.loop_openings;
        product.timings.absorb(&part.timings);
        for w in &part.warnings {
            if !product.warnings.contains(w) {
                product.warnings.push(w.clone());
            }
        }
    }
    let solids: Vec<Part> =
        parts.iter().filter_map(|(p, role)| Some(Part { solid_mm: p.mesh_mm.as_ref()?, role: *role })).collect();
    let object = assemble(model, with_model, &solids, &mut product.timings)?;
    product.warnings.extend(object.warnings);
    product.fill_mm = fill_triangles(&product.region_mm);
    product.facts.push("parts", Fact::Count(parts.len()));
    product.facts.push("shells", Fact::Count(object.bodies));
    product.facts.push("crumbs_removed", Fact::Count(object.crumbs));
    product.facts.push("cavities_filled", Fact::Count(object.cavities));
    product.mesh_mm = Some(object.mesh_mm);
    Ok(product)
}

impl crate::control::MaybeCancelled for AssemblyError {
    fn is_cancelled(&self) -> bool {
        // Booleans run to the end; a newer request replaces their result.
        false
    }
}
