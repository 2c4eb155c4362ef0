//! The Tracery desktop app.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

use egui::{Color32, Key, KeyboardShortcut, Modifiers, PointerButton, RichText, Stroke};
use serde::{Deserialize, Serialize};
use tracery_core::{BUILTIN_NAMES, DVec2, Exemplar, Mesh, PieceSet, Region, SliceOptions, SlicingMode, extrude};

use crate::canvas::{self, View};
use crate::dialogs::{Dialogs, FileKind, SystemDialogs};
use crate::document::{Count, Document, ExemplarRef, History, PatternSettings, Slicing};
use crate::files::write_atomically;
use crate::preview::{Orbit, preview_ui};
use crate::worker::{JobState, Request, Worker};

/// What a primary drag on the canvas does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Tool {
    /// Draw a new curve.
    Draw,
    /// Select, move and reshape curves.
    Edit,
}

/// What is remembered between runs, apart from the document (autosaved on its own).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
struct Persisted {
    view: View,
    defaults: PatternSettings,
    tool: Tool,
    show_band: bool,
    show_seams: bool,
    show_3d: bool,
    export_selected_only: bool,
    /// Where "Quick export" writes, for desktops without file dialogs.
    export_folder: PathBuf,
    orbit: Orbit,
    project_path: Option<PathBuf>,
}

impl Default for Persisted {
    fn default() -> Self {
        Persisted {
            view: View::default(),
            defaults: PatternSettings::default(),
            tool: Tool::Draw,
            show_band: true,
            show_seams: false,
            show_3d: false,
            export_selected_only: false,
            export_folder: default_export_folder(),
            orbit: Orbit::default(),
            project_path: None,
        }
    }
}

enum Drag {
    Stroke(Vec<DVec2>),
    Point { curve: u64, index: usize },
    Curve { curve: u64, last: DVec2 },
    Pan,
}

/// A drawing of an exemplar for the side panel: filled triangles and, for the
/// cut view, pieces in turn and the cut lines.
struct ExemplarPicture {
    bounds: tracery_core::Rect,
    pieces: Vec<Vec<[DVec2; 3]>>,
    cuts: Vec<f64>,
}

/// A curve smoothed through its control points, and what it was made from.
struct Smoothed {
    points: Vec<[f64; 2]>,
    closed: bool,
    curve: Option<tracery_core::Curve>,
}

const STORAGE_KEY: &str = "tracery";

fn default_export_folder() -> PathBuf {
    std::env::var_os("HOME").map_or_else(|| PathBuf::from("."), |h| PathBuf::from(h).join("Tracery"))
}
const AUTOSAVE_EVERY: Duration = Duration::from_secs(2);

/// The app: a document of curves, a canvas, controls, and a background worker.
pub struct TraceryApp {
    /// The project being edited.
    pub doc: Document,
    /// The selected curve.
    pub selected: Option<u64>,
    history: History,
    state: Persisted,
    drag: Option<Drag>,
    /// The document as it was when the current gesture began (one undo step per gesture).
    gesture_base: Option<Document>,
    /// Set when this frame's change already went through the history (undo,
    /// redo, delete, import, open), so it is not recorded again as a gesture.
    history_handled: bool,
    worker: Worker,
    exemplars: HashMap<ExemplarRef, Arc<Exemplar>>,
    pictures: HashMap<(ExemplarRef, Slicing), Option<ExemplarPicture>>,
    /// Smoothed curves by id, with the control points they were made from:
    /// smoothing runs when a curve changes, not on every frame.
    smoothed: HashMap<u64, Smoothed>,
    /// The last message for the status bar, and whether it is an error.
    pub message: Option<(String, bool)>,
    dialogs: Box<dyn Dialogs>,
    autosave_path: Option<PathBuf>,
    autosaved: Document,
    last_autosave: Instant,
}

impl TraceryApp {
    /// The app as eframe starts it: settings restored, the last session recovered.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let state: Persisted = cc.storage.and_then(|s| eframe::get_value(s, STORAGE_KEY)).unwrap_or_default();
        let autosave_path = eframe::storage_dir("Tracery").map(|d| d.join("autosave.ron"));
        let mut app = TraceryApp::with(Box::new(SystemDialogs), autosave_path.clone());
        app.state = state;
        if let Some(path) = &autosave_path
            && let Ok(text) = std::fs::read_to_string(path)
        {
            match Document::from_ron(&text) {
                Ok(doc) if !doc.curves.is_empty() => {
                    app.message = Some((format!("Restored your last session ({} curves)", doc.curves.len()), false));
                    app.autosaved = doc.clone();
                    app.doc = doc;
                }
                Ok(_) => {}
                Err(e) => app.message = Some((format!("Could not restore the last session: {e}"), true)),
            }
        }
        app
    }

    /// An app with the given dialogs and autosave file (none for tests).
    pub fn with(dialogs: Box<dyn Dialogs>, autosave_path: Option<PathBuf>) -> Self {
        TraceryApp {
            doc: Document::default(),
            selected: None,
            history: History::default(),
            state: Persisted::default(),
            drag: None,
            gesture_base: None,
            history_handled: false,
            worker: Worker::default(),
            exemplars: HashMap::new(),
            pictures: HashMap::new(),
            smoothed: HashMap::new(),
            message: None,
            dialogs,
            autosave_path,
            autosaved: Document::default(),
            last_autosave: Instant::now(),
        }
    }

    /// The settings the controls edit: the selected curve's, or those for new curves.
    fn settings_mut(&mut self) -> &mut PatternSettings {
        match self.selected.and_then(|id| self.doc.curves.iter().position(|c| c.id == id)) {
            Some(i) => &mut self.doc.curves[i].settings,
            None => &mut self.state.defaults,
        }
    }

    fn exemplar(&mut self, r: &ExemplarRef) -> Result<Arc<Exemplar>, String> {
        if let Some(e) = self.exemplars.get(r) {
            return Ok(e.clone());
        }
        let e = Arc::new(self.doc.exemplar(r)?);
        self.exemplars.insert(r.clone(), e.clone());
        Ok(e)
    }

    /// Whether any curve is still being synthesized (or waiting to be).
    pub fn busy(&self) -> bool {
        self.doc.curves.iter().any(|c| self.worker.is_stale(c.id))
    }

    /// The latest finished pattern of a curve.
    pub fn output(&self, id: u64) -> Option<&Arc<crate::worker::Output>> {
        self.worker.output(id)
    }

    /// The synthesis state of a curve.
    pub fn job_state(&self, id: u64) -> Option<&JobState> {
        self.worker.state(id)
    }

    fn submit_jobs(&mut self, ctx: &egui::Context) {
        let now = Instant::now();
        let curves = self.doc.curves.clone();
        for item in curves {
            match self.exemplar(&item.settings.exemplar) {
                Ok(exemplar) => self.worker.want(item.id, Request { curve: item, exemplar }, now),
                Err(e) => self.message = Some((e, true)),
            }
        }
        let ids: Vec<u64> = self.doc.curves.iter().map(|c| c.id).collect();
        self.worker.retain(&ids);
        if self.worker.poll(ctx, now) {
            ctx.request_repaint_after(Duration::from_millis(30));
        }
    }

    fn undo(&mut self) {
        if self.history.undo(&mut self.doc) {
            self.after_document_swap();
        }
    }

    fn redo(&mut self) {
        if self.history.redo(&mut self.doc) {
            self.after_document_swap();
        }
    }

    fn after_document_swap(&mut self) {
        self.history_handled = true;
        if self.selected.is_some_and(|id| self.doc.curve(id).is_none()) {
            self.selected = None;
        }
        self.exemplars.retain(|r, _| matches!(r, ExemplarRef::Builtin(_)));
    }

    fn delete_selected(&mut self) {
        if let Some(id) = self.selected.take() {
            self.history.record(self.doc.clone());
            self.doc.curves.retain(|c| c.id != id);
            self.history_handled = true;
        }
    }

    /// Imports an SVG exemplar from `path`; on failure the document is left as it was.
    pub fn import_svg(&mut self, path: &std::path::Path) {
        let name = path.file_name().map_or_else(|| "exemplar.svg".into(), |n| n.to_string_lossy().into_owned());
        let text = match std::fs::read(path) {
            Ok(bytes) => String::from_utf8_lossy(&bytes).into_owned(),
            Err(e) => {
                self.message = Some((format!("Could not read {}: {e}", path.display()), true));
                return;
            }
        };
        let before = self.doc.clone();
        match self.doc.import(&name, &text) {
            Ok(r) => {
                self.history.record(before);
                self.history_handled = true;
                self.settings_mut().exemplar = r.clone();
                self.message = Some((format!("Imported '{}'", r.name()), false));
            }
            Err(e) => self.message = Some((format!("Could not import: {e}"), true)),
        }
    }

    fn open_project(&mut self, path: &std::path::Path) {
        match std::fs::read_to_string(path).map_err(|e| e.to_string()).and_then(|t| Document::from_ron(&t)) {
            Ok(doc) => {
                self.history.record(self.doc.clone());
                self.doc = doc;
                self.selected = None;
                self.after_document_swap();
                self.state.project_path = Some(path.to_path_buf());
                self.message = Some((format!("Opened {}", path.display()), false));
            }
            Err(e) => self.message = Some((format!("Could not open {}: {e}", path.display()), true)),
        }
    }

    fn save_project(&mut self, choose: bool) {
        let path = match (&self.state.project_path, choose) {
            (Some(p), false) => Some(p.clone()),
            _ => self.dialogs.pick(FileKind::SaveProject),
        };
        let Some(path) = path else { return };
        let result = self.doc.to_ron().map_err(anyhow::Error::msg).and_then(|t| write_atomically(&path, t.as_bytes()));
        self.message = Some(match result {
            Ok(()) => {
                self.state.project_path = Some(path.clone());
                (format!("Saved {}", path.display()), false)
            }
            Err(e) => (format!("{e:#}"), true),
        });
    }

    fn export_ids(&self) -> Vec<u64> {
        match (self.state.export_selected_only, self.selected) {
            (true, Some(id)) => vec![id],
            _ => self.doc.curves.iter().map(|c| c.id).collect(),
        }
    }

    /// The meshes of the curves to export, or why they cannot be.
    fn export_meshes(&self) -> Result<Vec<&Mesh>, String> {
        let ids = self.export_ids();
        if ids.is_empty() {
            return Err("Nothing to export: draw a curve first".into());
        }
        ids.iter()
            .map(|id| match (self.worker.is_stale(*id), self.worker.output(*id)) {
                (false, Some(o)) if matches!(self.worker.state(*id), Some(JobState::Done(Ok(_)))) => Ok(&o.mesh),
                (true, _) => Err("A pattern is still being synthesized; export when the status bar says done".into()),
                _ => Err("A curve has no pattern (see the status bar); fix or delete it before exporting".into()),
            })
            .collect()
    }

    /// Writes the STL of the exported curves (all, or the selected one) to `path`.
    pub fn export_stl_to(&mut self, path: &std::path::Path) {
        let result = self.export_meshes().and_then(|meshes| {
            let mut all = Mesh::default();
            for m in meshes {
                let base = all.vertices.len() as u32;
                all.vertices.extend_from_slice(&m.vertices);
                all.triangles.extend(m.triangles.iter().map(|t| t.map(|i| i + base)));
            }
            let mut bytes = Vec::new();
            all.write_stl(&mut bytes).map_err(|e| e.to_string())?;
            write_atomically(path, &bytes).map_err(|e| format!("{e:#}"))?;
            Ok(all.triangles.len())
        });
        self.message = Some(match result {
            Ok(n) => (format!("Exported {n} triangles to {}", path.display()), false),
            Err(e) => (e, true),
        });
    }

    /// Writes STL and SVG into the export folder under a new name.
    pub fn quick_export(&mut self) {
        let folder = self.state.export_folder.clone();
        if let Err(e) = std::fs::create_dir_all(&folder) {
            self.message = Some((format!("Could not create {}: {e}", folder.display()), true));
            return;
        }
        let stamp = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
        let stl = folder.join(format!("tracery-{stamp}.stl"));
        self.export_stl_to(&stl);
        if matches!(self.message, Some((_, false))) {
            self.export_svg_to(&folder.join(format!("tracery-{stamp}.svg")));
            self.message = Some((format!("Exported {} and .svg", stl.display()), false));
        }
    }

    fn export_svg_to(&mut self, path: &std::path::Path) {
        let ids = self.export_ids();
        let mut region = Region::default();
        for id in &ids {
            if let Some(o) = self.worker.output(*id) {
                region.polygons.extend(o.region.polygons.iter().cloned());
            }
        }
        let result = if region.is_empty() {
            Err("Nothing to export yet".to_string())
        } else {
            write_atomically(path, tracery_core::region_to_svg(&region).as_bytes()).map_err(|e| format!("{e:#}"))
        };
        self.message = Some(match result {
            Ok(()) => (format!("Exported {}", path.display()), false),
            Err(e) => (e, true),
        });
    }

    fn shortcuts(&mut self, ctx: &egui::Context) {
        let shortcut = |m: Modifiers, k: Key| KeyboardShortcut::new(m, k);
        let pressed = |s: KeyboardShortcut| ctx.input_mut(|i| i.consume_shortcut(&s));
        if pressed(shortcut(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z))
            || pressed(shortcut(Modifiers::COMMAND, Key::Y))
        {
            self.redo();
        }
        if pressed(shortcut(Modifiers::COMMAND, Key::Z)) {
            self.undo();
        }
        if pressed(shortcut(Modifiers::COMMAND, Key::S)) {
            self.save_project(false);
        }
        if pressed(shortcut(Modifiers::COMMAND, Key::O))
            && let Some(p) = self.dialogs.pick(FileKind::OpenProject)
        {
            self.open_project(&p);
        }
        if pressed(shortcut(Modifiers::COMMAND, Key::E)) {
            match self.dialogs.pick(FileKind::ExportStl) {
                Some(p) => self.export_stl_to(&p),
                None => self.message = Some(("No file chosen; Quick export writes without a dialog".into(), false)),
            }
        }
        let typing = ctx.egui_wants_keyboard_input();
        if !typing && ctx.input(|i| i.key_pressed(Key::Delete) || i.key_pressed(Key::Backspace)) {
            self.delete_selected();
        }
        if !typing && ctx.input(|i| i.key_pressed(Key::Escape)) {
            self.selected = None;
        }
    }

    fn dropped_files(&mut self, ctx: &egui::Context) {
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        for file in dropped {
            let path = file.path().to_path_buf();
            match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
                Some("ron") => self.open_project(&path),
                _ => self.import_svg(&path),
            }
        }
    }

    fn autosave(&mut self) {
        let Some(path) = &self.autosave_path else { return };
        if self.doc == self.autosaved || self.last_autosave.elapsed() < AUTOSAVE_EVERY {
            return;
        }
        self.last_autosave = Instant::now();
        if let Some(dir) = path.parent() {
            let _ = std::fs::create_dir_all(dir);
        }
        if let Ok(text) = self.doc.to_ron()
            && write_atomically(path, text.as_bytes()).is_ok()
        {
            self.autosaved = self.doc.clone();
        }
    }

    fn picture(&mut self, r: &ExemplarRef, slicing: Slicing) -> Option<&ExemplarPicture> {
        let key = (r.clone(), slicing);
        if !self.pictures.contains_key(&key) {
            let picture = self.exemplar(r).ok().and_then(|e| {
                let mut options = SliceOptions::default();
                options.mode = match slicing {
                    Slicing::Topology => SlicingMode::Topology,
                    Slicing::Uniform(t) => SlicingMode::Uniform { cuts: t as usize },
                };
                let set = PieceSet::new(&e, &options).ok()?;
                let pieces = set
                    .pieces
                    .iter()
                    .map(|p| {
                        extrude(&p.region, 1.0).map_or_else(
                            |_| Vec::new(),
                            |m| {
                                let n = m.vertices.len() / 2;
                                m.triangles
                                    .iter()
                                    .filter(|t| t.iter().all(|&i| i as usize >= n))
                                    .map(|t| {
                                        t.map(|i| DVec2::new(m.vertices[i as usize][0], m.vertices[i as usize][1]))
                                    })
                                    .collect()
                            },
                        )
                    })
                    .collect();
                Some(ExemplarPicture { bounds: e.bounds, pieces, cuts: set.cuts.clone() })
            });
            self.pictures.insert(key.clone(), picture);
        }
        self.pictures.get(&key).and_then(Option::as_ref)
    }

    fn exemplar_picture_ui(
        &mut self,
        ui: &mut egui::Ui,
        r: &ExemplarRef,
        slicing: Slicing,
        size: egui::Vec2,
        cuts: bool,
    ) -> egui::Response {
        let (response, painter) = ui.allocate_painter(size, egui::Sense::click());
        let rect = response.rect.shrink(3.0);
        let dark = ui.visuals().dark_mode;
        let ink = if dark { Color32::from_gray(220) } else { Color32::from_gray(30) };
        let Some(picture) = self.picture(r, slicing) else {
            painter.text(
                rect.center(),
                egui::Align2::CENTER_CENTER,
                "?",
                egui::FontId::proportional(14.0),
                Color32::RED,
            );
            return response;
        };
        let b = picture.bounds;
        let scale = (rect.width() / b.width() as f32).min(rect.height() / b.height() as f32);
        let view = View { center_mm: [b.center().x, b.center().y], points_per_mm: scale };
        let full = egui::Rect::from_center_size(rect.center(), rect.size());
        for (k, tris) in picture.pieces.iter().enumerate() {
            let color = if cuts {
                let hue = (k as f32 * 0.618).fract();
                egui::ecolor::Hsva::new(hue, 0.55, if dark { 0.85 } else { 0.7 }, 1.0).into()
            } else {
                ink
            };
            painter.add(canvas::fill(&view, full, tris, color));
        }
        if cuts {
            for &c in &picture.cuts {
                let top = view.to_screen(full, DVec2::new(c, b.max.y));
                let bottom = view.to_screen(full, DVec2::new(c, b.min.y));
                painter.line_segment([top, bottom], Stroke::new(1.0, Color32::from_rgb(220, 40, 40)));
            }
        }
        response
    }

    fn side_panel_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.selectable_value(&mut self.state.tool, Tool::Draw, "Draw");
            ui.selectable_value(&mut self.state.tool, Tool::Edit, "Edit");
        });
        ui.separator();
        let editing = match self.selected {
            Some(id) => format!("Curve {id}"),
            None => "New curves".to_string(),
        };
        ui.label(RichText::new(format!("Exemplar — {editing}")).strong());
        let current = self.settings_mut().exemplar.clone();
        let slicing = self.settings_mut().slicing;
        let mut refs: Vec<ExemplarRef> = BUILTIN_NAMES.iter().map(|n| ExemplarRef::Builtin(n.to_string())).collect();
        refs.extend(self.doc.imported.iter().map(|e| ExemplarRef::Imported(e.name.clone())));
        egui::Grid::new("exemplars").num_columns(2).spacing([6.0, 6.0]).show(ui, |ui| {
            for (k, r) in refs.iter().enumerate() {
                let chosen = *r == current;
                ui.vertical(|ui| {
                    let frame = egui::Frame::new()
                        .stroke(if chosen {
                            Stroke::new(2.0, ui.visuals().selection.bg_fill)
                        } else {
                            Stroke::new(1.0, ui.visuals().widgets.noninteractive.bg_stroke.color)
                        })
                        .corner_radius(4.0);
                    let response = frame
                        .show(ui, |ui| {
                            self.exemplar_picture_ui(ui, r, Slicing::Topology, egui::vec2(110.0, 30.0), false)
                        })
                        .inner;
                    let label = ui.selectable_label(chosen, r.name());
                    if response.clicked() || label.clicked() {
                        self.settings_mut().exemplar = r.clone();
                    }
                });
                if k % 2 == 1 {
                    ui.end_row();
                }
            }
        });
        if ui.button("Import SVG…").on_hover_text("Or drop an SVG file on the window").clicked()
            && let Some(path) = self.dialogs.pick(FileKind::ImportSvg)
        {
            self.import_svg(&path);
        }
        ui.add_space(4.0);
        ui.label("How it is cut:");
        self.exemplar_picture_ui(ui, &current, slicing, egui::vec2(ui.available_width(), 56.0), true);
        ui.separator();

        ui.label(RichText::new(format!("Pattern — {editing}")).strong());
        let s = self.settings_mut();
        ui.horizontal(|ui| {
            let label = ui.label("Components");
            ui.selectable_value(&mut s.components, Count::One, "1");
            let n = if let Count::Exactly(n) = s.components { n } else { 2 };
            ui.selectable_value(&mut s.components, Count::Exactly(n), "N");
            ui.selectable_value(&mut s.components, Count::Any, "any");
            if let Count::Exactly(n) = &mut s.components {
                ui.add(egui::DragValue::new(n).range(2..=100)).labelled_by(label.id);
            }
        });
        ui.horizontal(|ui| {
            let label = ui.label("Holes");
            ui.selectable_value(&mut s.holes, Count::Zero, "0");
            let n = if let Count::Exactly(n) = s.holes { n } else { 1 };
            ui.selectable_value(&mut s.holes, Count::Exactly(n), "N");
            ui.selectable_value(&mut s.holes, Count::Any, "any");
            if let Count::Exactly(n) = &mut s.holes {
                ui.add(egui::DragValue::new(n).range(1..=500)).labelled_by(label.id);
            }
        });
        ui.checkbox(&mut s.closed_pattern, "Closed pattern (loops run all around)");
        ui.add(egui::Slider::new(&mut s.band_mm, 2.0..=40.0).text("Band width (mm)"));
        ui.add(egui::Slider::new(&mut s.variety, 0.0..=2.0).text("Variety"));
        ui.add(egui::Slider::new(&mut s.scale, 0.25..=4.0).logarithmic(true).text("Scale"));
        ui.horizontal(|ui| {
            let label = ui.label("Slicing");
            ui.selectable_value(&mut s.slicing, Slicing::Topology, "topology");
            let t = if let Slicing::Uniform(t) = s.slicing { t } else { 8 };
            ui.selectable_value(&mut s.slicing, Slicing::Uniform(t), "uniform");
            if let Slicing::Uniform(t) = &mut s.slicing {
                ui.add(egui::DragValue::new(t).range(1..=40).suffix(" cuts")).labelled_by(label.id);
            }
        });
        ui.add(egui::Slider::new(&mut s.min_portal_mm, 0.0..=3.0).text("Min. portal (mm)"));
        ui.add(egui::Slider::new(&mut s.thickness_mm, 0.4..=10.0).text("Thickness (mm)"));
        ui.horizontal(|ui| {
            let label = ui.label("Seed");
            ui.add(egui::DragValue::new(&mut s.seed)).labelled_by(label.id);
            if ui.button("Another one").clicked() {
                s.seed = s.seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407) % 1_000_000 + 1;
            }
        });
        ui.separator();

        ui.label(RichText::new("Files").strong());
        ui.horizontal_wrapped(|ui| {
            if ui.button("Open…").clicked()
                && let Some(p) = self.dialogs.pick(FileKind::OpenProject)
            {
                self.open_project(&p);
            }
            if ui.button("Save…").clicked() {
                self.save_project(true);
            }
            if ui.button("Export STL…").clicked()
                && let Some(p) = self.dialogs.pick(FileKind::ExportStl)
            {
                self.export_stl_to(&p);
            }
            if ui.button("Export SVG…").clicked()
                && let Some(p) = self.dialogs.pick(FileKind::ExportSvg)
            {
                self.export_svg_to(&p);
            }
        });
        ui.checkbox(&mut self.state.export_selected_only, "Export the selected curve only");
        ui.horizontal(|ui| {
            if ui
                .button("Quick export")
                .on_hover_text("Writes STL and SVG into the folder below, without a dialog")
                .clicked()
            {
                self.quick_export();
            }
            let mut folder = self.state.export_folder.display().to_string();
            let label = ui.label("to");
            if ui.add(egui::TextEdit::singleline(&mut folder).desired_width(150.0)).labelled_by(label.id).changed() {
                self.state.export_folder = PathBuf::from(folder);
            }
        });
        ui.horizontal(|ui| {
            if ui.add_enabled(self.history.can_undo(), egui::Button::new("Undo")).clicked() {
                self.undo();
            }
            if ui.add_enabled(self.history.can_redo(), egui::Button::new("Redo")).clicked() {
                self.redo();
            }
            if ui.add_enabled(self.selected.is_some(), egui::Button::new("Delete")).clicked() {
                self.delete_selected();
            }
        });
    }

    fn status_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            let focus = self.selected.or_else(|| self.doc.curves.last().map(|c| c.id));
            match focus.and_then(|id| self.worker.state(id).map(|s| (id, s))) {
                Some((id, JobState::Running { progress })) => {
                    ui.add(egui::ProgressBar::new(*progress).desired_width(160.0).show_percentage());
                    ui.label(format!("Synthesizing curve {id}…"));
                }
                Some((id, JobState::Done(Ok(o)))) => {
                    let t = &o.timings;
                    let openings = if o.topology.loop_openings > 0 {
                        format!(" + {} loop opening", o.topology.loop_openings)
                    } else {
                        String::new()
                    };
                    ui.label(format!(
                        "Curve {id}: {} component(s), {} hole(s){openings}, {} pieces — {:.0} ms",
                        o.topology.components,
                        o.topology.holes,
                        o.pieces,
                        t.analysis + t.dp + t.geometry + t.mesh
                    ));
                    for w in &o.warnings {
                        ui.label(RichText::new(format!("Warning: {w}")).color(Color32::from_rgb(200, 140, 0)));
                    }
                }
                Some((id, JobState::Done(Err(e)))) => {
                    ui.label(RichText::new(format!("Curve {id}: {e}")).color(Color32::from_rgb(220, 60, 60)));
                }
                _ => {
                    ui.label(if self.doc.curves.is_empty() {
                        "Draw a curve on the canvas: drag with the left button. End near the start to close a loop."
                    } else {
                        "Ready"
                    });
                }
            }
            if let Some((text, error)) = &self.message {
                ui.separator();
                let color = if *error { Color32::from_rgb(220, 60, 60) } else { ui.visuals().text_color() };
                ui.label(RichText::new(text).color(color));
            }
        });
    }

    fn refresh_smoothed(&mut self) {
        let ids: Vec<u64> = self.doc.curves.iter().map(|c| c.id).collect();
        self.smoothed.retain(|id, _| ids.contains(id));
        for item in &self.doc.curves {
            let fresh = self.smoothed.get(&item.id).is_some_and(|s| s.points == item.points && s.closed == item.closed);
            if !fresh {
                let smoothed = Smoothed { points: item.points.clone(), closed: item.closed, curve: item.curve() };
                self.smoothed.insert(item.id, smoothed);
            }
        }
    }

    fn smoothed(&self, id: u64) -> Option<&tracery_core::Curve> {
        self.smoothed.get(&id).and_then(|s| s.curve.as_ref())
    }

    fn canvas_ui(&mut self, ui: &mut egui::Ui) {
        self.refresh_smoothed();
        let (response, painter) = canvas::allocate(ui);
        let rect = response.rect;
        let dark = ui.visuals().dark_mode;
        painter.rect_filled(rect, 0.0, if dark { Color32::from_gray(24) } else { Color32::from_gray(250) });
        canvas::grid_ui(&painter, rect, &self.state.view, dark);
        let view = self.state.view;

        // Zoom with the wheel (or pinch), pan with the middle or right button.
        if response.hovered() {
            let (scroll, zoom) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
            if let Some(pointer) = response.hover_pos() {
                let factor = zoom * (scroll * 0.0015).exp();
                if factor != 1.0 {
                    self.state.view.zoom_at(rect, pointer, factor);
                }
            }
        }
        let world = |p: egui::Pos2| view.from_screen(rect, p);
        let pointer = response.interact_pointer_pos();
        if response.drag_started_by(PointerButton::Middle) || response.drag_started_by(PointerButton::Secondary) {
            self.drag = Some(Drag::Pan);
        } else if response.drag_started_by(PointerButton::Primary)
            // Start where the button went down, not where the drag was recognised.
            && let Some(p) = ui.input(|i| i.pointer.press_origin()).or(pointer).map(world)
        {
            self.drag = Some(self.begin_drag(p));
        }
        if response.dragged() {
            match &mut self.drag {
                Some(Drag::Pan) => self.state.view.pan(response.drag_delta()),
                Some(Drag::Stroke(points)) => {
                    if let Some(p) = pointer.map(world)
                        && points.last().is_none_or(|q| q.distance(p) > 0.25)
                    {
                        points.push(p);
                    }
                }
                Some(Drag::Point { curve, index }) => {
                    let (curve, index) = (*curve, *index);
                    if let (Some(p), Some(c)) = (pointer.map(world), self.doc.curve_mut(curve))
                        && let Some(slot) = c.points.get_mut(index)
                    {
                        *slot = [p.x, p.y];
                    }
                }
                Some(Drag::Curve { curve, last }) => {
                    if let Some(p) = pointer.map(world) {
                        let delta = p - *last;
                        *last = p;
                        let id = *curve;
                        if let Some(c) = self.doc.curve_mut(id) {
                            for q in &mut c.points {
                                q[0] += delta.x;
                                q[1] += delta.y;
                            }
                        }
                    }
                }
                None => {}
            }
        }
        if response.drag_stopped() {
            if let Some(Drag::Stroke(points)) = self.drag.take() {
                self.finish_stroke(&points);
            }
            self.drag = None;
        }
        if response.clicked()
            && let Some(p) = pointer.map(world)
        {
            self.selected = self.curve_at(p, 6.0 / f64::from(view.points_per_mm));
        }

        // Patterns, then curves and overlays on top.
        let ink = if dark { Color32::from_rgb(230, 200, 140) } else { Color32::from_rgb(40, 40, 48) };
        for item in &self.doc.curves {
            let selected = self.selected == Some(item.id);
            if let Some(o) = self.worker.output(item.id) {
                let stale = self.worker.is_stale(item.id);
                let color = if stale { ink.gamma_multiply(0.45) } else { ink };
                painter.add(canvas::fill(&view, rect, &o.fill, color));
                if self.state.show_band {
                    for edge in &o.band_outline {
                        painter.add(canvas::polyline(
                            &view,
                            rect,
                            edge,
                            item.closed,
                            Stroke::new(1.0, Color32::from_rgba_unmultiplied(90, 140, 230, 120)),
                        ));
                    }
                }
                if self.state.show_seams {
                    for s in &o.seams {
                        painter.line_segment(
                            [view.to_screen(rect, s[0]), view.to_screen(rect, s[1])],
                            Stroke::new(1.0, Color32::from_rgb(230, 70, 70)),
                        );
                    }
                }
            }
            if let Some(curve) = self.smoothed(item.id) {
                let color = if selected {
                    Color32::from_rgb(40, 140, 255)
                } else {
                    Color32::from_rgba_unmultiplied(40, 140, 255, 110)
                };
                painter.add(canvas::polyline(
                    &view,
                    rect,
                    curve.points(),
                    false,
                    Stroke::new(if selected { 2.0 } else { 1.0 }, color),
                ));
            }
            if selected && self.state.tool == Tool::Edit {
                for p in item.control_points() {
                    painter.circle(
                        view.to_screen(rect, p),
                        4.0,
                        Color32::WHITE,
                        Stroke::new(1.5, Color32::from_rgb(40, 140, 255)),
                    );
                }
            }
        }
        if let Some(Drag::Stroke(points)) = &self.drag {
            painter.add(canvas::polyline(
                &view,
                rect,
                points,
                false,
                Stroke::new(2.0, Color32::from_rgb(40, 140, 255)),
            ));
        }
        painter.text(
            rect.right_bottom() + egui::vec2(-8.0, -8.0),
            egui::Align2::RIGHT_BOTTOM,
            format!("{:.1} px/mm", view.points_per_mm),
            egui::FontId::proportional(11.0),
            ui.visuals().weak_text_color(),
        );
    }

    fn begin_drag(&mut self, p: DVec2) -> Drag {
        let tolerance = 8.0 / f64::from(self.state.view.points_per_mm);
        if self.state.tool == Tool::Edit {
            if let Some(item) = self.selected.and_then(|id| self.doc.curve(id))
                && let Some(index) = item.control_points().iter().position(|q| q.distance(p) <= tolerance)
            {
                return Drag::Point { curve: item.id, index };
            }
            if let Some(id) = self.curve_at(p, tolerance) {
                self.selected = Some(id);
                return Drag::Curve { curve: id, last: p };
            }
        }
        Drag::Stroke(vec![p])
    }

    fn curve_at(&self, p: DVec2, tolerance: f64) -> Option<u64> {
        self.doc
            .curves
            .iter()
            .filter_map(|c| {
                let half = 0.5 * c.settings.band_mm;
                let d = canvas::distance_to(self.smoothed(c.id)?.points(), false, p);
                (d <= tolerance.max(half)).then_some((d, c.id))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, id)| id)
    }

    fn finish_stroke(&mut self, raw: &[DVec2]) {
        let close_mm = 20.0 / f64::from(self.state.view.points_per_mm);
        let Some((points, closed)) = canvas::stroke_to_control_points(raw, 6.0, close_mm) else { return };
        let mut settings = self.state.defaults.clone();
        if let Some(item) = self.selected.and_then(|id| self.doc.curve(id)) {
            settings = item.settings.clone();
        }
        settings.seed = 0;
        let id = self.doc.add_curve(points, closed, settings);
        self.selected = Some(id);
    }

    /// The meshes the 3D preview shows: the selected curve's, or all.
    fn preview_meshes(&self) -> Vec<&Mesh> {
        let ids: Vec<u64> = match self.selected {
            Some(id) => vec![id],
            None => self.doc.curves.iter().map(|c| c.id).collect(),
        };
        ids.iter().filter_map(|id| self.worker.output(*id)).map(|o| &o.mesh).collect()
    }
}

impl eframe::App for TraceryApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        let before = self.doc.clone();
        self.shortcuts(&ctx);
        self.dropped_files(&ctx);

        egui::Panel::top("menu").show(ui, |ui| {
            ui.horizontal(|ui| {
                ui.heading("Tracery");
                ui.label(RichText::new("pattern brush").weak());
                ui.separator();
                ui.checkbox(&mut self.state.show_band, "Band outline");
                ui.checkbox(&mut self.state.show_seams, "Piece seams");
                ui.checkbox(&mut self.state.show_3d, "3D preview");
                if let Some(p) = &self.state.project_path {
                    ui.separator();
                    ui.label(RichText::new(p.display().to_string()).weak());
                }
            });
        });
        egui::Panel::bottom("status").show(ui, |ui| self.status_ui(ui));
        egui::Panel::left("controls").resizable(true).default_size(270.0).show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| self.side_panel_ui(ui));
        });
        if self.state.show_3d {
            egui::Panel::right("preview").resizable(true).default_size(320.0).show(ui, |ui| {
                ui.label(RichText::new("3D preview").strong());
                let meshes = self.preview_meshes();
                let mut orbit = self.state.orbit;
                preview_ui(ui, &meshes, &mut orbit);
                self.state.orbit = orbit;
            });
        }
        egui::CentralPanel::default().show(ui, |ui| self.canvas_ui(ui));

        // One undo step per gesture: a drag of a slider or of a point counts once.
        if std::mem::take(&mut self.history_handled) {
            self.gesture_base = None;
        } else if self.doc != before && self.gesture_base.is_none() {
            self.gesture_base = Some(before);
        }
        let pointer_down = ctx.input(|i| i.pointer.any_down());
        if !pointer_down
            && let Some(base) = self.gesture_base.take()
            && base != self.doc
        {
            self.history.record(base);
        }
        self.submit_jobs(&ctx);
        self.autosave();
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, STORAGE_KEY, &self.state);
    }
}
