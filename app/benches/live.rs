//! How far the pattern lags behind the pointer while a stroke is drawn.
//!
//! A recorded 300 mm stroke (a hand-drawn wave, sampled every 0.5 mm) is
//! replayed through the app's live worker at drawing speed, 60 frames a
//! second. For every frame, the lag is the time from the pointer reaching
//! that frame's point to the first result whose pattern covers it.
//!
//! ```sh
//! cargo bench -p tracery --bench live [-- --speed MM_PER_S] [--exemplar NAME|FILE.svg]
//! ```
//! Prints p50, p95 and the worst lag, with the growing pattern (pieces kept)
//! and, for comparison, restarting every job from nothing.

use std::sync::Arc;
use std::time::{Duration, Instant};

use tracery::live::{LIVE_ID, LiveJob, Session};
use tracery::worker::{JobState, Worker};
use tracery_core::DVec2;
use tracery_core::product::Fact;
use tracery_core::vector_brush::{Exemplar, LoadOptions, Settings, builtin};

const FRAME: Duration = Duration::from_micros(16_667);

/// The recorded stroke: a wave with a hand's wobble, 300 mm long, a point every 0.5 mm.
fn recorded_stroke() -> Vec<DVec2> {
    let mut points = vec![DVec2::ZERO];
    let mut x = 0.0;
    let mut length = 0.0;
    while length < 300.0 {
        x += 0.2;
        let p = DVec2::new(x, 18.0 * (x / 32.0).sin() + 0.3 * (x * 1.7).sin());
        let step = p.distance(*points.last().unwrap());
        if step >= 0.5 {
            length += step;
            points.push(p);
        }
    }
    points
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

/// Replays the stroke; returns the lag of every frame, ms, and the pieces kept per result.
fn replay(exemplar: &str, speed_mm_s: f64, reuse: bool) -> (Vec<f64>, Vec<usize>) {
    let stroke = recorded_stroke();
    let exemplar = Arc::new(builtin(exemplar).unwrap_or_else(|_| {
        Exemplar::from_svg_file(std::path::Path::new(exemplar), &LoadOptions::default()).expect("an exemplar")
    }));
    let settings = Settings::default();
    let mut worker: Worker<LiveJob> = Worker::live(Arc::new(|| {}));
    let session = Session::default();
    let mm_per_frame = speed_mm_s * FRAME.as_secs_f64();
    let samples_per_frame = (mm_per_frame / 0.5).max(1.0) as usize;
    let frames = stroke.len().div_ceil(samples_per_frame);
    let start = Instant::now();
    // When each frame's pointer position was drawn, and how many samples it had.
    let mut drawn: Vec<(Instant, usize)> = Vec::new();
    let mut lags: Vec<Option<f64>> = vec![None; frames];
    let mut kept = Vec::new();
    let mut last_output: Option<*const tracery_core::Product> = None;
    let mut frame = 0;
    loop {
        let now = Instant::now();
        if frame < frames && now >= start + FRAME * frame as u32 {
            let count = ((frame + 1) * samples_per_frame).min(stroke.len());
            drawn.push((now, count));
            if LiveJob::long_enough(&stroke[..count]) {
                let session = if reuse { session.clone() } else { Session::default() };
                let job = LiveJob {
                    raw: Arc::new(stroke[..count].to_vec()),
                    exemplar: exemplar.clone(),
                    settings: settings.clone(),
                    session,
                };
                worker.want(LIVE_ID, job, now);
            } else {
                lags[frame] = Some(0.0);
            }
            frame += 1;
        }
        worker.poll(Instant::now());
        if let Some(output) = worker.output(LIVE_ID)
            && last_output != Some(Arc::as_ptr(output))
        {
            last_output = Some(Arc::as_ptr(output));
            let arrived = Instant::now();
            let covered = match output.facts.get("stroke_samples") {
                Some(Fact::Count(n)) => *n,
                _ => 0,
            };
            if let Some(Fact::Count(k)) = output.facts.get("pieces_kept") {
                kept.push(*k);
            }
            for (f, (at, count)) in drawn.iter().enumerate() {
                if lags[f].is_none() && *count <= covered {
                    lags[f] = Some((arrived - *at).as_secs_f64() * 1e3);
                }
            }
        }
        if let Some(JobState::Done(Err(e))) = worker.state(LIVE_ID) {
            println!(
                "| {} | {} | no pattern: {e} | | | |",
                exemplar.name,
                if reuse { "growing" } else { "restarting" }
            );
            return (Vec::new(), Vec::new());
        }
        if frame >= frames && lags.iter().all(Option::is_some) {
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(60), "the replay did not finish");
        std::thread::sleep(Duration::from_micros(500));
    }
    (lags.into_iter().flatten().collect(), kept)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let mut speed = 150.0;
    let mut exemplars = vec!["lace".to_string(), "vine".to_string(), "braid".to_string()];
    while let Some(a) = args.next() {
        match a.as_str() {
            "--speed" => speed = args.next().and_then(|s| s.parse().ok()).expect("--speed MM_PER_S"),
            "--exemplar" => exemplars = vec![args.next().expect("--exemplar NAME")],
            _ => {} // cargo bench passes --bench
        }
    }
    println!("A 300 mm stroke drawn at {speed} mm/s, 60 frames/s; lag from the pointer to a pattern covering it:");
    println!("| exemplar | jobs | p50 ms | p95 ms | worst ms | mean pieces kept |");
    println!("|---|---|---|---|---|---|");
    for name in &exemplars {
        for reuse in [true, false] {
            let (mut lags, kept) = replay(name, speed, reuse);
            if lags.is_empty() {
                continue;
            }
            lags.sort_by(f64::total_cmp);
            let mean_kept = kept.iter().sum::<usize>() as f64 / kept.len().max(1) as f64;
            println!(
                "| {name} | {} | {:.1} | {:.1} | {:.1} | {:.0} |",
                if reuse { "growing" } else { "restarting" },
                percentile(&lags, 0.5),
                percentile(&lags, 0.95),
                lags.last().copied().unwrap_or(0.0),
                mean_kept
            );
        }
    }
}
