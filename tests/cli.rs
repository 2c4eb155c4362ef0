//! The `tracery` command as a person runs it.

#[path = "common/cli.rs"]
mod cli;
use cli::tracery;

#[test]
fn list_prints_every_builtin() {
    let out = tracery().arg("list").output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for name in tracery_core::vector_brush::BUILTIN_NAMES {
        assert!(text.lines().any(|l| l.starts_with(name)), "{name} missing from:\n{text}");
    }
}

#[test]
fn unknown_command_fails_and_says_so() {
    let out = tracery().arg("frobnicate").output().unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("frobnicate"), "{err}");
}

#[test]
fn a_listing_cut_short_by_its_reader_ends_quietly() {
    // As `tracery list --raster | head -0`: the reader is gone before the
    // first line (the raster built-ins are painted first), so every write
    // meets a broken pipe.
    let mut child = tracery()
        .args(["list", "--raster"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(!err.contains("panicked"), "{err}");
    assert!(out.status.success(), "{err}");
}
