//! The document a person edits: curves, imported exemplars, and their settings.
//! Saved as `.ron`; imported exemplars are embedded so a project opens anywhere.

use serde::{Deserialize, Serialize};
use tracery_core::{DVec2, Exemplar, LoadOptions, SlicingMode, SynthesisRequest, Target, builtin};

/// Which exemplar a curve uses.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ExemplarRef {
    /// A built-in exemplar, by name.
    Builtin(String),
    /// An imported exemplar, by its name in [`Document::imported`].
    Imported(String),
}

impl ExemplarRef {
    /// The name shown to people.
    pub fn name(&self) -> &str {
        match self {
            ExemplarRef::Builtin(n) | ExemplarRef::Imported(n) => n,
        }
    }
}

/// A count target as the controls show it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Count {
    /// Exactly one.
    One,
    /// Exactly zero.
    Zero,
    /// Exactly this many.
    Exactly(u32),
    /// Any number.
    Any,
}

impl Count {
    /// The solver target.
    pub fn target(self) -> Target {
        match self {
            Count::One => Target::Exactly(1),
            Count::Zero => Target::Exactly(0),
            Count::Exactly(n) => Target::Exactly(n),
            Count::Any => Target::Any,
        }
    }
}

/// How the exemplar is cut, as the controls show it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Slicing {
    /// At topology events.
    Topology,
    /// Evenly, with this many cut lines.
    Uniform(u32),
}

/// Everything that decides a curve's pattern besides its shape.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PatternSettings {
    /// The exemplar.
    pub exemplar: ExemplarRef,
    /// Components wanted.
    pub components: Count,
    /// Holes wanted.
    pub holes: Count,
    /// On loops, the pattern runs all around.
    pub closed_pattern: bool,
    /// Band width across the curve, mm.
    pub band_mm: f64,
    /// Variety (autocorrelation penalty).
    pub variety: f64,
    /// Exemplar scale relative to fitting its height to the band.
    pub scale: f64,
    /// How the exemplar is cut.
    pub slicing: Slicing,
    /// Cuts through thinner features are dropped, mm.
    pub min_portal_mm: f64,
    /// Printed thickness, mm.
    pub thickness_mm: f64,
    /// 0 for the best pattern; "another one" picks a new seed.
    pub seed: u64,
}

impl Default for PatternSettings {
    fn default() -> Self {
        PatternSettings {
            exemplar: ExemplarRef::Builtin("lace".into()),
            components: Count::One,
            holes: Count::Any,
            closed_pattern: true,
            band_mm: 10.0,
            variety: 0.3,
            scale: 1.0,
            slicing: Slicing::Topology,
            min_portal_mm: 0.0,
            thickness_mm: 2.0,
            seed: 0,
        }
    }
}

impl PatternSettings {
    /// The synthesis request for an exemplar of `exemplar_height` units.
    pub fn request(&self, exemplar_height: f64) -> SynthesisRequest {
        let mut r = SynthesisRequest::default();
        r.band_mm = self.band_mm;
        r.components = self.components.target();
        r.holes = self.holes.target();
        r.closed_pattern = self.closed_pattern;
        r.variety = self.variety;
        r.slicing = match self.slicing {
            Slicing::Topology => SlicingMode::Topology,
            Slicing::Uniform(t) => SlicingMode::Uniform { cuts: t as usize },
        };
        r.min_portal_mm = self.min_portal_mm;
        r.scale_mm_per_unit = Some(self.scale * self.band_mm / exemplar_height.max(1e-9));
        r.seed = self.seed;
        r
    }
}

/// One curve and its pattern settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CurveItem {
    /// Stable id (for results and selection).
    pub id: u64,
    /// Control points in mm, `y` up; the curve is smoothed through them.
    pub points: Vec<[f64; 2]>,
    /// Whether the curve is a loop.
    pub closed: bool,
    /// Its pattern settings.
    pub settings: PatternSettings,
}

impl CurveItem {
    /// The control points as vectors.
    pub fn control_points(&self) -> Vec<DVec2> {
        self.points.iter().map(|p| DVec2::new(p[0], p[1])).collect()
    }

    /// The smooth curve through the control points.
    pub fn curve(&self) -> Option<tracery_core::Curve> {
        tracery_core::Curve::from_stroke(&self.control_points(), self.closed, 0.5).ok()
    }
}

/// An exemplar imported from SVG, embedded in the document.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImportedExemplar {
    /// Name (from the file name), unique in the document.
    pub name: String,
    /// The SVG source.
    pub svg: String,
}

/// A Tracery project.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Document {
    /// Curves, in drawing order.
    pub curves: Vec<CurveItem>,
    /// Imported exemplars.
    pub imported: Vec<ImportedExemplar>,
    /// The next curve id.
    pub next_id: u64,
}

impl Document {
    /// Adds a curve and returns its id.
    pub fn add_curve(&mut self, points: Vec<DVec2>, closed: bool, settings: PatternSettings) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        self.curves.push(CurveItem { id, points: points.iter().map(|p| [p.x, p.y]).collect(), closed, settings });
        id
    }

    /// The curve with `id`.
    pub fn curve(&self, id: u64) -> Option<&CurveItem> {
        self.curves.iter().find(|c| c.id == id)
    }

    /// The curve with `id`, mutable.
    pub fn curve_mut(&mut self, id: u64) -> Option<&mut CurveItem> {
        self.curves.iter_mut().find(|c| c.id == id)
    }

    /// Loads the exemplar a curve refers to.
    pub fn exemplar(&self, r: &ExemplarRef) -> Result<Exemplar, String> {
        match r {
            ExemplarRef::Builtin(name) => builtin(name).map_err(|e| e.to_string()),
            ExemplarRef::Imported(name) => {
                let imported = self
                    .imported
                    .iter()
                    .find(|e| &e.name == name)
                    .ok_or_else(|| format!("the imported exemplar '{name}' is missing"))?;
                Exemplar::from_svg_str(name.clone(), &imported.svg, &LoadOptions::default()).map_err(|e| e.to_string())
            }
        }
    }

    /// Imports an SVG exemplar, checking it loads; returns its reference.
    pub fn import(&mut self, file_name: &str, svg: &str) -> Result<ExemplarRef, String> {
        let base = std::path::Path::new(file_name)
            .file_stem()
            .map_or_else(|| "imported".to_string(), |s| s.to_string_lossy().into_owned());
        Exemplar::from_svg_str(base.clone(), svg, &LoadOptions::default()).map_err(|e| format!("{file_name}: {e}"))?;
        let mut name = base.clone();
        let mut k = 2;
        while self.imported.iter().any(|e| e.name == name) || tracery_core::BUILTIN_NAMES.contains(&name.as_str()) {
            name = format!("{base} {k}");
            k += 1;
        }
        self.imported.push(ImportedExemplar { name: name.clone(), svg: svg.to_string() });
        Ok(ExemplarRef::Imported(name))
    }

    /// The document as `.ron` text.
    pub fn to_ron(&self) -> Result<String, String> {
        ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default()).map_err(|e| e.to_string())
    }

    /// A document from `.ron` text.
    pub fn from_ron(text: &str) -> Result<Document, String> {
        ron::from_str(text).map_err(|e| format!("not a Tracery project: {e}"))
    }
}

/// Undo and redo by snapshots of the document.
#[derive(Debug, Default)]
pub struct History {
    undo: Vec<Document>,
    redo: Vec<Document>,
}

/// Most undo steps kept.
const HISTORY_LIMIT: usize = 200;

impl History {
    /// Records `before` as the state to return to.
    pub fn record(&mut self, before: Document) {
        if self.undo.last() == Some(&before) {
            return;
        }
        self.undo.push(before);
        if self.undo.len() > HISTORY_LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
    }

    /// Steps back; `current` becomes redoable.
    pub fn undo(&mut self, current: &mut Document) -> bool {
        match self.undo.pop() {
            Some(previous) => {
                self.redo.push(std::mem::replace(current, previous));
                true
            }
            None => false,
        }
    }

    /// Steps forward again.
    pub fn redo(&mut self, current: &mut Document) -> bool {
        match self.redo.pop() {
            Some(next) => {
                self.undo.push(std::mem::replace(current, next));
                true
            }
            None => false,
        }
    }

    /// Whether there is something to undo.
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    /// Whether there is something to redo.
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }
}
