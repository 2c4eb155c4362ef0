//! Running the `tracery` command in tests: the binary, a fresh folder for
//! its files, and fields of its JSON report.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

/// The `tracery` binary built for these tests.
pub fn tracery() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tracery"))
}

/// An empty folder of its own for test `name`, removed with what it holds
/// when the test is done with it (a failing test's files go too: its
/// assertion says what was wrong). Every run of the suite left its STLs
/// behind before, a few megabytes each time.
pub fn tempdir(name: &str) -> TestDir {
    let dir = std::env::temp_dir().join(format!("tracery-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    TestDir(dir)
}

/// A test's folder (see [`tempdir`]), removed when dropped.
pub struct TestDir(PathBuf);

impl std::ops::Deref for TestDir {
    type Target = Path;

    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for TestDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for TestDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The value of the first field called `name` in a report, as text.
pub fn field(json: &str, name: &str) -> String {
    let key = format!("\"{name}\": ");
    let start = json.find(&key).unwrap_or_else(|| panic!("no {name} in report")) + key.len();
    json[start..].split([',', '\n']).next().unwrap().trim().trim_matches('"').to_string()
}

/// Runs `tracery SUBCOMMAND ARGS --report REPORT`, which must succeed, and
/// returns the report.
pub fn report_of(subcommand: &str, args: &[&str], report: &std::path::Path) -> String {
    let out = tracery().arg(subcommand).args(args).arg("--report").arg(report).output().unwrap();
    assert!(out.status.success(), "{subcommand} {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    std::fs::read_to_string(report).unwrap()
}
