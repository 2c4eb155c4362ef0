//! Background work, generic over what a mode computes: one named thread per
//! job, the latest request wins.
//!
//! Requests are compared with `PartialEq`: an unchanged item is never
//! computed again, a changed one waits a short debounce, then starts, and a
//! job still running for the same item is cancelled through its flag. The
//! worker wakes the UI through a callback, so it knows nothing of egui.

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::{Duration, Instant};

use tracery_core::control::{Control, Internal, MaybeCancelled};

/// Wait after the last change before computing, so a slider drag does not
/// start a job per frame.
pub const DEBOUNCE: Duration = Duration::from_millis(120);

/// Something a mode computes off the UI thread.
pub trait Job: Clone + PartialEq + Send + 'static {
    /// What it makes.
    type Output: Send + Sync + 'static;
    /// Why it failed; cancellations are dropped, not shown.
    type Error: std::error::Error + MaybeCancelled + From<Internal> + Send + Sync + 'static;
    /// Does the work, checking `control` for cancellation and reporting progress.
    fn run(&self, control: &Control) -> Result<Self::Output, Self::Error>;
}

/// Called from worker threads when there is something new to show.
pub type Waker = Arc<dyn Fn() + Send + Sync>;

/// Where an item's job stands.
#[derive(Debug)]
pub enum JobState<O, E> {
    /// Nothing asked yet.
    Idle,
    /// Running, with the fraction done.
    Running {
        /// Fraction done, 0 to 1.
        progress: f32,
    },
    /// Finished: an output, or why not.
    Done(Result<Arc<O>, Arc<E>>),
}

struct Slot<J: Job> {
    /// The request the current state answers (or is working on).
    request: Option<J>,
    generation: u64,
    cancel: Arc<AtomicBool>,
    progress: Arc<AtomicU32>,
    state: JobState<J::Output, J::Error>,
    /// The last output, kept on screen while a new one is computed.
    last: Option<Arc<J::Output>>,
    pending: Option<(J, Instant)>,
}

struct Message<J: Job> {
    id: u64,
    generation: u64,
    result: Result<J::Output, J::Error>,
}

/// Runs jobs off the UI thread, one slot per item id.
pub struct Worker<J: Job> {
    slots: HashMap<u64, Slot<J>>,
    sender: Sender<Message<J>>,
    receiver: Receiver<Message<J>>,
    next_generation: u64,
    wake: Waker,
    /// Wait after the last change before starting.
    debounce: Duration,
    /// Let a running job finish before starting the latest request, rather
    /// than cancelling it: for requests that change every frame, where
    /// cancelling would never let one finish.
    finish_first: bool,
}

impl<J: Job> Default for Worker<J> {
    fn default() -> Self {
        Worker::new(Arc::new(|| {}))
    }
}

impl<J: Job> Worker<J> {
    /// A worker that calls `wake` whenever progress or a result arrives.
    pub fn new(wake: Waker) -> Self {
        let (sender, receiver) = channel();
        Worker {
            slots: HashMap::new(),
            sender,
            receiver,
            next_generation: 1,
            wake,
            debounce: DEBOUNCE,
            finish_first: false,
        }
    }

    /// A worker for requests that change every frame (a stroke being
    /// drawn): no debounce, and a running job finishes before the latest
    /// request starts, so results keep coming while the input moves.
    pub fn live(wake: Waker) -> Self {
        Worker { debounce: Duration::ZERO, finish_first: true, ..Worker::new(wake) }
    }

    /// Replaces the wake-up callback (the app sets it once it has a context).
    pub fn set_waker(&mut self, wake: Waker) {
        self.wake = wake;
    }

    /// Asks for `request` for item `id`; nothing happens if it is what was last asked.
    pub fn want(&mut self, id: u64, request: J, now: Instant) {
        let slot = self.slots.entry(id).or_insert_with(|| Slot {
            request: None,
            generation: 0,
            cancel: Arc::new(AtomicBool::new(false)),
            progress: Arc::new(AtomicU32::new(0)),
            state: JobState::Idle,
            last: None,
            pending: None,
        });
        let same_as_pending = slot.pending.as_ref().is_some_and(|(r, _)| *r == request);
        if slot.request.as_ref() == Some(&request) {
            slot.pending = None;
        } else if !same_as_pending {
            slot.pending = Some((request, now));
        }
    }

    /// Forgets items that no longer exist, cancelling their jobs.
    pub fn retain(&mut self, ids: &[u64]) {
        self.slots.retain(|id, slot| {
            let keep = ids.contains(id);
            if !keep {
                slot.cancel.store(true, Ordering::Relaxed);
            }
            keep
        });
    }

    /// Collects finished jobs and starts debounced ones. Returns whether
    /// anything is still running or waiting (the UI should repaint).
    pub fn poll(&mut self, now: Instant) -> bool {
        while let Ok(message) = self.receiver.try_recv() {
            if let Some(slot) = self.slots.get_mut(&message.id)
                && slot.generation == message.generation
            {
                let result = message.result.map(Arc::new).map_err(Arc::new);
                if let Ok(output) = &result {
                    slot.last = Some(output.clone());
                }
                slot.state = JobState::Done(result);
            }
        }
        let mut busy = false;
        for (&id, slot) in &mut self.slots {
            if let Some((_, since)) = &slot.pending {
                let running = matches!(slot.state, JobState::Running { .. });
                if now.duration_since(*since) >= self.debounce && !(self.finish_first && running) {
                    let Some((request, _)) = slot.pending.take() else { continue };
                    slot.cancel.store(true, Ordering::Relaxed);
                    slot.cancel = Arc::new(AtomicBool::new(false));
                    slot.progress = Arc::new(AtomicU32::new(0));
                    slot.generation = self.next_generation;
                    self.next_generation += 1;
                    slot.state = JobState::Running { progress: 0.0 };
                    slot.request = Some(request.clone());
                    let task = Task {
                        id,
                        generation: slot.generation,
                        request,
                        cancel: slot.cancel.clone(),
                        progress: slot.progress.clone(),
                        sender: self.sender.clone(),
                        wake: self.wake.clone(),
                    };
                    if let Err(e) = task.spawn() {
                        slot.state = JobState::Idle;
                        eprintln!("tracery: could not start a worker thread: {e}");
                    }
                }
                busy = true;
            }
            if let JobState::Running { progress } = &mut slot.state {
                *progress = f32::from_bits(slot.progress.load(Ordering::Relaxed));
                busy = true;
            }
        }
        busy
    }

    /// The state of item `id`'s job.
    pub fn state(&self, id: u64) -> Option<&JobState<J::Output, J::Error>> {
        self.slots.get(&id).map(|s| &s.state)
    }

    /// The latest output for item `id`, possibly from before the last change.
    pub fn output(&self, id: u64) -> Option<&Arc<J::Output>> {
        self.slots.get(&id).and_then(|s| s.last.as_ref())
    }

    /// Whether item `id` has a change not yet computed (waiting or running).
    pub fn is_stale(&self, id: u64) -> bool {
        self.slots.get(&id).is_some_and(|s| s.pending.is_some() || matches!(s.state, JobState::Running { .. }))
    }
}

/// One job on its way to a thread.
struct Task<J: Job> {
    id: u64,
    generation: u64,
    request: J,
    cancel: Arc<AtomicBool>,
    progress: Arc<AtomicU32>,
    sender: Sender<Message<J>>,
    wake: Waker,
}

impl<J: Job> Task<J> {
    fn spawn(self) -> std::io::Result<()> {
        let name = format!("tracery-job-{}", self.id);
        std::thread::Builder::new().name(name).spawn(move || {
            let report = |f: f32| {
                self.progress.store(f.to_bits(), Ordering::Relaxed);
                (self.wake)();
            };
            let control = Control { cancel: Some(&self.cancel), progress: Some(&report) };
            // A panic is a fault in Tracery: it becomes this job's error, so
            // the item shows it and the app goes on, rather than the job
            // staying "running" for ever.
            let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.request.run(&control)))
                .unwrap_or_else(|payload| Err(Internal::from_panic(&*payload).into()));
            // A cancelled job has a newer one behind it: drop its result quietly.
            if !matches!(&result, Err(e) if e.is_cancelled()) {
                let _ = self.sender.send(Message { id: self.id, generation: self.generation, result });
            }
            (self.wake)();
        })?;
        Ok(())
    }
}
