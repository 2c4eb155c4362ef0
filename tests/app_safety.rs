//! The app never loses a drawing and keeps working: a job that panics
//! shows an internal error instead of running for ever, and the autosave
//! keeps its previous copy, never writes over a file it could not read,
//! and writes only when the document changed.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::{Duration, Instant};

use egui_kittest::Harness;
use tracery::TraceryApp;
use tracery::dialogs::ScriptedDialogs;
use tracery::document::SurfaceCurveItem;
use tracery::worker::{Job, JobState, Worker};
use tracery_core::control::{Control, Internal, MaybeCancelled};

#[derive(Clone, PartialEq)]
struct Panics;

#[derive(Debug, thiserror::Error)]
#[error(transparent)]
struct PanicError(#[from] Internal);

impl MaybeCancelled for PanicError {
    fn is_cancelled(&self) -> bool {
        false
    }
}

impl Job for Panics {
    type Output = ();
    type Error = PanicError;

    fn run(&self, _control: &Control) -> Result<(), PanicError> {
        let coordinates = [f64::NAN, 1.0];
        // As a library's assertion fails on input it was never meant to get.
        assert!(coordinates[0] <= coordinates[1], "min > max, or either was NaN");
        Ok(())
    }
}

#[test]
fn a_job_that_panics_shows_an_internal_error_and_the_worker_goes_on() {
    let mut worker: Worker<Panics> = Worker::new(Arc::new(|| {}));
    let start = Instant::now();
    worker.want(7, Panics, start);
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        let now = start + Duration::from_secs(1) + start.elapsed();
        let busy = worker.poll(now);
        if !busy || Instant::now() > deadline {
            break;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    match worker.state(7) {
        Some(JobState::Done(Err(e))) => {
            let text = e.to_string();
            assert!(text.starts_with("internal error: min > max"), "{text}");
            assert!(text.contains("report"), "says what to report: {text}");
        }
        Some(JobState::Running { .. }) => panic!("the job still shows as running after it panicked"),
        other => panic!("no error shown: {:?}", other.map(|_| ())),
    }
}

/// An app autosaving to `path`, with one curve on the model.
fn app_with_a_drawing(path: &Path) -> TraceryApp {
    let mut app = TraceryApp::with(Box::new(ScriptedDialogs::default()), Some(path.to_path_buf()));
    app.restore_autosave();
    let id = app.doc.add_surface_curve(&SurfaceCurveItem::default());
    app.doc.model.curve_mut(id).unwrap().surface.points_mm = vec![[30.0, 0.0, 25.0], [0.0, 30.0, 25.0]];
    app
}

/// Steps the app's frame loop until `done` or `seconds` pass; whether `done` came.
fn step_until(harness: &mut Harness<'_, TraceryApp>, seconds: u64, done: impl Fn(&TraceryApp) -> bool) -> bool {
    let deadline = Instant::now() + Duration::from_secs(seconds);
    while Instant::now() < deadline {
        harness.step();
        if done(harness.state()) {
            return true;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    false
}

fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tracery-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn an_autosave_that_cannot_be_read_is_kept_aside_never_written_over() {
    let dir = folder("autosave-unreadable");
    let path = dir.join("autosave.ron");
    // As from a newer Tracery, or damaged on the disk.
    let theirs = "(format: 99, curves: [\"a drawing from a newer version\"])";
    std::fs::write(&path, theirs).unwrap();
    let app = app_with_a_drawing(&path);
    let said = app.message.clone().map(|(m, _)| m).unwrap_or_default();
    assert!(said.contains("Could not restore") && said.contains("kept as"), "{said}");
    let mut harness = Harness::builder().build_eframe(move |_| app);
    assert!(step_until(&mut harness, 10, |_| path.exists()), "the new drawing was never autosaved");
    let aside: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.file_name().is_some_and(|n| n.to_string_lossy().contains("unreadable")))
        .collect();
    assert_eq!(aside.len(), 1, "{aside:?}");
    assert_eq!(std::fs::read_to_string(&aside[0]).unwrap(), theirs, "the unreadable file was changed");
    assert!(said.contains(&*aside[0].to_string_lossy()), "the message says where: {said}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_autosave_keeps_its_previous_copy_and_falls_back_to_it() {
    let dir = folder("autosave-previous");
    let path = dir.join("autosave.ron");
    let app = app_with_a_drawing(&path);
    let mut harness = Harness::builder().build_eframe(move |_| app);
    assert!(step_until(&mut harness, 10, |_| path.exists()));
    let first = std::fs::read_to_string(&path).unwrap();
    // A second curve: the first autosave becomes the previous copy.
    harness.state_mut().doc.add_surface_curve(&SurfaceCurveItem::default());
    let previous = path.with_extension("previous.ron");
    assert!(step_until(&mut harness, 10, |_| previous.exists()), "no previous copy kept");
    assert_eq!(std::fs::read_to_string(&previous).unwrap(), first);
    // The newest copy is damaged (a crash of the disk, not of Tracery):
    // the previous one comes back.
    std::fs::write(&path, "(curves: [").unwrap();
    let mut restored = TraceryApp::with(Box::new(ScriptedDialogs::default()), Some(path.clone()));
    restored.restore_autosave();
    assert_eq!(restored.doc.model.curves.len(), 1, "{:?}", restored.message);
    assert!(restored.message.clone().unwrap().0.contains("previous copy"), "{:?}", restored.message);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_document_holding_nan_is_autosaved_once_not_every_two_seconds() {
    let dir = folder("autosave-nan");
    let path = dir.join("autosave.ron");
    let mut app = app_with_a_drawing(&path);
    let id = app.doc.model.curves[0].id;
    app.doc.model.curve_mut(id).unwrap().surface.twist_deg = f64::NAN;
    assert_ne!(app.doc, app.doc.clone(), "the document must not equal itself for this test");
    let mut harness = Harness::builder().build_eframe(move |_| app);
    assert!(step_until(&mut harness, 10, |_| path.exists()));
    std::fs::remove_file(&path).unwrap();
    // Nothing changed: nothing is written again, over three autosave periods.
    assert!(!step_until(&mut harness, 7, |_| path.exists()), "autosave wrote an unchanged document again");
    let _ = std::fs::remove_dir_all(&dir);
}
