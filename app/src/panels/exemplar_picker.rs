//! The exemplar picker: thumbnails of the built-in and imported exemplars,
//! "Import SVG…", and how the chosen one is cut.

use egui::{Color32, RichText, Stroke};
use tracery_core::DVec2;
use tracery_core::mesh::extrude;
use tracery_core::vector_brush::{BUILTIN_NAMES, Exemplar, PieceSet, SliceOptions, SlicingMode};

use crate::canvas::{View, fill};
use crate::command::Command;
use crate::document::ExemplarRef;
use crate::modes::ModeEnv;
use crate::state::ExemplarPicture;

/// Thumbnail size, points.
const THUMBNAIL: egui::Vec2 = egui::vec2(110.0, 30.0);
/// Height of the "how it is cut" picture, points.
const CUT_VIEW_HEIGHT: f32 = 56.0;
/// Golden-ratio hue step, so neighbouring pieces get distinct colours.
const HUE_STEP: f32 = 0.618;

/// The picture of `exemplar` cut with `slicing`: each piece triangulated.
pub fn picture(exemplar: &Exemplar, slicing: SlicingMode) -> Option<ExemplarPicture> {
    let mut options = SliceOptions::default();
    options.mode = slicing;
    let set = PieceSet::new(exemplar, &options).ok()?;
    // Any thickness will do: only the top faces are drawn.
    let pieces =
        set.pieces.iter().map(|p| extrude(&p.region, 1.0).map(|m| m.top_faces()).unwrap_or_default()).collect();
    Some(ExemplarPicture { bounds: exemplar.bounds, pieces, cuts: set.cuts.clone() })
}

/// One exemplar drawn in `size`; with `cuts`, pieces in colour and the cut lines.
fn exemplar_picture_ui(
    ui: &mut egui::Ui,
    env: &mut ModeEnv<'_>,
    r: &ExemplarRef,
    slicing: SlicingMode,
    size: egui::Vec2,
    cuts: bool,
) -> egui::Response {
    let (response, painter) = ui.allocate_painter(size, egui::Sense::click());
    let rect = response.rect.shrink(3.0);
    let dark = ui.visuals().dark_mode;
    let ink = if dark { Color32::from_gray(220) } else { Color32::from_gray(30) };
    let Some(picture) = env.caches.picture(env.doc, r, slicing) else {
        painter.text(rect.center(), egui::Align2::CENTER_CENTER, "?", egui::FontId::proportional(14.0), Color32::RED);
        return response;
    };
    let b = picture.bounds;
    let scale = (rect.width() / b.width() as f32).min(rect.height() / b.height() as f32);
    let view = View { center_mm: [b.center().x, b.center().y], points_per_mm: scale };
    for (k, tris) in picture.pieces.iter().enumerate() {
        let color = if cuts {
            let hue = (k as f32 * HUE_STEP).fract();
            egui::ecolor::Hsva::new(hue, 0.55, if dark { 0.85 } else { 0.7 }, 1.0).into()
        } else {
            ink
        };
        painter.add(fill(&view, rect, tris, color));
    }
    if cuts {
        for &c in &picture.cuts {
            let top = view.to_screen(rect, DVec2::new(c, b.max.y));
            let bottom = view.to_screen(rect, DVec2::new(c, b.min.y));
            painter.line_segment([top, bottom], Stroke::new(1.0, Color32::from_rgb(220, 40, 40)));
        }
    }
    response
}

/// Exemplars as a grid of thumbnails, two to a row, each framed (the chosen
/// one highlighted) above its name; a click on either chooses it.
/// `thumbnail` draws one and returns its response. Shared by every mode's picker.
pub fn thumbnail_grid_ui(
    ui: &mut egui::Ui,
    id_salt: &str,
    refs: &[ExemplarRef],
    chosen: &mut ExemplarRef,
    mut thumbnail: impl FnMut(&mut egui::Ui, &ExemplarRef) -> egui::Response,
) {
    egui::Grid::new(id_salt).num_columns(2).spacing([6.0, 6.0]).show(ui, |ui| {
        for (k, r) in refs.iter().enumerate() {
            let is_chosen = r == chosen;
            ui.vertical(|ui| {
                let stroke = if is_chosen {
                    Stroke::new(2.0, ui.visuals().selection.bg_fill)
                } else {
                    Stroke::new(1.0, ui.visuals().widgets.noninteractive.bg_stroke.color)
                };
                let frame = egui::Frame::new().stroke(stroke).corner_radius(4.0);
                let response = frame.show(ui, |ui| thumbnail(ui, r)).inner;
                let label = ui.selectable_label(is_chosen, r.name());
                if response.clicked() || label.clicked() {
                    *chosen = r.clone();
                }
            });
            if k % 2 == 1 {
                ui.end_row();
            }
        }
    });
}

/// The picker: a grid of thumbnails, import, and the cut view of the chosen exemplar.
pub fn exemplar_picker_ui(ui: &mut egui::Ui, chosen: &mut ExemplarRef, slicing: SlicingMode, env: &mut ModeEnv<'_>) {
    ui.label(RichText::new("Exemplar").strong());
    let mut refs: Vec<ExemplarRef> = BUILTIN_NAMES.iter().map(|n| ExemplarRef::Builtin(n.to_string())).collect();
    refs.extend(env.doc.imported.iter().map(|e| ExemplarRef::Imported(e.name.clone())));
    thumbnail_grid_ui(ui, "exemplars", &refs, chosen, |ui, r| {
        exemplar_picture_ui(ui, env, r, SlicingMode::Topology, THUMBNAIL, false)
    });
    if ui.button(Command::ImportSvg.label()).on_hover_text("Or drop an SVG file on the window").clicked() {
        env.commands.push(Command::ImportSvg);
    }
    ui.add_space(4.0);
    ui.label("How it is cut:");
    let size = egui::vec2(ui.available_width(), CUT_VIEW_HEIGHT);
    exemplar_picture_ui(ui, env, chosen, slicing, size, true);
}
