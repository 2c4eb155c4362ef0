//! The pen: a curve drawn with a round pen of a chosen width, as it prints.
//! Pen strokes inside a region fill are what the person drew there: the
//! fill grows around them and prints them as part of its one solid.

use std::sync::Arc;

use tracery_core::Product;
use tracery_core::curve::Curve;
use tracery_core::geom::{Region, brush_stroke, count_topology, fill_triangles};
use tracery_core::mesh::extrude;
use tracery_core::product::StrokedPath;
use tracery_core::region_fill::{FillError, region_from_outlines};

use super::{ModeEnv, ModeJob, ModeUi, same};
use crate::document::{Document, DocumentError, ModeSettings, PenItem};
use crate::state::Caches;

/// The pen's [`ModeUi`].
pub struct PenUi;

/// A pen stroke along one curve.
#[derive(Clone, Debug)]
pub struct PenJob {
    /// The smoothed curve, mm.
    pub curve: Arc<Curve>,
    /// The pen.
    pub pen: PenItem,
    /// Whether it lies in a region fill, whose solid prints it.
    pub in_fill: bool,
}

impl PartialEq for PenJob {
    fn eq(&self, other: &Self) -> bool {
        same(&self.curve, &other.curve) && self.pen == other.pen && self.in_fill == other.in_fill
    }
}

impl PenJob {
    /// The stroke's outline (or the filled shape) and, outside a fill, its solid.
    pub fn run(&self) -> Result<Product, FillError> {
        let closed = self.curve.is_closed();
        let filled = self.pen.fills(closed);
        let region = if filled {
            region_from_outlines(&[self.curve.points().to_vec()])?
        } else {
            brush_stroke(self.curve.points(), self.pen.width_mm, closed)
        };
        let topology = count_topology(&region);
        let mesh_mm = if self.in_fill { None } else { Some(extrude(&region, self.pen.thickness_mm)?) };
        let paths_mm = if filled {
            Vec::new()
        } else {
            vec![StrokedPath { points_mm: self.curve.points().to_vec(), closed, width_mm: self.pen.width_mm }]
        };
        let mut product = Product {
            fill_mm: fill_triangles(&region),
            paths_mm,
            // A filled shape is drawn filled in the SVG.
            filled_mm: if filled { region.clone() } else { Region::default() },
            mesh_mm,
            topology: topology.into(),
            ..Product::default()
        };
        // Inside a fill, the fill's solid and outline hold this stroke.
        if !self.in_fill {
            product.region_mm = region;
        }
        Ok(product)
    }
}

impl ModeUi for PenUi {
    fn name(&self) -> &'static str {
        "Pen"
    }

    fn default_settings(&self) -> ModeSettings {
        ModeSettings::Pen(PenItem::default())
    }

    fn owns(&self, settings: &ModeSettings) -> bool {
        matches!(settings, ModeSettings::Pen(_))
    }

    fn settings_ui(&self, ui: &mut egui::Ui, settings: &mut ModeSettings, _env: &mut ModeEnv<'_>) {
        let ModeSettings::Pen(pen) = settings else { return };
        ui.checkbox(&mut pen.filled, "Filled").on_hover_text(
            "A closed stroke is a filled shape, such as a berry or a dot; in a fill like one of its exemplar's \
             elements, it is that element",
        );
        ui.add_enabled(!pen.filled, egui::Slider::new(&mut pen.width_mm, 0.3..=5.0).text("Pen width (mm)"));
        ui.add(egui::Slider::new(&mut pen.thickness_mm, 0.4..=10.0).text("Thickness (mm)"));
        ui.label(
            egui::RichText::new("Inside a region fill, pen strokes are yours: the fill grows around them.").weak(),
        );
    }

    fn job(
        &self,
        curve: &Arc<Curve>,
        settings: &ModeSettings,
        doc: &Document,
        caches: &mut Caches,
    ) -> Result<ModeJob, DocumentError> {
        let ModeSettings::Pen(pen) = settings else {
            return Err(DocumentError::Exemplar("not a pen stroke".into()));
        };
        let in_fill = doc.curves.iter().any(|c| {
            matches!(c.mode, ModeSettings::RegionFill(_))
                && caches
                    .smoothed(c.id)
                    .is_some_and(|outline| crate::document::inside(outline.points(), curve.points()))
        });
        Ok(ModeJob::Pen(PenJob { curve: curve.clone(), pen: pen.clone(), in_fill }))
    }
}
