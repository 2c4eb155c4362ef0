//! Helpers for driving the app in tests.
#![allow(dead_code)]

use std::time::{Duration, Instant};

use egui_kittest::Harness;
use tracery::TraceryApp;
use tracery::worker::JobState;

/// Steps the UI until every pattern is done (the worker runs on its own threads).
pub fn settle(harness: &mut Harness<'static, TraceryApp>) {
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        harness.step();
        let app = harness.state();
        let done = !app.busy() && app.doc.curves.iter().all(|c| matches!(app.job_state(c.id), Some(JobState::Done(_))));
        if done || Instant::now() > deadline {
            break;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    harness.step();
}

/// Steps until the curves on the model are done.
pub fn settle_model(harness: &mut Harness<'static, TraceryApp>) {
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        harness.step();
        let app = harness.state();
        let done = !app.busy()
            && app.doc.model.drawn_curves().all(|c| matches!(app.surface_job_state(c.id), Some(JobState::Done(_))));
        if done || Instant::now() > deadline {
            break;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    harness.step();
}
