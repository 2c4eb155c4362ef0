//! [`make_product`]: a quilt as the [`Product`] every mode returns, its
//! elements one mesh of separate closed shells, with its figures.

use super::matching::reach_mm;
use super::resting::{keep_held, rests_on};
use super::{
    Element, GuidanceField, Quilt, QuiltError, Settings, Swatch, Trimmed, bare_share, crosses_itself, floor_of,
    quilt_plane, quilt_surface, swatch_bare_share, trim_below, trim_to_area,
};
use crate::control::Control;
use crate::mesh::Mesh;
use crate::product::{Fact, Product};
use crate::report::Warning;
use crate::surface::{PartRole, SurfaceMesh, assemble_products};

/// How near the model a piece cut at the floor must come to count as
/// resting on it when nothing sinks, mm.
const TOUCH_TOLERANCE_MM: f64 = 0.05;

/// A quilt is sparse, and says so, when it leaves more of its model bare
/// than the swatch leaves of a plane by this share of the area.
const SPARSE_MARGIN: f64 = 0.2;

/// What the quilt covers.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Base {
    /// A `width_mm` × `depth_mm` area of the plane.
    Plane {
        /// Along `x`, mm.
        width_mm: f64,
        /// Along `y`, mm.
        depth_mm: f64,
    },
}

/// Reads `plane:WIDTHxDEPTH` (mm).
///
/// ```
/// use tracery_core::mesh_quilt::{Base, parse_base};
/// assert_eq!(parse_base("plane:60x40").unwrap(), Base::Plane { width_mm: 60.0, depth_mm: 40.0 });
/// assert!(parse_base("plane:60").is_err());
/// ```
pub fn parse_base(spec: &str) -> Result<Base, QuiltError> {
    let bad = || QuiltError::BadBase(spec.to_string());
    let size = spec.strip_prefix("plane:").ok_or_else(bad)?;
    let (w, d) = size.split_once('x').ok_or_else(bad)?;
    let (width_mm, depth_mm) =
        (w.trim().parse::<f64>().map_err(|_| bad())?, d.trim().parse::<f64>().map_err(|_| bad())?);
    let world = 0.0..=crate::setting::WORLD_EXTENT_MM;
    let why = "larger than any printer's bed";
    crate::setting::within("base", "the plane's width", width_mm, world.clone(), true, " mm", why)?;
    crate::setting::within("base", "the plane's depth", depth_mm, world, true, " mm", why)?;
    Ok(Base::Plane { width_mm, depth_mm })
}

/// Quilts `base` with `swatch` at the settings' scale: the elements as one
/// mesh of closed shells (a body each), and the counts in its facts.
pub fn make_product(
    swatch: &Swatch,
    base: Base,
    settings: &Settings,
    control: &Control,
) -> Result<Product, QuiltError> {
    settings.validate()?;
    let mut product = Product::default();
    let swatch = swatch.scaled(settings.scale);
    let Base::Plane { width_mm, depth_mm } = base;
    let mut quilt = product.timings.time("quilt", || quilt_plane(&swatch, width_mm, depth_mm, settings, control))?;
    // What is left of a thread past the edge is kept on the terms the quilt
    // keeps any fragment.
    let least_mm3 = swatch.fragment_volume_mm3();
    let trimmed = product.timings.time("edge", || trim_to_area(&mut quilt.elements, width_mm, depth_mm, least_mm3))?;
    // Stitches that would pass through themselves are refused, but a whole
    // element of an imported swatch is taken as it is: the count says so.
    let self_crossing = quilt.elements.iter().filter(|e| crosses_itself(e)).count();
    describe(&mut product, &quilt, &swatch, self_crossing);
    product.facts.push("cut_at_edge", Fact::Count(trimmed.cut));
    product.facts.push("removed_at_edge", Fact::Count(trimmed.crumbs));
    Ok(product)
}

/// Quilts the curved `surface` with `swatch` at the settings' scale, along
/// `field` ([`GuidanceField::around_axis`] for a vase), in a shell as thick
/// as the scaled swatch: the texture alone, its elements one
/// mesh of closed shells, with the shell's stretch before and after tuning
/// among the facts. Elements reaching below the plane the model stands on
/// are cut off flat there (the fact `cut_at_floor` counts them).
pub fn make_surface_product(
    swatch: &Swatch,
    surface: &SurfaceMesh,
    field: &GuidanceField,
    settings: &Settings,
    control: &Control,
) -> Result<Product, QuiltError> {
    settings.validate()?;
    let mut product = Product::default();
    let swatch = swatch.scaled(settings.scale);
    let mut quilt = product.timings.time("quilt", || quilt_surface(&swatch, surface, field, settings, control))?;
    // A piece left by the cut is kept where it still rests on the model:
    // sunk into it at least half the sink (a piece only grazing the foot's
    // edge would print loose), or touching it when nothing sinks.
    let rest_depth_mm = 0.5 * settings.sink_mm - TOUCH_TOLERANCE_MM;
    let rests = |piece: &Element| rests_on(piece, surface, rest_depth_mm);
    // The shell can bend a whole element through itself where the model
    // turns tightly (a vase's neck). Such an element prints wrong, and a
    // boolean's result made from it can come out pinched. It is left out
    // (after the floor's cut, which takes some such bottoms off).
    let trimmed = match floor_of(surface) {
        Some(floor_z_mm) => product.timings.time("floor", || trim_below(&mut quilt.elements, floor_z_mm, rests))?,
        None => Trimmed::default(),
    };
    let before = quilt.elements.len();
    product.timings.time("self-crossing", || quilt.elements.retain(|e| !crosses_itself(e)));
    let bent = before - quilt.elements.len();
    // An element resting nowhere on the model, nor hanging from one that
    // does as the swatch's floating elements do, would print loose.
    let hold_mm = reach_mm(&swatch);
    let floating = product.timings.time("floating", || {
        keep_held(&mut quilt.elements, surface, &swatch, settings.sink_mm, rest_depth_mm, hold_mm)
    });
    if quilt.elements.is_empty() {
        return Err(QuiltError::NothingPlaced(format!(
            "{} laid, {} left out crossing others, {} removed below where it stands, {} bent through \
             themselves, {} resting nowhere on it",
            quilt.counts.merges.added + quilt.counts.merges.replaced + quilt.counts.merges.kept,
            quilt.counts.merges.collided,
            trimmed.removed + trimmed.crumbs,
            bent,
            floating,
        )));
    }
    // Those that crossed themselves were just left out.
    describe(&mut product, &quilt, &swatch, 0);
    // Measured within half a grid cell: how much of the model the texture
    // leaves bare, against how much the swatch leaves bare by design.
    let reach_mm = 0.5 * swatch.size_mm().truncate().min_element() / settings.cells_across as f64;
    let bare = product.timings.time("coverage", || bare_share(surface, &quilt.elements, reach_mm));
    let swatch_bare = swatch_bare_share(&swatch, settings.sink_mm, reach_mm);
    product.facts.push("bare_share", Fact::Number(bare));
    product.facts.push("swatch_bare_share", Fact::Number(swatch_bare));
    if bare > swatch_bare + SPARSE_MARGIN {
        product
            .warnings
            .push(Warning::QuiltSparse { bare_percent: 100.0 * bare, swatch_bare_percent: 100.0 * swatch_bare });
    }
    product.facts.push("left_out_self_crossing", Fact::Count(bent));
    product.facts.push("left_out_floating", Fact::Count(floating));
    product.facts.push("cut_at_floor", Fact::Count(trimmed.cut));
    product.facts.push("removed_at_floor", Fact::Count(trimmed.removed + trimmed.crumbs));
    if let Some(shell) = quilt.shell {
        let facts = &mut product.facts;
        facts.push("shell_l2_stretch_normals", Fact::Number(shell.before.l2));
        facts.push("shell_inverted_normals", Fact::Count(shell.before.inverted));
        facts.push("shell_l2_stretch", Fact::Number(shell.after.l2));
        facts.push("shell_inverted", Fact::Count(shell.after.inverted));
        facts.push("max_patch_area_distortion", Fact::Number(shell.max_patch_distortion));
        facts.push("bare_seeds", Fact::Count(shell.bare_seeds));
        facts.push("cut_at_rim", Fact::Count(shell.cut_at_rim));
        facts.push("cut_under_rim", Fact::Count(shell.cut_under_rim));
        facts.push("left_out_torn", Fact::Count(shell.torn));
    }
    Ok(product)
}

/// The texture of [`make_surface_product`] united with the model it was
/// made on into one solid: the model's shape with the texture standing out
/// of it, as one body where every element rests on the model (they sink
/// into it by [`Settings::sink_mm`]). The fact `shells` counts the bodies;
/// the texture's facts are kept.
pub fn unite_with_base(texture: Product, surface: &SurfaceMesh) -> Result<Product, QuiltError> {
    let object = assemble_products(Some(surface), true, &[(&texture, PartRole::Add)])?;
    let mut product = texture;
    product.timings = object.timings;
    product.warnings = object.warnings;
    product.mesh_mm = object.mesh_mm;
    for fact in ["crumbs_removed", "cavities_filled"] {
        product.facts.push(fact, Fact::Count(object.facts.count(fact).unwrap_or(0)));
    }
    let shells = product.mesh_mm.as_ref().map_or(0, |m| m.shell_count());
    product.topology.components = shells;
    product.facts.push("shells", Fact::Count(shells));
    Ok(product)
}

/// The quilt's elements as the product's mesh, with its counts, of which
/// `self_crossing` elements pass through themselves.
fn describe(product: &mut Product, quilt: &Quilt, swatch: &Swatch, self_crossing: usize) {
    let mut mesh = Mesh::default();
    for e in &quilt.elements {
        mesh.append(&e.to_mesh());
    }
    let closed = quilt.elements.iter().filter(|e| e.is_closed()).count();
    let m = &quilt.counts.merges;
    product.topology.components = quilt.elements.len();
    let facts = &mut product.facts;
    facts.push("elements", Fact::Count(quilt.elements.len()));
    facts.push("closed_elements", Fact::Count(closed));
    facts.push("self_crossing_elements", Fact::Count(self_crossing));
    facts.push("swatch_elements", Fact::Count(swatch.elements.len()));
    facts.push("patches", Fact::Count(quilt.counts.patches));
    facts.push("stitched", Fact::Count(m.stitched));
    facts.push("unstitched", Fact::Count(m.unstitched));
    facts.push("replaced_whole", Fact::Count(m.replaced));
    facts.push("kept_whole", Fact::Count(m.kept));
    facts.push("added_whole", Fact::Count(m.added));
    facts.push("left_out_crossing", Fact::Count(m.collided));
    facts.push("fragments_removed", Fact::Count(quilt.counts.fragments));
    facts.push("faces", Fact::Count(mesh.triangles.len()));
    product.mesh_mm = Some(mesh);
}
