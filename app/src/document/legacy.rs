//! Format 0: projects and autosaves written before documents had a
//! `format_version` (one vector-brush curve list, counts as the controls
//! showed them). Read here and converted, never written.

use serde::Deserialize;
use tracery_core::vector_brush::{SlicingMode, Target};

use super::{CurveItem, Document, ExemplarRef, FORMAT_VERSION, ImportedExemplar, ModeSettings, VectorBrushItem};

/// A count target as format 0 stored it.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
pub enum CountV0 {
    /// Exactly one.
    One,
    /// Exactly zero.
    Zero,
    /// Exactly this many.
    Exactly(u32),
    /// Any number.
    Any,
}

impl From<CountV0> for Target {
    fn from(c: CountV0) -> Target {
        match c {
            CountV0::One => Target::Exactly(1),
            CountV0::Zero => Target::Exactly(0),
            CountV0::Exactly(n) => Target::Exactly(n),
            CountV0::Any => Target::Any,
        }
    }
}

/// Slicing as format 0 stored it.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
pub enum SlicingV0 {
    /// At topology events.
    Topology,
    /// Evenly, with this many cut lines.
    Uniform(u32),
}

/// A curve's settings in format 0, with that version's defaults.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(default)]
pub struct PatternSettingsV0 {
    exemplar: ExemplarRef,
    components: CountV0,
    holes: CountV0,
    closed_pattern: bool,
    band_mm: f64,
    variety: f64,
    scale: f64,
    slicing: SlicingV0,
    min_portal_mm: f64,
    thickness_mm: f64,
    seed: u64,
}

impl Default for PatternSettingsV0 {
    fn default() -> Self {
        PatternSettingsV0 {
            exemplar: ExemplarRef::Builtin("lace".into()),
            components: CountV0::One,
            holes: CountV0::Any,
            closed_pattern: true,
            band_mm: 10.0,
            variety: 0.3,
            scale: 1.0,
            slicing: SlicingV0::Topology,
            min_portal_mm: 0.0,
            thickness_mm: 2.0,
            seed: 0,
        }
    }
}

impl From<PatternSettingsV0> for ModeSettings {
    fn from(old: PatternSettingsV0) -> ModeSettings {
        let mut item = VectorBrushItem { exemplar: old.exemplar, ..VectorBrushItem::default() };
        let s = &mut item.settings;
        s.components = old.components.into();
        s.holes = old.holes.into();
        s.closed_pattern = old.closed_pattern;
        s.band_mm = old.band_mm;
        s.variety = old.variety;
        s.scale = old.scale;
        s.slicing = match old.slicing {
            SlicingV0::Topology => SlicingMode::Topology,
            SlicingV0::Uniform(cuts) => SlicingMode::Uniform { cuts: cuts as usize },
        };
        s.min_portal_mm = old.min_portal_mm;
        s.thickness_mm = old.thickness_mm;
        s.seed = old.seed;
        ModeSettings::VectorBrush(item)
    }
}

/// A curve in format 0.
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub struct CurveItemV0 {
    id: u64,
    points: Vec<[f64; 2]>,
    closed: bool,
    settings: PatternSettingsV0,
}

/// A whole format-0 document.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(default)]
pub struct DocumentV0 {
    curves: Vec<CurveItemV0>,
    imported: Vec<ImportedExemplar>,
    next_id: u64,
}

impl From<DocumentV0> for Document {
    fn from(old: DocumentV0) -> Document {
        Document {
            format_version: FORMAT_VERSION,
            curves: old
                .curves
                .into_iter()
                .map(|c| CurveItem {
                    id: c.id,
                    points: c.points,
                    closed: c.closed,
                    mode: c.settings.into(),
                    jump_rings: Default::default(),
                })
                .collect(),
            imported: old.imported,
            next_id: old.next_id,
            ..Document::default()
        }
    }
}
