//! The vector brush in the app: exemplar picker, pattern controls, and its job.

use std::sync::Arc;

use egui::RichText;
use tracery_core::Product;
use tracery_core::control::Control;
use tracery_core::curve::{Along, Curve};
use tracery_core::vector_brush::{
    ALTERNATIVES, Exemplar, Settings, SlicingMode, SynthesisError, Target, make_alternatives, make_product,
};

use super::{ModeEnv, ModeJob, ModeUi, same};
use crate::command::Command;
use crate::document::{Document, DocumentError, ModeSettings, VectorBrushItem};
use crate::panels::exemplar_picker::exemplar_picker_ui;
use crate::state::Caches;

/// Cut lines offered when switching to uniform slicing.
const DEFAULT_UNIFORM_CUTS: usize = 8;

/// The vector brush's [`ModeUi`].
pub struct VectorBrushUi;

/// A vector-brush synthesis along one curve.
#[derive(Clone, Debug)]
pub struct VectorBrushJob {
    /// The smoothed curve, mm (shared with the app's cache).
    pub curve: Arc<Curve>,
    /// The exemplar.
    pub exemplar: Arc<Exemplar>,
    /// The settings.
    pub settings: Settings,
}

impl PartialEq for VectorBrushJob {
    fn eq(&self, other: &Self) -> bool {
        same(&self.curve, &other.curve) && self.settings == other.settings && same(&self.exemplar, &other.exemplar)
    }
}

impl VectorBrushJob {
    /// Runs the vector brush.
    pub fn run(&self, control: &Control) -> Result<Product, SynthesisError> {
        make_product(&self.exemplar, &Along::Curve(Curve::clone(&self.curve)), &self.settings, control)
    }

    /// Every alternative the gallery offers, the best first.
    pub fn alternatives(&self, control: &Control) -> Result<Vec<Product>, SynthesisError> {
        let along = Along::Curve(Curve::clone(&self.curve));
        make_alternatives(&self.exemplar, &along, &self.settings, ALTERNATIVES, control)
    }

    /// The same job for the best pattern.
    pub fn best(&self) -> VectorBrushJob {
        let mut settings = self.settings.clone();
        settings.alternative = 0;
        VectorBrushJob { settings, ..self.clone() }
    }
}

fn target_ui(ui: &mut egui::Ui, label: &str, target: &mut Target, single: u32, n_range: std::ops::RangeInclusive<u32>) {
    ui.horizontal(|ui| {
        let label = ui.label(label);
        ui.selectable_value(target, Target::Exactly(single), single.to_string());
        let n = match *target {
            Target::Exactly(n) if n != single => n,
            _ => *n_range.start(),
        };
        if ui.selectable_label(matches!(*target, Target::Exactly(m) if m != single), "N").clicked() {
            *target = Target::Exactly(n);
        }
        ui.selectable_value(target, Target::Any, "any");
        if let Target::Exactly(n) = target
            && *n != single
        {
            ui.add(egui::DragValue::new(n).range(n_range)).labelled_by(label.id);
        }
    });
}

/// The pattern controls of the vector brush.
pub fn pattern_ui(ui: &mut egui::Ui, s: &mut Settings, commands: &mut Vec<Command>) {
    target_ui(ui, "Components", &mut s.components, 1, 2..=100);
    target_ui(ui, "Holes", &mut s.holes, 0, 1..=500);
    ui.checkbox(&mut s.closed_pattern, "Closed pattern (loops run all around)");
    ui.add(egui::Slider::new(&mut s.band_mm, 2.0..=40.0).text("Band width (mm)"));
    let least_mm = s.corner_radius_least_mm();
    // In half millimetres: the arrow keys move a slider by its step, and
    // without one they stuck at the first round value past 0.
    let corners = egui::Slider::new(&mut s.corner_radius_mm, 0.0..=40.0).step_by(0.5).text("Corners (mm)");
    ui.add(corners).on_hover_text(format!(
        "The radius of the arcs that round the curve's sharp corners: at least {least_mm:.2} mm, which the band needs to turn \
         without folding; a larger radius squeezes the pattern less inside each corner"
    ));
    ui.checkbox(&mut s.flip, "Flip").on_hover_text(
        "Turn the pattern over to the other side of the curve. A loop's pattern faces the same way whichever way it \
         was drawn; an open stroke keeps the side it was drawn with",
    );
    ui.add(egui::Slider::new(&mut s.variety, 0.0..=2.0).text("Variety"));
    ui.add(egui::Slider::new(&mut s.scale, 0.25..=4.0).logarithmic(true).text("Scale"));
    ui.horizontal(|ui| {
        let label = ui.label("Slicing");
        ui.selectable_value(&mut s.slicing, SlicingMode::Topology, "topology");
        let cuts = if let SlicingMode::Uniform { cuts } = s.slicing { cuts } else { DEFAULT_UNIFORM_CUTS };
        ui.selectable_value(&mut s.slicing, SlicingMode::Uniform { cuts }, "uniform");
        if let SlicingMode::Uniform { cuts } = &mut s.slicing {
            ui.add(egui::DragValue::new(cuts).range(1..=40).suffix(" cuts")).labelled_by(label.id);
        }
    });
    ui.add(egui::Slider::new(&mut s.min_portal_mm, 0.0..=3.0).text("Min. portal (mm)"));
    ui.add(egui::Slider::new(&mut s.thickness_mm, 0.4..=10.0).text("Thickness (mm)"));
    ui.horizontal(|ui| {
        ui.label(format!("Solution {} of {ALTERNATIVES}", s.alternative + 1))
            .on_hover_text("1 is the best; the gallery below the canvas shows them all");
        if Command::AnotherOne.button(ui, true) {
            commands.push(Command::AnotherOne);
        }
    });
    ui.horizontal(|ui| {
        let label = ui.label("Seed");
        ui.add(egui::DragValue::new(&mut s.seed))
            .labelled_by(label.id)
            .on_hover_text("0 keeps the solutions as they are; any other number perturbs them at random");
    });
}

impl ModeUi for VectorBrushUi {
    fn name(&self) -> &'static str {
        "Vector brush"
    }

    fn default_settings(&self) -> ModeSettings {
        ModeSettings::VectorBrush(VectorBrushItem::default())
    }

    fn owns(&self, settings: &ModeSettings) -> bool {
        matches!(settings, ModeSettings::VectorBrush(_))
    }

    fn settings_ui(&self, ui: &mut egui::Ui, settings: &mut ModeSettings, env: &mut ModeEnv<'_>) {
        let ModeSettings::VectorBrush(item) = settings else { return };
        exemplar_picker_ui(ui, &mut item.exemplar, item.settings.slicing, env);
        ui.separator();
        ui.label(RichText::new("Pattern").strong());
        pattern_ui(ui, &mut item.settings, env.commands);
    }

    fn job(
        &self,
        curve: &Arc<Curve>,
        settings: &ModeSettings,
        doc: &Document,
        caches: &mut Caches,
    ) -> Result<ModeJob, DocumentError> {
        let ModeSettings::VectorBrush(item) = settings else {
            return Err(DocumentError::Exemplar("not a vector-brush curve".into()));
        };
        let exemplar = caches.exemplar(doc, &item.exemplar)?;
        Ok(ModeJob::VectorBrush(VectorBrushJob { curve: curve.clone(), exemplar, settings: item.settings.clone() }))
    }
}
