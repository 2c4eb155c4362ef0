//! Running commands: open, save, import, export, undo and the rest, and the
//! autosave. Every button, menu entry and shortcut ends up in [`run`].

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use tracery_core::export::{ThreeMfObject, object_colour, write_3mf, write_stl, write_svg};
use tracery_core::geom::Region;
use tracery_core::mesh::Mesh;

use crate::TraceryApp;
use crate::command::Command;
use crate::dialogs::FileKind;
use crate::document::{
    Document, DocumentError, ExemplarRef, ModeSettings, RasterBrushItem, RegionFillItem, VectorBrushItem,
};
use crate::files::write_atomically;
use crate::model::ASSEMBLY;
use crate::state::Workspace;
use crate::worker::JobState;
use tracery_core::Product;
use tracery_core::mesh::read_mesh_file;

/// A finished job's product (`Some(None)` when it failed), or `None` while unfinished.
fn done<E>(state: Option<&JobState<Product, E>>) -> Option<Option<Arc<Product>>> {
    match state {
        Some(JobState::Done(Ok(product))) => Some(Some(product.clone())),
        Some(JobState::Done(Err(_))) => Some(None),
        _ => None,
    }
}

/// Runs `command` on the app.
pub fn run(app: &mut TraceryApp, command: Command) {
    match command {
        Command::Undo => {
            if app.history.undo(&mut app.doc) {
                app.after_document_swap();
            }
        }
        Command::Redo => {
            if app.history.redo(&mut app.doc) {
                app.after_document_swap();
            }
        }
        Command::Open => {
            if let Some(p) = app.dialogs.pick(FileKind::OpenProject) {
                app.open_project(&p);
            }
        }
        Command::Save => app.save_project(false),
        Command::SaveAs => app.save_project(true),
        Command::ImportSvg => {
            if let Some(p) = app.dialogs.pick(FileKind::ImportSvg) {
                app.import_svg(&p);
            }
        }
        Command::ImportPng => {
            if let Some(p) = app.dialogs.pick(FileKind::ImportPng) {
                app.import_png(&p);
            }
        }
        Command::ImportModel => {
            if let Some(p) = app.dialogs.pick(FileKind::ImportModel) {
                app.import_model(&p);
            }
        }
        Command::ExportStl => match app.dialogs.pick(FileKind::ExportStl) {
            Some(p) => app.export_stl_to(&p),
            None => app.message = Some(("No file chosen; Quick export writes without a dialog".into(), false)),
        },
        Command::Export3mf => {
            if let Some(p) = app.dialogs.pick(FileKind::Export3mf) {
                app.export_3mf_to(&p);
            }
        }
        Command::ExportSvg => {
            if let Some(p) = app.dialogs.pick(FileKind::ExportSvg) {
                app.export_svg_to(&p);
            }
        }
        Command::QuickExport => app.quick_export(),
        Command::Delete => app.delete_selected(),
        // Escape takes back predictions first.
        Command::Deselect if app.predictions.is_some() => app.reject_predictions(),
        Command::AcceptPredictions => app.accept_predictions(false),
        Command::AcceptPicked => app.accept_predictions(true),
        Command::RejectPredictions => app.reject_predictions(),
        Command::Deselect => match app.state.workspace {
            Workspace::Canvas => app.selected = None,
            Workspace::Model => app.selected_surface = None,
        },
        Command::AnotherOne => app.next_alternative(),
        Command::ClearAvoided => {
            if !app.doc.avoid.is_empty() {
                app.history.record(app.doc.clone());
                app.doc.avoid.clear();
                app.history_handled = true;
                app.message = Some(("Cleared the avoided areas".into(), false));
            }
        }
    }
}

impl TraceryApp {
    fn after_document_swap(&mut self) {
        self.history_handled = true;
        if self.selected.is_some_and(|id| self.doc.curve(id).is_none()) {
            self.selected = None;
        }
        if self.selected_surface.is_some_and(|id| self.doc.model.curve(id).is_none()) {
            self.selected_surface = None;
        }
        self.caches.forget_imported();
    }

    fn delete_selected(&mut self) {
        let selected = match self.state.workspace {
            Workspace::Model => self.selected_surface.take(),
            Workspace::Canvas => self.selected.take(),
        };
        let Some(id) = selected else { return };
        self.history.record(self.doc.clone());
        // Ids are shared by canvas curves, model curves and shades: one of them goes.
        self.doc.curves.retain(|c| c.id != id);
        self.doc.model.curves.retain(|c| c.id != id);
        self.doc.model.shades.retain(|c| c.id != id);
        self.history_handled = true;
    }

    /// Imports a 3D model from `path` and draws on it; a model that cannot
    /// be drawn on (broken, too large) is refused with the reason, and the
    /// document is left as it was.
    pub fn import_model(&mut self, path: &Path) {
        let result = read_mesh_file(path).map_err(|e| e.to_string()).and_then(|mesh| {
            let name = path.file_name().map_or_else(|| "model".into(), |n| n.to_string_lossy().into_owned());
            let before = self.doc.clone();
            let base = self.doc.model.import(&name, &mesh).map_err(|e| e.to_string())?;
            // Checked as the workspace loads it (from the embedded copy), once:
            // the loaded model stays in the cache for drawing and picking.
            if let Err(e) = self.caches.model(&self.doc.model, &base) {
                self.caches.forget_model(&base);
                self.doc = before;
                return Err(format!("{} was not imported: {e}", path.display()));
            }
            self.history.record(before);
            self.history_handled = true;
            self.doc.model.base = base.clone();
            self.state.workspace = Workspace::Model;
            Ok(format!("Imported the model {} ({} triangles)", base.name(), mesh.triangles.len()))
        });
        self.message = Some(match result {
            Ok(text) => (text, false),
            Err(e) => (e, true),
        });
    }

    /// Imports an SVG exemplar from `path`: a curve exemplar when the
    /// controls are region fill's, otherwise one for the vector brush. On
    /// failure the document is left as it was.
    pub fn import_svg(&mut self, path: &Path) {
        if let ModeSettings::RegionFill(item) = self.settings() {
            let item = item.clone();
            self.import_exemplar(path, "curves.svg", |doc, name, bytes| {
                let r = doc.import_curves(name, &String::from_utf8_lossy(bytes))?;
                Ok((r.clone(), RegionFillItem { exemplar: r, ..item }.into()))
            });
            return;
        }
        self.import_exemplar(path, "exemplar.svg", |doc, name, bytes| {
            let r = doc.import(name, &String::from_utf8_lossy(bytes))?;
            // An SVG exemplar is for the vector brush: the controls switch to it.
            Ok((r.clone(), VectorBrushItem { exemplar: r, ..Default::default() }.into()))
        });
    }

    /// Imports a PNG exemplar from `path` for the raster brush; on failure
    /// the document is left as it was.
    pub fn import_png(&mut self, path: &Path) {
        self.import_exemplar(path, "exemplar.png", |doc, name, bytes| {
            let r = doc.import_png(name, bytes)?;
            // A PNG exemplar is for the raster brush: the controls switch to it.
            Ok((r.clone(), RasterBrushItem { exemplar: r, ..Default::default() }.into()))
        });
    }

    /// Reads `path` and hands it to `import`, which adds it to the document
    /// and gives the settings of the mode that uses it; those replace the
    /// controls' settings unless they are of that mode already (then only
    /// the exemplar changes). One undo step; on failure nothing changes.
    fn import_exemplar(
        &mut self,
        path: &Path,
        fallback_name: &str,
        import: impl FnOnce(&mut Document, &str, &[u8]) -> Result<(ExemplarRef, ModeSettings), DocumentError>,
    ) {
        let name = path.file_name().map_or_else(|| fallback_name.into(), |n| n.to_string_lossy().into_owned());
        let bytes = match std::fs::read(path) {
            Ok(bytes) => bytes,
            Err(e) => {
                self.message = Some((format!("Could not read {}: {e}", path.display()), true));
                return;
            }
        };
        let before = self.doc.clone();
        match import(&mut self.doc, &name, &bytes) {
            Ok((r, fresh)) => {
                self.history.record(before);
                self.history_handled = true;
                let settings = self.settings_mut();
                let same_mode = std::mem::discriminant(settings) == std::mem::discriminant(&fresh);
                match settings.exemplar_mut() {
                    Some(exemplar) if same_mode => *exemplar = r.clone(),
                    _ => *settings = fresh,
                }
                self.message = Some((format!("Imported '{}'", r.name()), false));
            }
            Err(e) => self.message = Some((format!("Could not import: {e}"), true)),
        }
    }

    /// Opens a project (any format version this one reads).
    pub fn open_project(&mut self, path: &Path) {
        let read = std::fs::read_to_string(path).map_err(|e| e.to_string());
        match read.and_then(|t| Document::from_ron(&t).map_err(|e| e.to_string())) {
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
        let result = self.doc.to_ron().map_err(anyhow::Error::from).and_then(|t| write_atomically(&path, t.as_bytes()));
        self.message = Some(match result {
            Ok(()) => {
                self.state.project_path = Some(path.clone());
                (format!("Saved {}", path.display()), false)
            }
            Err(e) => (format!("{e:#}"), true),
        });
    }

    fn export_ids(&self) -> Vec<u64> {
        match self.state.workspace {
            Workspace::Canvas => match (self.state.export_selected_only, self.selected) {
                (true, Some(id)) => vec![id],
                _ => self.doc.curves.iter().map(|c| c.id).collect(),
            },
            // The object on the model is one: every curve and shade is in it.
            Workspace::Model => {
                let curves = self.doc.model.drawn_curves().map(|c| c.id);
                let texture = self.doc.model.texture.on.then_some(crate::model::TEXTURE);
                curves.chain(self.doc.model.shades.iter().map(|c| c.id)).chain(texture).collect()
            }
        }
    }

    /// The finished products to export, each with its name (a canvas curve
    /// is "Curve ID"; the model workspace exports its one object), or why
    /// they cannot be.
    fn export_products(&self) -> Result<Vec<(String, Arc<Product>)>, String> {
        let ids = self.export_ids();
        if ids.is_empty() {
            return Err("Nothing to export: draw a curve first".into());
        }
        let products: Vec<(String, Arc<Product>)> = ids
            .iter()
            .map(|&id| {
                // Finished: the product, or `None` when the job failed.
                let (stale, finished) = match self.state.workspace {
                    Workspace::Canvas => (self.worker.is_stale(id), done(self.worker.state(id))),
                    Workspace::Model if id == crate::model::TEXTURE => {
                        (self.texture_worker.is_stale(id), done(self.texture_worker.state(id)))
                    }
                    Workspace::Model if self.doc.model.shade(id).is_some() => {
                        (self.shade_worker.is_stale(id), done(self.shade_worker.state(id)))
                    }
                    Workspace::Model => (self.surface_worker.is_stale(id), done(self.surface_worker.state(id))),
                };
                match (stale, finished) {
                    (false, Some(Some(product))) => Ok((format!("Curve {id}"), product)),
                    (true, _) => {
                        Err("A pattern is still being synthesized; export when the status bar says done".into())
                    }
                    _ => Err("A curve has no pattern (see the status bar); fix or delete it before exporting".into()),
                }
            })
            .collect::<Result<_, String>>()?;
        if self.state.workspace == Workspace::Canvas {
            return Ok(products);
        }
        match (self.model_object(), self.assembly_worker.state(ASSEMBLY)) {
            (Some(object), _) => Ok(vec![(self.doc.model.base.name().to_string(), object)]),
            (None, Some(JobState::Done(Err(e)))) if !self.assembly_worker.is_stale(ASSEMBLY) => {
                Err(format!("The curves could not be combined with the model: {e}"))
            }
            _ => Err("The object is still being made; export when the status bar says done".into()),
        }
    }

    /// Writes the STL of the exported curves (all, or the selected one) to `path`.
    pub fn export_stl_to(&mut self, path: &Path) {
        let result = self.export_products().and_then(|products| {
            let mut all = Mesh::default();
            for mesh in products.iter().filter_map(|(_, p)| p.mesh_mm.as_ref()) {
                all.append(mesh);
            }
            let mut bytes = Vec::new();
            write_stl(&all, &mut bytes).map_err(|e| e.to_string())?;
            write_atomically(path, &bytes).map_err(|e| format!("{e:#}"))?;
            Ok(all.triangles.len())
        });
        self.message = Some(match result {
            Ok(n) => (format!("Exported {n} triangles to {}", path.display()), false),
            Err(e) => (e, true),
        });
    }

    /// Writes the 3MF of the exported curves to `path`: one object per
    /// canvas curve, named after it, each with a colour of its own; or the
    /// model workspace's one object, named after the model.
    pub fn export_3mf_to(&mut self, path: &Path) {
        let result = self.export_products().and_then(|products| {
            let objects: Vec<ThreeMfObject<'_>> = products
                .iter()
                .enumerate()
                .filter_map(|(k, (name, p))| {
                    let mesh = p.mesh_mm.as_ref()?;
                    Some(ThreeMfObject { name: name.clone(), colour_rgb: object_colour(k), mesh })
                })
                .collect();
            let mut bytes = std::io::Cursor::new(Vec::new());
            write_3mf(&objects, &mut bytes).map_err(|e| e.to_string())?;
            write_atomically(path, bytes.get_ref()).map_err(|e| format!("{e:#}"))?;
            Ok(objects.len())
        });
        self.message = Some(match result {
            Ok(n) => (format!("Exported {n} object(s) to {}", path.display()), false),
            Err(e) => (e, true),
        });
    }

    /// Writes the SVG of the exported curves to `path`, engrave or cut as chosen.
    pub fn export_svg_to(&mut self, path: &Path) {
        let options = self.state.svg;
        let result = self.export_products().and_then(|products| {
            let mut region = Region::default();
            for (_, p) in products {
                region.polygons.extend(p.region_mm.polygons.iter().cloned());
            }
            write_atomically(path, write_svg(&region, &options).as_bytes()).map_err(|e| format!("{e:#}"))
        });
        self.message = Some(match result {
            Ok(()) => (format!("Exported {}", path.display()), false),
            Err(e) => (e, true),
        });
    }

    /// Writes STL, 3MF and SVG into the export folder under a new name.
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
            self.export_3mf_to(&folder.join(format!("tracery-{stamp}.3mf")));
        }
        if matches!(self.message, Some((_, false))) {
            self.export_svg_to(&folder.join(format!("tracery-{stamp}.svg")));
        }
        if matches!(self.message, Some((_, false))) {
            self.message = Some((format!("Exported {} and .3mf, .svg", stl.display()), false));
        }
    }

    /// Files dropped on the window: projects open, PNG files import as raster
    /// exemplars, anything else as an SVG exemplar (see [`Self::import_svg`]).
    pub(crate) fn dropped_files(&mut self, ctx: &egui::Context) {
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        for file in dropped {
            let path = file.path().to_path_buf();
            match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
                Some("ron") => self.open_project(&path),
                Some("png") => self.import_png(&path),
                _ => self.import_svg(&path),
            }
        }
    }

    /// Restores the last session's document, if anything was drawn in it
    /// (on the canvas or on the model). An autosave that cannot be read (a
    /// newer format, a damaged file) is moved aside, never written over, and
    /// the previous good copy is restored in its place when there is one.
    pub fn restore_autosave(&mut self) {
        let Some(path) = self.autosave.path.clone() else { return };
        let Ok(text) = std::fs::read_to_string(&path) else { return };
        let (doc, text, note) = match Document::from_ron(&text) {
            Ok(doc) => (doc, text, String::new()),
            Err(e) => {
                let aside = autosave_aside(&path);
                let moved = std::fs::rename(&path, &aside).is_ok();
                let kept = if moved { format!("kept as {}", aside.display()) } else { "left as it was".into() };
                let previous = previous_copy(&path);
                match std::fs::read_to_string(&previous).ok().and_then(|t| Document::from_ron(&t).ok().map(|d| (d, t)))
                {
                    Some((doc, text)) if moved => {
                        (doc, text, format!(" from its previous copy (the last one could not be read: {e}; {kept})"))
                    }
                    _ => {
                        self.message =
                            Some((format!("Could not restore the last session: {e} (the file is {kept})"), true));
                        if !moved {
                            // Never written over: autosave is off for this session.
                            self.autosave.path = None;
                        }
                        return;
                    }
                }
            }
        };
        if doc.has_drawing() {
            let curves = doc.curves.len() + doc.model.curves.len();
            self.message = Some((format!("Restored your last session ({curves} curves){note}"), false));
            self.autosave.saved = doc.clone();
            self.autosave.saved_text = Some(text);
            self.doc = doc;
        }
    }

    /// Writes the autosave when the document changed and enough time
    /// passed, keeping the copy it replaces beside it.
    pub(crate) fn autosave_now(&mut self) {
        if !self.autosave_due() {
            return;
        }
        let Some(path) = self.autosave.path.clone() else { return };
        self.autosave.last = Instant::now();
        let Ok(text) = self.doc.to_ron() else { return };
        if self.autosave.saved_text.as_deref() == Some(text.as_str()) {
            self.autosave.saved = self.doc.clone();
            return;
        }
        if let Some(dir) = path.parent() {
            let _ = std::fs::create_dir_all(dir);
        }
        // The copy being replaced was written (or read) whole by this app: it
        // becomes the previous copy, which a damaged autosave falls back to.
        if self.autosave.saved_text.is_some()
            && let Ok(old) = std::fs::read(&path)
        {
            let _ = write_atomically(&previous_copy(&path), &old);
        }
        if write_atomically(&path, text.as_bytes()).is_ok() {
            self.autosave.saved = self.doc.clone();
            self.autosave.saved_text = Some(text);
        }
    }
}

/// The previous good copy of an autosave, beside it.
pub fn previous_copy(autosave: &Path) -> PathBuf {
    autosave.with_extension("previous.ron")
}

/// Where an autosave that could not be read is moved, beside it, under a
/// name no other session uses.
fn autosave_aside(autosave: &Path) -> PathBuf {
    let seconds = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    autosave.with_extension(format!("unreadable-{seconds}-{}.ron", std::process::id()))
}
