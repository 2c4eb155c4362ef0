//! Progress and Ctrl+C on the command line: a bar on stderr fed from core's
//! [`Control`], and a cancel flag that Ctrl+C sets, the same flag the app's
//! Cancel sets on a job.

use std::io::IsTerminal as _;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use tracery_core::control::Control;

/// Set by Ctrl+C; every stage checks it through [`Control`].
static CANCEL: AtomicBool = AtomicBool::new(false);

/// Set while the outputs are being put in place: Ctrl+C then lets them finish.
static WRITING: AtomicBool = AtomicBool::new(false);

/// Set once "cancelled" has been said, so that it is said once.
static SAID: AtomicBool = AtomicBool::new(false);

/// How long a stage has to notice Ctrl+C before the process ends without
/// it: several stages (meshing, the print check) check seldom, and nothing
/// has been written while the work runs, so ending is safe.
const CANCEL_GRACE: Duration = Duration::from_millis(300);

/// Says the run was cancelled, once, and ends the process with 130.
pub fn exit_cancelled() -> ! {
    if !SAID.swap(true, Ordering::SeqCst) {
        eprintln!("tracery: {}", super::Interrupted);
    }
    std::process::exit(130)
}

/// Marks the outputs being put in place (see [`WRITING`]).
pub fn writing(on: bool) {
    WRITING.store(on, Ordering::SeqCst);
}

/// Ticks on the bar: a fraction done is shown in thousandths.
const BAR_TICKS: u64 = 1000;

/// How a run reports on stderr: a bar when stderr is a terminal and
/// `--quiet` is not given, nothing otherwise.
pub struct Progress {
    bar: ProgressBar,
    report: Box<dyn Fn(f32) + Sync>,
    quiet: bool,
}

impl Progress {
    /// Starts listening for Ctrl+C and shows a bar for `what` (the subcommand).
    pub fn start(what: &'static str, quiet: bool) -> Progress {
        // A second handler cannot be set (tests run several commands in one
        // process); the first one sets the same flag.
        let _ = ctrlc::set_handler(|| {
            if CANCEL.swap(true, Ordering::SeqCst) {
                // Asked twice: stop at once. Outputs are written nameless
                // until whole, so none is left half written.
                exit_cancelled();
            }
            std::thread::sleep(CANCEL_GRACE);
            if !WRITING.load(Ordering::SeqCst) {
                exit_cancelled();
            }
        });
        let draw = !quiet && std::io::stderr().is_terminal();
        let bar = if draw {
            let bar = ProgressBar::with_draw_target(Some(BAR_TICKS), ProgressDrawTarget::stderr());
            let style = ProgressStyle::with_template("{prefix} [{bar:30}] {percent:>3}%  {elapsed} (Ctrl+C cancels)")
                .unwrap_or_else(|_| ProgressStyle::default_bar())
                .progress_chars("=> ");
            bar.set_style(style);
            bar.set_prefix(what);
            bar.enable_steady_tick(Duration::from_millis(200));
            bar
        } else {
            ProgressBar::hidden()
        };
        let shown = bar.clone();
        let report = Box::new(move |fraction: f32| {
            // Stages report their own fractions from 0 to 1; the bar never goes back.
            let at = (f64::from(fraction.clamp(0.0, 1.0)) * BAR_TICKS as f64) as u64;
            if at > shown.position() {
                shown.set_position(at);
            }
        });
        Progress { bar, report, quiet }
    }

    /// The control to hand to core.
    pub fn control(&self) -> Control<'_> {
        Control { cancel: Some(&CANCEL), progress: Some(&*self.report) }
    }

    /// Whether the run was cancelled (checked again before files are put in place).
    pub fn is_cancelled(&self) -> bool {
        CANCEL.load(Ordering::Relaxed)
    }

    /// Whether only errors are to be printed.
    pub fn is_quiet(&self) -> bool {
        self.quiet
    }

    /// Clears the bar, before the summary is printed.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}
