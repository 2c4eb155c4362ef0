//! Background synthesis: one named thread per job, the latest request wins.
//!
//! Requests are compared with `PartialEq`: an unchanged curve is never
//! re-synthesized, a changed one waits a short debounce, then starts, and a
//! job still running for the same curve is cancelled through its flag.

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::{Duration, Instant};

use tracery_core::{
    Control, Curve, DVec2, Exemplar, Mesh, PatternTopology, Region, SolveError, SynthesisError, Timings, extrude,
    synthesize,
};

use crate::document::CurveItem;

/// Wait after the last change before synthesizing, so a slider drag does
/// not start a job per frame.
pub const DEBOUNCE: Duration = Duration::from_millis(120);

/// What a job needs: the curve with its settings, and its exemplar.
#[derive(Clone, Debug)]
pub struct Request {
    /// The curve, its control points and settings.
    pub curve: CurveItem,
    /// The exemplar it uses.
    pub exemplar: Arc<Exemplar>,
}

impl PartialEq for Request {
    fn eq(&self, other: &Self) -> bool {
        // Exemplars are immutable once loaded: the same name and the same
        // geometry are the same exemplar.
        self.curve == other.curve && (Arc::ptr_eq(&self.exemplar, &other.exemplar) || self.exemplar == other.exemplar)
    }
}

/// A synthesized pattern, ready to draw and export.
#[derive(Debug)]
pub struct Output {
    /// The pattern in the plane, mm.
    pub region: Region,
    /// The extruded mesh, mm.
    pub mesh: Mesh,
    /// Top-face triangles, for drawing the pattern filled.
    pub fill: Vec<[DVec2; 3]>,
    /// The band's two edges along the curve.
    pub band_outline: Vec<Vec<DVec2>>,
    /// Seams between pieces, as short segments across the band.
    pub seams: Vec<[DVec2; 2]>,
    /// Topology counted on the final geometry.
    pub topology: PatternTopology,
    /// Pieces used.
    pub pieces: usize,
    /// Time per stage, ms.
    pub timings: Timings,
    /// Things to tell the person.
    pub warnings: Vec<String>,
}

/// Where a curve's synthesis stands.
#[derive(Debug, Default)]
pub enum JobState {
    /// Nothing asked yet.
    #[default]
    Idle,
    /// Running, with the fraction done.
    Running {
        /// Fraction done, 0 to 1.
        progress: f32,
    },
    /// Finished: a pattern, or a message saying why not.
    Done(Result<Arc<Output>, String>),
}

struct Job {
    /// The request the current state answers (or is working on).
    request: Option<Request>,
    generation: u64,
    cancel: Arc<AtomicBool>,
    progress: Arc<AtomicU32>,
    state: JobState,
    /// The last pattern, kept on screen while a new one is computed.
    last: Option<Arc<Output>>,
    pending: Option<(Request, Instant)>,
}

struct Message {
    id: u64,
    generation: u64,
    result: Result<Output, String>,
}

/// Runs synthesis off the UI thread.
pub struct Worker {
    jobs: HashMap<u64, Job>,
    sender: Sender<Message>,
    receiver: Receiver<Message>,
    next_generation: u64,
}

impl Default for Worker {
    fn default() -> Self {
        let (sender, receiver) = channel();
        Worker { jobs: HashMap::new(), sender, receiver, next_generation: 1 }
    }
}

impl Worker {
    /// Asks for `request` for curve `id`; nothing happens if it is what was last asked.
    pub fn want(&mut self, id: u64, request: Request, now: Instant) {
        let job = self.jobs.entry(id).or_insert_with(|| Job {
            request: None,
            generation: 0,
            cancel: Arc::new(AtomicBool::new(false)),
            progress: Arc::new(AtomicU32::new(0)),
            state: JobState::Idle,
            last: None,
            pending: None,
        });
        let same_as_pending = job.pending.as_ref().is_some_and(|(r, _)| *r == request);
        if job.request.as_ref() == Some(&request) {
            job.pending = None;
        } else if !same_as_pending {
            job.pending = Some((request, now));
        }
    }

    /// Forgets curves that no longer exist, cancelling their jobs.
    pub fn retain(&mut self, ids: &[u64]) {
        self.jobs.retain(|id, job| {
            let keep = ids.contains(id);
            if !keep {
                job.cancel.store(true, Ordering::Relaxed);
            }
            keep
        });
    }

    /// Collects finished jobs and starts debounced ones. Returns whether
    /// anything is still running or waiting (the UI should repaint).
    pub fn poll(&mut self, ctx: &egui::Context, now: Instant) -> bool {
        while let Ok(message) = self.receiver.try_recv() {
            if let Some(job) = self.jobs.get_mut(&message.id)
                && job.generation == message.generation
            {
                let result = message.result.map(Arc::new);
                if let Ok(output) = &result {
                    job.last = Some(output.clone());
                }
                job.state = JobState::Done(result);
            }
        }
        let mut busy = false;
        for (&id, job) in &mut self.jobs {
            if let Some((_, since)) = &job.pending {
                if now.duration_since(*since) >= DEBOUNCE {
                    let (request, _) = job.pending.take().unwrap_or_else(|| unreachable!());
                    job.cancel.store(true, Ordering::Relaxed);
                    job.cancel = Arc::new(AtomicBool::new(false));
                    job.progress = Arc::new(AtomicU32::new(0));
                    job.generation = self.next_generation;
                    self.next_generation += 1;
                    job.state = JobState::Running { progress: 0.0 };
                    job.request = Some(request.clone());
                    spawn(
                        id,
                        job.generation,
                        request,
                        job.cancel.clone(),
                        job.progress.clone(),
                        self.sender.clone(),
                        ctx.clone(),
                    );
                } else {
                    busy = true;
                }
            }
            if let JobState::Running { progress } = &mut job.state {
                *progress = f32::from_bits(job.progress.load(Ordering::Relaxed));
                busy = true;
            }
        }
        busy
    }

    /// The state of curve `id`'s synthesis.
    pub fn state(&self, id: u64) -> Option<&JobState> {
        self.jobs.get(&id).map(|j| &j.state)
    }

    /// The latest pattern for curve `id`, possibly from before the last change.
    pub fn output(&self, id: u64) -> Option<&Arc<Output>> {
        self.jobs.get(&id).and_then(|j| j.last.as_ref())
    }

    /// Whether curve `id` has a change not yet synthesized (waiting or running).
    pub fn is_stale(&self, id: u64) -> bool {
        self.jobs.get(&id).is_some_and(|j| j.pending.is_some() || matches!(j.state, JobState::Running { .. }))
    }
}

fn spawn(
    id: u64,
    generation: u64,
    request: Request,
    cancel: Arc<AtomicBool>,
    progress: Arc<AtomicU32>,
    sender: Sender<Message>,
    ctx: egui::Context,
) {
    let name = format!("tracery-synth-{id}");
    let started = std::thread::Builder::new().name(name).spawn(move || {
        let report = |f: f32| {
            progress.store(f.to_bits(), Ordering::Relaxed);
            ctx.request_repaint();
        };
        let control = Control { cancel: Some(&cancel), progress: Some(&report) };
        let result = run(&request, &control);
        if !matches!(result, Err(ref e) if e == CANCELLED) {
            let _ = sender.send(Message { id, generation, result });
        }
        ctx.request_repaint();
    });
    if let Err(e) = started {
        eprintln!("tracery: could not start a synthesis thread: {e}");
    }
}

const CANCELLED: &str = "cancelled";

/// One synthesis, as the app shows it.
pub fn run(request: &Request, control: &Control) -> Result<Output, String> {
    let item = &request.curve;
    let curve: Curve = item.curve().ok_or_else(|| "the curve is too short".to_string())?;
    let settings = &item.settings;
    let exemplar = &request.exemplar;
    let synthesis =
        synthesize(exemplar, &curve, &settings.request(exemplar.height()), control).map_err(|e| match e {
            SynthesisError::Solve(SolveError::Cancelled) => CANCELLED.to_string(),
            other => other.to_string(),
        })?;
    let start = Instant::now();
    let mesh = extrude(&synthesis.planar.region, settings.thickness_mm).map_err(|e| e.to_string())?;
    let mut timings = synthesis.timings;
    timings.mesh = start.elapsed().as_secs_f64() * 1e3;
    let count = mesh.vertices.len() / 2;
    let fill = mesh
        .triangles
        .iter()
        .filter(|t| t.iter().all(|&i| i as usize >= count))
        .map(|t| t.map(|i| DVec2::new(mesh.vertices[i as usize][0], mesh.vertices[i as usize][1])))
        .collect();
    let half = 0.5 * settings.band_mm;
    let steps = ((curve.length() / 1.0).ceil() as usize).clamp(2, 5000);
    let edge = |side: f64| -> Vec<DVec2> {
        (0..=steps).map(|k| curve.map(curve.length() * k as f64 / steps as f64, side * half)).collect()
    };
    let band_outline = vec![edge(1.0), edge(-1.0)];
    let scale = synthesis.scale_mm_per_unit;
    let seams =
        synthesis.band.seams.iter().map(|&u| [curve.map(u * scale, -half), curve.map(u * scale, half)]).collect();
    Ok(Output {
        region: synthesis.planar.region,
        mesh,
        fill,
        band_outline,
        seams,
        topology: synthesis.topology,
        pieces: synthesis.solution.pieces.len(),
        timings,
        warnings: synthesis.warnings,
    })
}
