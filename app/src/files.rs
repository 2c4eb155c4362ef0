//! Writing files safely.

use std::path::Path;

use anyhow::{Context, Result, anyhow};

/// Writes `bytes` to `path` through a temporary file beside it, so that a
/// failure never leaves a partial file and a crash never truncates the old one.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().ok_or_else(|| anyhow!("'{}' is not a file name", path.display()))?;
    let temp = dir.join(format!(".{}.partial", name.to_string_lossy()));
    std::fs::write(&temp, bytes).with_context(|| format!("could not write {}", path.display()))?;
    std::fs::rename(&temp, path).with_context(|| format!("could not write {}", path.display()))?;
    Ok(())
}
