//! Control of long work: cancellation, progress, and the one [`Cancelled`] error.
//!
//! Every stage that can run for long takes a [`Control`]. The caller sets the
//! cancel flag from another thread; the stage notices it at its next check
//! and returns an error that says it was cancelled (each mode's error type
//! has a variant holding [`Cancelled`], so callers can tell it apart from a
//! failure without comparing messages).

use std::sync::atomic::{AtomicBool, Ordering};

/// The work was stopped on request.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, thiserror::Error)]
#[error("cancelled")]
pub struct Cancelled;

/// A fault in Tracery itself (a panic caught in a worker), never the
/// person's input: said so, with what to report, and the app goes on.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "internal error: {0}. This is a fault in Tracery, not in your drawing: please report it with the project file (File > Save) and this message"
)]
pub struct Internal(pub String);

impl Internal {
    /// The message of a caught panic's payload.
    pub fn from_panic(payload: &(dyn std::any::Any + Send)) -> Internal {
        let text = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a worker stopped unexpectedly".into());
        Internal(text)
    }
}

/// Errors that can say whether they are a cancellation; the app drops
/// cancelled results silently and shows every other error.
pub trait MaybeCancelled {
    /// Whether this error only says the work was cancelled.
    fn is_cancelled(&self) -> bool;
}

impl MaybeCancelled for Cancelled {
    fn is_cancelled(&self) -> bool {
        true
    }
}

/// Cancellation and progress for a running stage.
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use tracery_core::control::{Cancelled, Control};
/// let flag = AtomicBool::new(true);
/// let control = Control { cancel: Some(&flag), ..Control::default() };
/// assert_eq!(control.check(), Err(Cancelled));
/// assert_eq!(Control::default().check(), Ok(()));
/// ```
#[derive(Clone, Copy, Default)]
pub struct Control<'a> {
    /// Set to stop the work; it then returns an error holding [`Cancelled`].
    pub cancel: Option<&'a AtomicBool>,
    /// Called with the fraction done, from 0 to 1, possibly from several threads.
    pub progress: Option<&'a (dyn Fn(f32) + Sync)>,
}

impl Control<'_> {
    /// Whether the work has been asked to stop.
    pub fn is_cancelled(&self) -> bool {
        self.cancel.is_some_and(|c| c.load(Ordering::Relaxed))
    }

    /// `Err(Cancelled)` once the work has been asked to stop.
    pub fn check(&self) -> Result<(), Cancelled> {
        if self.is_cancelled() { Err(Cancelled) } else { Ok(()) }
    }

    /// Reports the fraction done, if anyone listens.
    pub fn report(&self, fraction: f32) {
        if let Some(progress) = self.progress {
            progress(fraction.clamp(0.0, 1.0));
        }
    }

    /// The same cancel flag without progress reports (for inner searches
    /// whose progress would confuse the caller's bar).
    pub fn silent(&self) -> Self {
        Control { progress: None, ..*self }
    }
}

/// A cap on the states a search may hold, so that a hopeless search ends
/// with an error rather than by exhausting memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateCap {
    /// Most states held at once.
    pub max_states: usize,
    /// Bytes one state takes, with its share of the search's tables.
    pub bytes_per_state: usize,
}

impl StateCap {
    /// The memory the cap stands for, in megabytes.
    ///
    /// ```
    /// use tracery_core::control::StateCap;
    /// assert_eq!(StateCap { max_states: 1 << 20, bytes_per_state: 96 }.megabytes(), 96);
    /// ```
    pub fn megabytes(&self) -> usize {
        self.max_states.saturating_mul(self.bytes_per_state) / (1 << 20)
    }
}
