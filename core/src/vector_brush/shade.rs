//! Lamp shades from the vector brush (section 6.2 of the paper, with rows
//! that differ): rows of pattern, each made along a closed circle as long as
//! the shade's girth at its height, laid on a cylinder or a cone by
//! [`crate::surface::wrap_rows`].

use rayon::prelude::*;

use super::{Exemplar, InvalidSetting, Settings, Synthesis, SynthesisError, Target, synthesize};
use crate::Product;
use crate::control::{Control, MaybeCancelled};
use crate::curve::Curve;
use crate::geom::fill_triangles;
use crate::product::{Fact, Facts};
use crate::report::Timings;
use crate::surface::{RowPlace, ShadeError, ShadeSettings, WrapError, Wrapped, wrap_rows};

/// Why a shade could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ShadeSynthesisError {
    /// A vector-brush setting is out of range.
    #[error(transparent)]
    Setting(#[from] InvalidSetting),
    /// The shade's shape or rows are wrong.
    #[error(transparent)]
    Shape(#[from] ShadeError),
    /// A row could not be made.
    #[error("row {row} of the shade (from the bottom): {source}")]
    Row {
        /// Which row, from 1 at the bottom.
        row: usize,
        /// Why.
        source: SynthesisError,
    },
    /// One piece was asked for, and the rows do not touch.
    #[error(
        "the shade falls into {components} pieces: its rows do not touch even overlapping by {overlap_mm:.1} mm; raise --row-overlap, or ask for --components any to have the pieces anyway"
    )]
    Apart {
        /// Separate pieces.
        components: usize,
        /// The largest overlap tried, mm.
        overlap_mm: f64,
    },
    /// The rows could not be made solid.
    #[error(transparent)]
    Wrap(#[from] WrapError),
    /// A fault in Tracery itself, caught in a worker.
    #[error(transparent)]
    Internal(#[from] crate::control::Internal),
}

impl MaybeCancelled for ShadeSynthesisError {
    fn is_cancelled(&self) -> bool {
        matches!(self, ShadeSynthesisError::Row { source, .. } if source.is_cancelled())
    }
}

/// The seed of row (or strip) `row`: the person's own for the first, and
/// one drawn from it for each next, so that rows differ and the same
/// settings always give the same result.
pub(crate) fn derived_seed(seed: u64, row: usize) -> u64 {
    if row == 0 {
        return seed;
    }
    // Nearby rows give unrelated seeds.
    crate::random::mix(seed ^ crate::random::steps(row as u64)).max(1)
}

/// Each retry lays the rows closer by this share of the band.
const OVERLAP_STEP: f64 = 0.15;

/// More pieces than this per row, not falling as rows are laid closer,
/// means the rows are made of islands: trying closer still is given up.
const ISLAND_PIECES_PER_ROW: usize = 2;

/// Rows overlap by at most this share of the band: beyond it, a row would
/// hide more than half of its neighbour.
const MAX_OVERLAP: f64 = 0.5;

type Rows = Vec<(Synthesis, RowPlace)>;

/// Makes every row of `shade` (in parallel) and wraps them.
fn made_rows(
    exemplar: &Exemplar,
    shade: &ShadeSettings,
    settings: &Settings,
    control: &Control,
    timings: &mut Timings,
) -> Result<(Rows, Wrapped), ShadeSynthesisError> {
    let places = shade.rows(settings.band_mm)?;
    let done = std::sync::atomic::AtomicUsize::new(0);
    let rows: Rows = places
        .par_iter()
        .enumerate()
        .map(|(k, place)| {
            let mut row_settings = settings.clone();
            row_settings.band_mm = place.band_mm;
            row_settings.seed = derived_seed(settings.seed, k);
            row_settings.closed_pattern = true;
            let fail = |source: SynthesisError| ShadeSynthesisError::Row { row: k + 1, source };
            let circle = Curve::circle(place.radius_mm).map_err(|e| fail(e.into()))?;
            let synthesis = match synthesize(exemplar, &circle, &row_settings, &control.silent()) {
                // The shade's own topology is counted on the whole: rows that
                // cannot each be one piece may still fuse with their
                // neighbours and the rims into one.
                Err(SynthesisError::Solve(e)) if !e.is_cancelled() && row_settings.components != Target::Any => {
                    row_settings.components = Target::Any;
                    row_settings.holes = Target::Any;
                    synthesize(exemplar, &circle, &row_settings, &control.silent()).map_err(fail)?
                }
                result => result.map_err(fail)?,
            };
            let finished = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            control.report(0.9 * finished as f32 / places.len() as f32);
            Ok((synthesis, *place))
        })
        .collect::<Result<_, ShadeSynthesisError>>()?;
    for (synthesis, _) in &rows {
        timings.absorb(&synthesis.timings);
    }
    let laid: Vec<_> = rows.iter().map(|(s, place)| (s.planar.region.clone(), *place)).collect();
    let wrapped = timings.time("wrap", || wrap_rows(&laid, shade, settings.thickness_mm))?;
    Ok((rows, wrapped))
}

/// A lamp shade: rows of `exemplar` about `settings.band_mm` high, each made
/// with every vector-brush setting (targets, variety) along a closed circle
/// as long as the shade's girth there, each with its own seed, then welded
/// with the rims and made `settings.thickness_mm` thick on the surface.
///
/// The product's `mesh_mm` is the shade standing on `z = 0`; `region_mm` is
/// its development (the pattern laid flat, for a laser or a picture).
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::surface::{Shade, ShadeSettings};
/// use tracery_core::vector_brush::{Settings, builtin, make_shade};
/// let mut shade = ShadeSettings::default();
/// shade.shade = Shade::cylinder(20.0, 30.0).unwrap();
/// let product = make_shade(&builtin("lace").unwrap(), &shade, &Settings::default(), &Control::default()).unwrap();
/// let mesh = product.mesh_mm.unwrap();
/// assert!(mesh.sanity_check().is_ok());
/// assert_eq!(mesh.shell_count(), 1);
/// ```
pub fn make_shade(
    exemplar: &Exemplar,
    shade: &ShadeSettings,
    settings: &Settings,
    control: &Control,
) -> Result<Product, ShadeSynthesisError> {
    // The shade itself is checked by the first `ShadeSettings::rows`.
    settings.validate()?;
    let mut timings = Timings::default();
    let mut warnings = Vec::new();
    let mut layout = shade.clone();
    // Rows fuse only where both hold material in their overlap. When one
    // piece is asked for and they do not fuse, they are laid closer.
    let mut pieces_before = usize::MAX;
    let (rows, wrapped) = loop {
        let (rows, wrapped) = made_rows(exemplar, &layout, settings, control, &mut timings)?;
        let pieces = wrapped.topology.components;
        let apart = pieces > 1 && settings.components == Target::Exactly(1);
        let closer = layout.row_overlap_mm + OVERLAP_STEP * settings.band_mm;
        if !apart {
            break (rows, wrapped);
        }
        // Rows made of islands (more than two pieces a row) stay apart
        // however close they are laid: when laying them closer joined
        // nothing, the next try would not either. Rows merely slow to fuse
        // (a few pieces) get every try.
        let islands = pieces > ISLAND_PIECES_PER_ROW * rows.len() && pieces >= pieces_before;
        if closer > MAX_OVERLAP * settings.band_mm || islands {
            return Err(ShadeSynthesisError::Apart {
                components: wrapped.topology.components,
                overlap_mm: layout.row_overlap_mm,
            });
        }
        layout.row_overlap_mm = closer;
        pieces_before = pieces;
    };
    for (synthesis, _) in &rows {
        for w in &synthesis.warnings {
            if !warnings.contains(w) {
                warnings.push(w.clone());
            }
        }
    }
    let mut facts = Facts::default();
    facts.push("rows", Fact::Count(rows.len()));
    facts.push("row_overlap_mm", Fact::Number(layout.row_overlap_mm));
    facts.push("row_band_mm", Fact::Number(rows[0].1.band_mm));
    facts.push("slant_height_mm", Fact::Number(shade.shade.slant_height_mm()));
    facts.push("pieces", Fact::Count(rows.iter().map(|(s, _)| s.solution.pieces.len()).sum()));
    facts.push("stretch_percent", Fact::Number(wrapped.stretch_percent));
    facts.push("thickness_mm", Fact::Number(settings.thickness_mm));
    facts.push("shells", Fact::Count(wrapped.mesh_mm.shell_count()));
    Ok(Product {
        fill_mm: fill_triangles(&wrapped.development_mm),
        region_mm: wrapped.development_mm,
        mesh_mm: Some(wrapped.mesh_mm),
        topology: wrapped.topology,
        warnings,
        timings,
        facts,
        ..Product::default()
    })
}
