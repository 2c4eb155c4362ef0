//! Every command a person can give, with its label and shortcuts. Buttons,
//! menus and keys all go through [`Command`], and `command_handling` runs them.

use egui::{Key, KeyboardShortcut, Modifiers};

const fn cmd(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::COMMAND, key)
}
const fn plain(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::NONE, key)
}
const COMMAND_SHIFT: Modifiers = Modifiers { shift: true, ..Modifiers::COMMAND };
const UNDO: &[KeyboardShortcut] = &[cmd(Key::Z)];
const REDO: &[KeyboardShortcut] = &[KeyboardShortcut::new(COMMAND_SHIFT, Key::Z), cmd(Key::Y)];
const OPEN: &[KeyboardShortcut] = &[cmd(Key::O)];
const SAVE: &[KeyboardShortcut] = &[cmd(Key::S)];
const EXPORT_STL: &[KeyboardShortcut] = &[cmd(Key::E)];
const DELETE: &[KeyboardShortcut] = &[plain(Key::Delete), plain(Key::Backspace)];
const DESELECT: &[KeyboardShortcut] = &[plain(Key::Escape)];
const ACCEPT: &[KeyboardShortcut] = &[plain(Key::Enter)];
const ACCEPT_PICKED: &[KeyboardShortcut] = &[plain(Key::A)];

/// A command.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Command {
    /// Undo the last change.
    Undo,
    /// Redo what was undone.
    Redo,
    /// Open a project.
    Open,
    /// Save the project (asks where the first time).
    Save,
    /// Save the project under a new name.
    SaveAs,
    /// Import an SVG exemplar.
    ImportSvg,
    /// Import a PNG exemplar for the raster brush.
    ImportPng,
    /// Import a 3D model (STL or OBJ) to draw on.
    ImportModel,
    /// Export STL through a file dialog.
    ExportStl,
    /// Export 3MF (one object per curve) through a file dialog.
    Export3mf,
    /// Export SVG (engrave or cut, as chosen) through a file dialog.
    ExportSvg,
    /// Export STL, 3MF and SVG into the export folder, without a dialog.
    QuickExport,
    /// Delete the selected curve.
    Delete,
    /// Select nothing (the controls then edit the settings for new curves).
    Deselect,
    /// Another pattern for the selected curve (a new seed).
    AnotherOne,
    /// Forget every area painted with the avoidance brush.
    ClearAvoided,
    /// Make every predicted path a pen stroke.
    AcceptPredictions,
    /// Make the predicted paths clicked a pen stroke each, and forget the rest.
    AcceptPicked,
    /// Forget the predicted paths (Escape does too).
    RejectPredictions,
}

impl Command {
    /// Every command, in menu order.
    pub const ALL: [Command; 19] = [
        Command::Undo,
        Command::Redo,
        Command::Open,
        Command::Save,
        Command::SaveAs,
        Command::ImportSvg,
        Command::ImportPng,
        Command::ImportModel,
        Command::ExportStl,
        Command::Export3mf,
        Command::ExportSvg,
        Command::QuickExport,
        Command::Delete,
        Command::Deselect,
        Command::AnotherOne,
        Command::ClearAvoided,
        Command::AcceptPredictions,
        Command::AcceptPicked,
        Command::RejectPredictions,
    ];

    /// The words on its button.
    pub fn label(self) -> &'static str {
        match self {
            Command::Undo => "Undo",
            Command::Redo => "Redo",
            Command::Open => "Open…",
            Command::Save => "Save",
            Command::SaveAs => "Save…",
            Command::ImportSvg => "Import SVG…",
            Command::ImportPng => "Import PNG…",
            Command::ImportModel => "Import model…",
            Command::ExportStl => "Export STL…",
            Command::Export3mf => "Export 3MF…",
            Command::ExportSvg => "Export SVG…",
            Command::QuickExport => "Quick export",
            Command::Delete => "Delete",
            Command::Deselect => "Deselect",
            Command::AnotherOne => "Another one",
            Command::ClearAvoided => "Clear avoided areas",
            Command::AcceptPredictions => "Accept all",
            Command::AcceptPicked => "Accept picked",
            Command::RejectPredictions => "Reject",
        }
    }

    /// Its keyboard shortcuts; the first is shown in tooltips.
    pub fn shortcuts(self) -> &'static [KeyboardShortcut] {
        match self {
            Command::Undo => UNDO,
            Command::Redo => REDO,
            Command::Open => OPEN,
            Command::Save => SAVE,
            Command::ExportStl => EXPORT_STL,
            Command::Delete => DELETE,
            Command::Deselect => DESELECT,
            Command::AcceptPredictions => ACCEPT,
            Command::AcceptPicked => ACCEPT_PICKED,
            Command::SaveAs
            | Command::ImportSvg
            | Command::ImportPng
            | Command::ImportModel
            | Command::ClearAvoided
            | Command::Export3mf
            | Command::ExportSvg
            | Command::QuickExport
            | Command::AnotherOne
            // Escape rejects predictions through Deselect, which must see the key first.
            | Command::RejectPredictions => &[],
        }
    }

    /// Whether its shortcuts are plain keys, which must not fire while a
    /// text field has the keyboard.
    fn plain_keys(self) -> bool {
        self.shortcuts().iter().all(|s| s.modifiers.is_none())
    }

    /// The commands whose shortcut was pressed this frame (consumed).
    pub fn pressed(ctx: &egui::Context) -> Vec<Command> {
        let typing = ctx.egui_wants_keyboard_input();
        let mut out = Vec::new();
        // Longer shortcuts first, so Ctrl+Shift+Z is not read as Ctrl+Z.
        let mut all: Vec<(Command, KeyboardShortcut)> =
            Command::ALL.iter().flat_map(|&c| c.shortcuts().iter().map(move |s| (c, *s))).collect();
        all.sort_by_key(|(_, s)| std::cmp::Reverse(s.modifiers.shift as u8 + s.modifiers.command as u8));
        for (command, shortcut) in all {
            if command.plain_keys() && typing {
                continue;
            }
            if ctx.input_mut(|i| i.consume_shortcut(&shortcut)) && !out.contains(&command) {
                out.push(command);
            }
        }
        out
    }

    /// A button for the command, with its shortcut in the tooltip; true when clicked.
    pub fn button(self, ui: &mut egui::Ui, enabled: bool) -> bool {
        let response = ui.add_enabled(enabled, egui::Button::new(self.label()));
        let response = match self.shortcuts().first() {
            Some(s) => response.on_hover_text(ui.ctx().format_shortcut(s)),
            None => response,
        };
        response.clicked()
    }
}
