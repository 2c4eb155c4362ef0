//! File dialogs, behind a trait so tests can answer them.

use std::path::PathBuf;

/// What kind of file a dialog asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// An SVG exemplar to import.
    ImportSvg,
    /// A PNG exemplar (with transparency) to import.
    ImportPng,
    /// A 3D model (STL or OBJ) to draw on.
    ImportModel,
    /// A project to open.
    OpenProject,
    /// Where to save the project.
    SaveProject,
    /// Where to write an STL.
    ExportStl,
    /// Where to write a 3MF.
    Export3mf,
    /// Where to write an SVG.
    ExportSvg,
}

/// Asks a person for a file.
pub trait Dialogs {
    /// A path, or `None` when cancelled (or when no dialog can be shown).
    fn pick(&mut self, kind: FileKind) -> Option<PathBuf>;
}

/// The system's file dialogs, through the desktop portal.
#[derive(Default)]
pub struct SystemDialogs;

impl Dialogs for SystemDialogs {
    fn pick(&mut self, kind: FileKind) -> Option<PathBuf> {
        let dialog = rfd::FileDialog::new();
        match kind {
            FileKind::ImportSvg => dialog.add_filter("SVG", &["svg"]).set_title("Import an exemplar").pick_file(),
            FileKind::ImportPng => dialog.add_filter("PNG", &["png"]).set_title("Import a raster exemplar").pick_file(),
            FileKind::ImportModel => {
                dialog.add_filter("3D model", &["stl", "obj"]).set_title("Import a model to draw on").pick_file()
            }
            FileKind::OpenProject => dialog.add_filter("Tracery project", &["ron"]).pick_file(),
            FileKind::SaveProject => {
                dialog.add_filter("Tracery project", &["ron"]).set_file_name("pattern.ron").save_file()
            }
            FileKind::ExportStl => dialog.add_filter("STL", &["stl"]).set_file_name("pattern.stl").save_file(),
            FileKind::Export3mf => dialog.add_filter("3MF", &["3mf"]).set_file_name("pattern.3mf").save_file(),
            FileKind::ExportSvg => dialog.add_filter("SVG", &["svg"]).set_file_name("pattern.svg").save_file(),
        }
    }
}

/// Dialogs that answer from a list, for tests and scripted runs.
#[derive(Default)]
pub struct ScriptedDialogs {
    /// Answers, taken in order for each kind.
    pub answers: Vec<(FileKind, PathBuf)>,
}

impl Dialogs for ScriptedDialogs {
    fn pick(&mut self, kind: FileKind) -> Option<PathBuf> {
        let at = self.answers.iter().position(|(k, _)| *k == kind)?;
        Some(self.answers.remove(at).1)
    }
}
