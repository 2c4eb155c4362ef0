//! The Tracery desktop app: state, layout and the frame loop. Panels, tools,
//! modes and commands live in their own modules.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

use tracery_core::DVec2;
use tracery_core::surface::PartRole;
use tracery_core::vector_brush::part_role;

use crate::command::Command;
use crate::dialogs::{Dialogs, SystemDialogs};
use crate::document::{Document, History, ModeSettings};
use crate::live::{LIVE_ID, LiveJob, Session};
use crate::model::{self, ASSEMBLY, AssemblyJob, ShadeJob, SurfaceJob};
use crate::modes::{CurveJob, GalleryJob, JobError, mode_ui};
use crate::panels::{files, gallery, preview_3d, side_panel, status, top_bar};
use crate::solutions::Solutions;
use crate::state::{Caches, Persisted, Workspace};
use crate::tools::Gesture;
use crate::worker::{JobState, Worker};
use crate::{canvas, command_handling};

/// Key of the persisted state in eframe's storage.
const STORAGE_KEY: &str = "tracery";
/// How often the document may be autosaved.
const AUTOSAVE_EVERY: Duration = Duration::from_secs(2);
/// Repaint interval while jobs run.
const BUSY_REPAINT: Duration = Duration::from_millis(30);
/// Default width of the side panel, points.
const SIDE_PANEL_WIDTH: f32 = 270.0;
/// Default width of the 3D preview panel, points.
const PREVIEW_WIDTH: f32 = 320.0;

/// Where the document is autosaved, and what was last written there.
pub(crate) struct Autosave {
    pub(crate) path: Option<PathBuf>,
    pub(crate) saved: Document,
    /// The text last written or read: a document holding NaN never equals
    /// itself, so the text, not the document, says whether to write.
    pub(crate) saved_text: Option<String>,
    pub(crate) last: Instant,
}

/// The app: a document of curves, a canvas, controls, and a background worker.
pub struct TraceryApp {
    /// The project being edited.
    pub doc: Document,
    /// The selected curve.
    pub selected: Option<u64>,
    /// The selected curve on the model (the model workspace's selection).
    pub selected_surface: Option<u64>,
    /// The last message for the status bar, and whether it is an error.
    pub message: Option<(String, bool)>,
    pub(crate) history: History,
    pub(crate) state: Persisted,
    pub(crate) caches: Caches,
    pub(crate) worker: Worker<CurveJob>,
    /// Alternatives of the selected curve, for the gallery.
    pub(crate) gallery: Worker<GalleryJob>,
    /// The pattern of the stroke being drawn.
    pub(crate) live: Worker<LiveJob>,
    /// Patterns of the curves on the model.
    pub(crate) surface_worker: Worker<SurfaceJob>,
    /// Lamp shades on the model's axis.
    pub(crate) shade_worker: Worker<ShadeJob>,
    /// Texture over the model (one slot, [`model::TEXTURE`]).
    pub(crate) texture_worker: Worker<model::TextureJob>,
    /// The object made of them and the model (one slot, [`ASSEMBLY`]).
    pub(crate) assembly_worker: Worker<AssemblyJob>,
    /// Autocomplete's and clone's suggested paths (one slot, [`crate::predictions::PREDICTION_ID`]).
    pub(crate) predictor: Worker<crate::predictions::PredictJob>,
    /// The predictions on screen, if any.
    pub(crate) predictions: Option<crate::predictions::Predictions>,
    /// Where the canvas was last laid out, on screen.
    pub(crate) canvas_rect: Option<egui::Rect>,
    /// The clone tool's source rectangle, mm, once dragged.
    pub(crate) clone_source: Option<tracery_core::geom::Rect>,
    /// What the stroke being drawn shares between its jobs.
    pub(crate) live_session: Session,
    pub(crate) gesture: Option<Gesture>,
    /// Where the pointer went, on screen, since the primary button went down
    /// on the canvas and before egui saw a drag: the start of a stroke.
    pub(crate) press_trail: Vec<egui::Pos2>,
    pub(crate) dialogs: Box<dyn Dialogs>,
    pub(crate) autosave: Autosave,
    /// The document as it was when the current gesture began (one undo step per gesture).
    gesture_base: Option<Document>,
    /// Set when this frame's change already went through the history (undo,
    /// redo, delete, import, open), so it is not recorded again as a gesture.
    pub(crate) history_handled: bool,
    /// Commands asked for during this frame's layout, run after it.
    commands: Vec<Command>,
    waker_set: bool,
    /// The format of egui's wgpu target, when it renders with wgpu (the 3D views draw with it).
    pub(crate) gpu_format: Option<eframe::wgpu::TextureFormat>,
}

impl TraceryApp {
    /// The app as eframe starts it: settings restored, the last session recovered.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let state: Persisted = cc.storage.and_then(|s| eframe::get_value(s, STORAGE_KEY)).unwrap_or_default();
        let autosave_path = eframe::storage_dir("Tracery").map(|d| d.join("autosave.ron"));
        let mut app = TraceryApp::with(Box::new(SystemDialogs), autosave_path);
        app.state = state;
        app.restore_autosave();
        app
    }

    /// An app with the given dialogs and autosave file (none for tests).
    pub fn with(dialogs: Box<dyn Dialogs>, autosave_path: Option<PathBuf>) -> Self {
        TraceryApp {
            doc: Document::default(),
            selected: None,
            selected_surface: None,
            message: None,
            history: History::default(),
            state: Persisted::default(),
            caches: Caches::default(),
            worker: Worker::default(),
            gallery: Worker::default(),
            live: Worker::live(Arc::new(|| {})),
            surface_worker: Worker::default(),
            shade_worker: Worker::default(),
            texture_worker: Worker::default(),
            assembly_worker: Worker::default(),
            predictor: Worker::default(),
            predictions: None,
            clone_source: None,
            canvas_rect: None,
            live_session: Session::default(),
            gesture: None,
            press_trail: Vec::new(),
            dialogs,
            autosave: Autosave {
                path: autosave_path,
                saved: Document::default(),
                saved_text: None,
                last: Instant::now(),
            },
            gesture_base: None,
            history_handled: false,
            commands: Vec::new(),
            waker_set: false,
            gpu_format: None,
        }
    }

    /// The canvas's view and where it was last laid out on screen (for
    /// tests that click on what they see).
    pub fn canvas_view(&self) -> Option<(crate::canvas::View, egui::Rect)> {
        self.canvas_rect.map(|rect| (self.state.view, rect))
    }

    /// The caches (for showing a mode's settings on their own, as the snapshot tests do).
    pub fn caches_mut(&mut self) -> &mut Caches {
        &mut self.caches
    }

    /// Shows or hides the 3D preview.
    pub fn set_show_3d(&mut self, show: bool) {
        self.state.show_3d = show;
    }

    /// Asks for a command to run once this frame's layout is done.
    pub fn queue(&mut self, command: Command) {
        self.commands.push(command);
    }

    /// The settings the controls edit: the selected curve's, or those for new curves.
    pub fn settings(&self) -> &ModeSettings {
        self.selected.and_then(|id| self.doc.curve(id)).map_or(&self.state.new_curve, |c| &c.mode)
    }

    /// The settings the controls edit, mutable.
    pub fn settings_mut(&mut self) -> &mut ModeSettings {
        match self.selected.and_then(|id| self.doc.curves.iter().position(|c| c.id == id)) {
            Some(i) => &mut self.doc.curves[i].mode,
            None => &mut self.state.new_curve,
        }
    }

    /// Adds a drawn curve with the settings the controls show, and selects it.
    pub fn add_curve(&mut self, points: Vec<DVec2>, closed: bool) {
        let mode = self.settings().for_new_curve();
        // A region's outline is a loop however it was drawn.
        let closed = closed || (mode.always_closed() && points.len() >= 3);
        let id = self.doc.add_curve(points, closed, mode);
        self.selected = Some(id);
    }

    /// Whether any curve is still being synthesized (or waiting to be), or
    /// the selected curve's solutions are.
    pub fn busy(&self) -> bool {
        self.doc.curves.iter().any(|c| self.worker.is_stale(c.id))
            || self.gallery_curve().is_some_and(|id| self.gallery.is_stale(id))
            || self.model_stale()
            || (self.predictions.is_some() && self.predictor.is_stale(crate::predictions::PREDICTION_ID))
    }

    /// Whether a curve or shade on the model, or the object made of them,
    /// has a change not yet computed.
    fn model_stale(&self) -> bool {
        self.doc.model.drawn_curves().any(|c| self.surface_worker.is_stale(c.id))
            || self.doc.model.shades.iter().any(|c| self.shade_worker.is_stale(c.id))
            || (self.doc.model.texture.on && self.texture_worker.is_stale(model::TEXTURE))
            || self.assembly_worker.is_stale(ASSEMBLY)
    }

    /// The latest finished product of a curve.
    pub fn output(&self, id: u64) -> Option<&Arc<tracery_core::Product>> {
        self.worker.output(id)
    }

    /// Asks for the pattern of the stroke being drawn, or forgets it.
    fn submit_live(&mut self, now: Instant) {
        let stroke = match &self.gesture {
            Some(Gesture::Stroke(stroke)) if LiveJob::long_enough(&stroke.points) => stroke,
            _ => {
                self.live.retain(&[]);
                return;
            }
        };
        // Only the vector brush is fast enough to follow the pointer; a raster
        // curve's pattern comes when the stroke ends.
        let ModeSettings::VectorBrush(item) = self.settings().for_new_curve() else {
            self.live.retain(&[]);
            return;
        };
        let Ok(exemplar) = self.caches.exemplar(&self.doc, &item.exemplar) else { return };
        let job = LiveJob {
            raw: Arc::new(stroke.points.clone()),
            exemplar,
            settings: item.settings,
            session: self.live_session.clone(),
        };
        self.live.want(LIVE_ID, job, now);
    }

    /// The pattern of the stroke being drawn, as far as it has been made.
    pub fn live_output(&self) -> Option<&Arc<tracery_core::Product>> {
        matches!(self.gesture, Some(Gesture::Stroke(_))).then(|| self.live.output(LIVE_ID)).flatten()
    }

    /// Starts a new stroke's live session (the last stroke's pattern is forgotten).
    pub(crate) fn begin_live_stroke(&mut self) {
        self.live.retain(&[]);
        self.live_session = Session::default();
    }

    /// The curve whose gallery is shown and computed: the selected one, when
    /// the gallery is on and its mode has alternatives (a mode with one
    /// result would only compute it a second time).
    pub fn gallery_curve(&self) -> Option<u64> {
        let id = self.selected.filter(|_| self.state.show_gallery)?;
        self.doc.curve(id).filter(|c| c.mode.has_alternatives()).map(|c| c.id)
    }

    /// The gallery of a curve: its alternatives, the best first.
    pub fn gallery(&self, id: u64) -> Option<&Arc<Solutions>> {
        self.gallery.output(id).filter(|_| !self.gallery.is_stale(id))
    }

    /// Where the gallery of a curve stands.
    pub fn gallery_state(&self, id: u64) -> Option<&JobState<Solutions, JobError>> {
        self.gallery.state(id)
    }

    /// "Another one": the selected curve's next solution that looks
    /// different from the one it has (all of them when the gallery is not
    /// ready yet), round to the best again after the last.
    pub fn next_alternative(&mut self) {
        use tracery_core::vector_brush::ALTERNATIVES;
        let current = self.settings().alternative();
        let gallery = self.selected.and_then(|id| self.gallery(id).cloned());
        let mut next = (current + 1) % ALTERNATIVES;
        if let Some(solutions) = gallery.filter(|s| s.products.len() == ALTERNATIVES as usize) {
            next = solutions.shown.iter().map(|&k| k as u32).find(|&k| k > current).unwrap_or(0);
        }
        self.settings_mut().set_alternative(next);
    }

    /// Hangs a jump ring at `p` (mm) on the selected curve, or on the
    /// nearest one within reach.
    pub fn add_jump_ring_at(&mut self, p: tracery_core::DVec2) {
        let reach_mm = 30.0;
        let target = self.selected.or_else(|| crate::canvas::curve_at(self, p, reach_mm));
        let Some(item) = target.and_then(|id| self.doc.curve_mut(id)) else {
            self.message = Some(("Click near a curve to hang a jump ring on it".into(), true));
            return;
        };
        item.jump_rings.at.push(tracery_core::print::RingAt::Point { x_mm: p.x, y_mm: p.y });
        let id = item.id;
        self.selected = Some(id);
        self.message = Some((format!("Jump ring added to Curve {id}"), false));
    }

    /// The latest finished product of a curve on the model.
    pub fn surface_output(&self, id: u64) -> Option<&Arc<tracery_core::Product>> {
        self.surface_worker.output(id)
    }

    /// The object made of every curve on the model, when it is up to date
    /// with all of them.
    pub fn model_object(&self) -> Option<Arc<tracery_core::Product>> {
        if self.model_stale() {
            return None;
        }
        match self.assembly_worker.state(ASSEMBLY) {
            Some(JobState::Done(Ok(object))) => Some(object.clone()),
            _ => None,
        }
    }

    /// Where the pattern of a curve on the model stands.
    pub fn surface_job_state(
        &self,
        id: u64,
    ) -> Option<&JobState<tracery_core::Product, tracery_core::vector_brush::SurfaceSynthesisError>> {
        self.surface_worker.state(id)
    }

    /// The job state of a curve.
    pub fn job_state(&self, id: u64) -> Option<&JobState<tracery_core::Product, JobError>> {
        self.worker.state(id)
    }

    fn submit_jobs(&mut self, ctx: &egui::Context) {
        if !self.waker_set {
            let ctx = ctx.clone();
            let wake: crate::worker::Waker = Arc::new(move || ctx.request_repaint());
            self.worker.set_waker(wake.clone());
            self.gallery.set_waker(wake.clone());
            self.surface_worker.set_waker(wake.clone());
            self.assembly_worker.set_waker(wake.clone());
            self.shade_worker.set_waker(wake.clone());
            self.texture_worker.set_waker(wake.clone());
            self.predictor.set_waker(wake.clone());
            self.live.set_waker(wake);
            self.waker_set = true;
        }
        self.caches.refresh_smoothed(&self.doc.curves);
        let now = Instant::now();
        let gallery_curve = self.gallery_curve();
        for item in &self.doc.curves {
            let Some(curve) = self.caches.smoothed(item.id).cloned() else { continue };
            match mode_ui(&item.mode).job(&curve, &item.mode, &self.doc, &mut self.caches) {
                Ok(mode) => {
                    let job = CurveJob { mode, jump_rings: item.jump_rings.clone(), print: self.doc.print };
                    if gallery_curve == Some(item.id) {
                        let best = CurveJob { mode: job.mode.best(), ..job.clone() };
                        self.gallery.want(item.id, GalleryJob { job: best, closed: item.closed }, now);
                    }
                    self.worker.want(item.id, job, now);
                }
                Err(e) => self.message = Some((e.to_string(), true)),
            }
        }
        self.submit_live(now);
        let predicting = self.submit_predictions(now);
        let surface_busy = self.submit_surface_jobs(now);
        let ids: Vec<u64> = self.doc.curves.iter().map(|c| c.id).collect();
        self.worker.retain(&ids);
        // Only the selected curve's gallery is worth the work.
        self.gallery.retain(&Vec::from_iter(gallery_curve));
        let gallery_busy = self.gallery.poll(now);
        let live_busy = self.live.poll(now);
        if self.worker.poll(now) || gallery_busy || live_busy || surface_busy || predicting {
            ctx.request_repaint_after(BUSY_REPAINT);
        }
    }

    /// Asks for the predictions on screen, forgetting them when their fill
    /// is gone; returns whether they are being made.
    fn submit_predictions(&mut self, now: Instant) -> bool {
        if self.predictions.as_ref().is_some_and(|p| self.doc.curve(p.fill).is_none()) {
            self.predictions = None;
        }
        match &self.predictions {
            Some(p) => self.predictor.want(crate::predictions::PREDICTION_ID, p.job.clone(), now),
            None => self.predictor.retain(&[]),
        }
        self.predictor.poll(now)
    }

    /// Asks for the patterns of the curves on the model; returns whether any is being made.
    fn submit_surface_jobs(&mut self, now: Instant) -> bool {
        let base = self.doc.model.base.clone();
        let mut ids = Vec::new();
        let holds_model = self.doc.model.holds_model();
        if let Ok(model) = self.caches.model(&self.doc.model, &base) {
            for item in self.doc.model.drawn_curves() {
                match self.caches.exemplar(&self.doc, &item.exemplar) {
                    Ok(exemplar) => {
                        let job = SurfaceJob {
                            surface: model.surface.clone(),
                            exemplar,
                            settings: item.settings.clone(),
                            drawn: item.surface.in_object(holds_model),
                            print: self.doc.print,
                        };
                        self.surface_worker.want(item.id, job, now);
                        ids.push(item.id);
                    }
                    Err(e) => self.message = Some((e.to_string(), true)),
                }
            }
        }
        self.surface_worker.retain(&ids);
        let mut shade_ids = Vec::new();
        for item in &self.doc.model.shades {
            match self.caches.exemplar(&self.doc, &item.exemplar) {
                Ok(exemplar) => {
                    let job = ShadeJob {
                        exemplar,
                        settings: item.settings.clone(),
                        shade: item.shade.clone(),
                        lift_mm: item.lift_mm,
                        print: self.doc.print,
                    };
                    self.shade_worker.want(item.id, job, now);
                    shade_ids.push(item.id);
                }
                Err(e) => self.message = Some((e.to_string(), true)),
            }
        }
        self.shade_worker.retain(&shade_ids);
        let busy = self.surface_worker.poll(now) | self.shade_worker.poll(now) | model::submit_texture(self, now);
        self.submit_assembly(now) || busy
    }

    /// A finished part of the object: `None` while it is being made,
    /// `Some(None)` when it failed (its error is on the status line, and
    /// export refuses until it is fixed, so it is left out meanwhile).
    fn finished_part<J: crate::worker::Job<Output = tracery_core::Product>>(
        worker: &Worker<J>,
        id: u64,
        role: PartRole,
    ) -> Option<Option<(Arc<tracery_core::Product>, PartRole)>> {
        match worker.state(id) {
            _ if worker.is_stale(id) => None,
            Some(JobState::Done(Ok(part))) => Some(Some((part.clone(), role))),
            Some(JobState::Done(Err(_))) => Some(None),
            _ => None,
        }
    }

    /// Asks for the object once every curve on the model is done; returns whether it is being made.
    fn submit_assembly(&mut self, now: Instant) -> bool {
        let base = self.doc.model.base.clone();
        let holds_model = self.doc.model.holds_model();
        let bands = self
            .doc
            .model
            .drawn_curves()
            .map(|c| Self::finished_part(&self.surface_worker, c.id, part_role(&c.surface.in_object(holds_model))));
        let shades = self.doc.model.shades.iter().map(|c| Self::finished_part(&self.shade_worker, c.id, PartRole::Add));
        let texture =
            self.doc.model.texture.on.then(|| Self::finished_part(&self.texture_worker, model::TEXTURE, PartRole::Add));
        let parts: Option<Vec<_>> = bands
            .chain(shades)
            .chain(texture)
            .collect::<Option<Vec<_>>>()
            .map(|parts| parts.into_iter().flatten().collect());
        match (parts, self.caches.model(&self.doc.model, &base)) {
            (Some(parts), Ok(model)) if !parts.is_empty() => {
                let with_model = self.doc.model.with_model;
                let job = AssemblyJob { surface: model.surface.clone(), parts, with_model };
                self.assembly_worker.want(ASSEMBLY, job, now);
            }
            // Curves still being made keep the last object on screen.
            (None, Ok(_)) => {}
            _ => self.assembly_worker.retain(&[]),
        }
        self.assembly_worker.poll(now)
    }

    /// One undo step per gesture: a drag of a slider or of a point counts once.
    fn record_history(&mut self, ctx: &egui::Context, before: Document) {
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
    }
}

impl eframe::App for TraceryApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        self.gpu_format = frame.wgpu_render_state().map(|r| r.target_format);
        let before = self.doc.clone();
        self.commands.extend(Command::pressed(&ctx));
        self.dropped_files(&ctx);

        egui::Panel::top("menu").show(ui, |ui| top_bar::top_bar_ui(self, ui));
        egui::Panel::bottom("status").show(ui, |ui| status::status_ui(self, ui));
        if self.gallery_curve().is_some() {
            // A fixed height, so the layout does not jump when the solutions arrive.
            egui::Panel::bottom("gallery")
                .resizable(false)
                .exact_size(gallery::STRIP_HEIGHT)
                .show(ui, |ui| gallery::gallery_ui(self, ui));
        }
        if self.state.workspace == Workspace::Model {
            egui::Panel::left("model controls").resizable(true).default_size(SIDE_PANEL_WIDTH).show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    model::model_panel_ui(self, ui);
                    ui.separator();
                    files::files_ui(self, ui);
                });
            });
            egui::CentralPanel::default().show(ui, |ui| model::model_view_ui(self, ui));
        } else {
            self.canvas_workspace_ui(ui);
        }

        for command in std::mem::take(&mut self.commands) {
            command_handling::run(self, command);
        }
        self.record_history(&ctx, before);
        self.submit_jobs(&ctx);
        self.autosave_now();
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, STORAGE_KEY, &self.state);
    }
}

impl TraceryApp {
    /// The canvas workspace: the brushes' controls, the canvas, and the 3D preview.
    fn canvas_workspace_ui(&mut self, ui: &mut egui::Ui) {
        egui::Panel::left("controls").resizable(true).default_size(SIDE_PANEL_WIDTH).show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| side_panel::side_panel_ui(self, ui));
        });
        if self.state.show_3d {
            egui::Panel::right("preview").resizable(true).default_size(PREVIEW_WIDTH).show(ui, |ui| {
                preview_3d::preview_panel_ui(self, ui);
            });
        }
        egui::CentralPanel::default().show(ui, |ui| canvas::canvas_ui(self, ui));
    }
}

impl TraceryApp {
    /// Whether the autosave is due.
    pub(crate) fn autosave_due(&self) -> bool {
        self.doc != self.autosave.saved && self.autosave.last.elapsed() >= AUTOSAVE_EVERY
    }
}
