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
