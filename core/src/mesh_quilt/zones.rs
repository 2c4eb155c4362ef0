//! [`Zones`]: where a point of the output lies for the patch being merged,
//! whether the output is a plane (a grid of cells) or a curved base (its
//! faces, marked as they are covered). Merging asks only this, so one
//! merge serves both.

use glam::DVec3;

/// Where a point lies for one patch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Zone {
    /// Made by earlier patches, outside this one.
    Old,
    /// Made by earlier patches and covered by this one.
    Overlap,
    /// Covered by this patch for the first time.
    New,
    /// Neither.
    Outside,
}

impl Zone {
    /// Whether the patch covers it (its new cells or its overlap).
    pub fn in_patch(self) -> bool {
        matches!(self, Zone::New | Zone::Overlap)
    }
}

/// The output's layout for the patch being merged.
pub(super) trait Zones: Sync {
    /// The size of a matching cell, mm: lengths in the cut's weights are
    /// measured in cells.
    fn cell_mm(&self) -> f64;

    /// Where `p` (output space, mm) lies for the current patch.
    fn zone(&self, p: DVec3) -> Zone;

    /// Whether `p` lies within `cells` cells of the patch's footprint.
    fn near_footprint(&self, p: DVec3, cells: f64) -> bool;

    /// A box (low and high corners, mm) holding everything within a few
    /// cells of the patch's footprint: output elements outside it are not
    /// looked at.
    fn near_box(&self, margin_mm: f64) -> (DVec3, DVec3);

    /// The base's point nearest `p` and its outward normal there: heights
    /// above the base are measured along it.
    fn base(&self, p: DVec3) -> (DVec3, DVec3);

    /// Whether a model lies under the texture, which an element may dip
    /// into; under a plane's texture lies the print bed.
    fn model_below(&self) -> bool;
}

/// Whether two boxes overlap.
pub(super) fn boxes_overlap(a: (DVec3, DVec3), b: (DVec3, DVec3)) -> bool {
    a.0.cmple(b.1).all() && b.0.cmple(a.1).all()
}
