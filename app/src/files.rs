//! Writing files so that nothing is ever half written: each file is written
//! whole and flushed to the disk under a name of its own before it takes
//! the place of the old one, and a run with several outputs puts none of
//! them in place until all are written.
//!
//! On Linux the file is first written without any name (`O_TMPFILE`), so a
//! run killed at any moment leaves no temporary file behind: the kernel
//! frees a nameless file with the process. Elsewhere, or on a file system
//! without nameless files, a temporary name unique to the process is used
//! and removed on every error.

use std::fs::File;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use anyhow::{Context, Result, anyhow, bail};

/// A file written whole and flushed, not yet in its place.
pub struct Staged {
    path: PathBuf,
    file: File,
    /// The temporary name, when the file has one (see the module's note).
    temp: Option<PathBuf>,
}

/// Counts temporary names so that two writes of one process never share one.
static NEXT_TEMP: AtomicU64 = AtomicU64::new(0);

/// A temporary name beside `path`, unique to this process and this write:
/// two windows saving at once never write into each other's file.
fn temp_name(path: &Path) -> Result<PathBuf> {
    let name = path.file_name().ok_or_else(|| anyhow!("'{}' is not a file name", path.display()))?;
    let n = NEXT_TEMP.fetch_add(1, Ordering::Relaxed);
    Ok(folder_of(path).join(format!(".{}.{}-{n}.partial", name.to_string_lossy(), std::process::id())))
}

/// The folder `path` is written in.
fn folder_of(path: &Path) -> &Path {
    path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."))
}

/// A file without a name in `folder`, where the system has them.
#[cfg(target_os = "linux")]
fn nameless_file(folder: &Path) -> Option<File> {
    use rustix::fs::{Mode, OFlags};
    let flags = OFlags::TMPFILE | OFlags::WRONLY | OFlags::CLOEXEC;
    rustix::fs::open(folder, flags, Mode::from_bits_truncate(0o644)).ok().map(File::from)
}

#[cfg(not(target_os = "linux"))]
fn nameless_file(_folder: &Path) -> Option<File> {
    None
}

/// Gives the nameless `file` the name `to` (which must not exist).
#[cfg(target_os = "linux")]
fn name_file(file: &File, to: &Path) -> std::io::Result<()> {
    use std::os::fd::AsRawFd as _;
    let fd = PathBuf::from(format!("/proc/self/fd/{}", file.as_raw_fd()));
    rustix::fs::linkat(rustix::fs::CWD, &fd, rustix::fs::CWD, to, rustix::fs::AtFlags::SYMLINK_FOLLOW)?;
    Ok(())
}

#[cfg(not(target_os = "linux"))]
fn name_file(_file: &File, _to: &Path) -> std::io::Result<()> {
    Err(std::io::Error::from(std::io::ErrorKind::Unsupported))
}

/// Flushes a folder's entries (a rename in it) to the disk. Not every
/// system can open a folder for that; the file's own data is flushed anyway.
fn sync_folder(folder: &Path) {
    if let Ok(dir) = File::open(folder) {
        let _ = dir.sync_all();
    }
}

/// Checks, before any work, that `path` can be written: its folder exists
/// and takes new files, and it is not a folder itself. Nothing is left
/// behind by the check.
pub fn check_writable(path: &Path) -> Result<()> {
    let folder = folder_of(path);
    if path.file_name().is_none() || path.is_dir() {
        bail!("cannot write {}: it is a folder, not a file name", path.display());
    }
    if !folder.is_dir() {
        bail!("cannot write {}: there is no folder {}", path.display(), folder.display());
    }
    if nameless_file(folder).is_some() {
        return Ok(());
    }
    let probe = temp_name(path)?;
    let made = File::create(&probe).with_context(|| format!("cannot write {}", path.display()));
    let _ = std::fs::remove_file(&probe);
    made.map(drop)
}

/// Writes `bytes` for `path` and flushes them to the disk, without yet
/// touching `path` itself.
pub fn stage(path: &Path, bytes: &[u8]) -> Result<Staged> {
    let fail = || format!("could not write {}", path.display());
    let folder = folder_of(path);
    let (file, temp) = match nameless_file(folder) {
        Some(file) => (file, None),
        None => {
            let temp = temp_name(path)?;
            let file = File::create(&temp).with_context(fail)?;
            (file, Some(temp))
        }
    };
    let mut staged = Staged { path: path.to_path_buf(), file, temp };
    staged.file.write_all(bytes).with_context(fail)?;
    staged.file.sync_all().with_context(fail)?;
    Ok(staged)
}

impl Staged {
    /// Puts the file in its place, replacing any old one in one step.
    pub fn commit(mut self) -> Result<()> {
        let fail = || format!("could not write {}", self.path.display());
        let temp = match self.temp.take() {
            Some(temp) => temp,
            None => {
                let temp = temp_name(&self.path)?;
                name_file(&self.file, &temp).with_context(fail)?;
                temp
            }
        };
        if let Err(e) = std::fs::rename(&temp, &self.path) {
            let _ = std::fs::remove_file(&temp);
            return Err(e).with_context(fail);
        }
        sync_folder(folder_of(&self.path));
        Ok(())
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if let Some(temp) = &self.temp {
            let _ = std::fs::remove_file(temp);
        }
    }
}

/// Writes `bytes` to `path` so that a failure or a crash leaves either the
/// old file or the whole new one, and no temporary file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    stage(path, bytes)?.commit()
}

/// Refuses one path given for two outputs, which would write one over the other.
pub fn refuse_same_path(paths: &[(&str, &Path)]) -> Result<()> {
    let key = |p: &Path| -> PathBuf {
        let folder = std::fs::canonicalize(folder_of(p)).unwrap_or_else(|_| folder_of(p).to_path_buf());
        folder.join(p.file_name().unwrap_or_default())
    };
    for (i, (flag_a, a)) in paths.iter().enumerate() {
        for (flag_b, b) in &paths[..i] {
            if key(a) == key(b) {
                bail!("{flag_b} and {flag_a} both name {}: give each output its own file", a.display());
            }
        }
    }
    Ok(())
}

/// Writes every file or none: all are written and flushed first, and put
/// in place only when all are.
pub fn write_all_or_none(files: &[(&Path, &[u8])]) -> Result<()> {
    let staged = files.iter().map(|(path, bytes)| stage(path, bytes)).collect::<Result<Vec<_>>>()?;
    for file in staged {
        file.commit()?;
    }
    Ok(())
}
