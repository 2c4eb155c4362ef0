//! The SVG files of a corpus folder, for the examples that sweep it.

use std::path::{Path, PathBuf};

/// Every `.svg` file in `dir`, sorted by path, so sweeps run in the same
/// order everywhere. Panics, naming the folder, when it cannot be read.
pub fn svg_files(dir: impl AsRef<Path>) -> Vec<PathBuf> {
    let dir = dir.as_ref();
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "svg"))
        .collect();
    files.sort();
    files
}
