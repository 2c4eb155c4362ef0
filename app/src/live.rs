//! The pattern growing under the pointer while a stroke is drawn.
//!
//! Each frame of the stroke asks the live worker for the pattern along the
//! stroke so far. Jobs share one [`Growing`] per stroke, which keeps the
//! pieces already laid and only extends them, and the worker lets a running
//! job finish before starting the latest stroke (see [`Worker::live`]), so
//! results keep arriving while the pointer moves. When the stroke ends, the
//! curve's own job solves it from scratch, as any curve.
//!
//! [`Worker::live`]: crate::worker::Worker::live

use std::sync::{Arc, Mutex};

use tracery_core::control::Control;
use tracery_core::curve::Curve;
use tracery_core::product::Fact;
use tracery_core::vector_brush::{Exemplar, Growing, Settings, SynthesisError};
use tracery_core::{DVec2, Product};

use crate::document::SMOOTHING_SPACING_MM;
use crate::tools::draw::{CONTROL_SPACING_MM, long_enough, stroke_to_control_points};
use crate::worker::Job;

/// The worker slot of the stroke being drawn.
pub const LIVE_ID: u64 = u64::MAX;

/// What one stroke's jobs share: the growing pattern.
pub type Session = Arc<Mutex<Option<Growing>>>;

/// The pattern along a stroke as drawn so far.
#[derive(Clone)]
pub struct LiveJob {
    /// The pointer's path so far, mm.
    pub raw: Arc<Vec<DVec2>>,
    /// The exemplar.
    pub exemplar: Arc<Exemplar>,
    /// The settings new curves take.
    pub settings: Settings,
    /// The stroke's growing pattern, shared by its jobs.
    pub session: Session,
}

impl std::fmt::Debug for LiveJob {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "LiveJob({} samples)", self.raw.len())
    }
}

impl PartialEq for LiveJob {
    fn eq(&self, other: &Self) -> bool {
        // A stroke only grows: its length and last sample tell it apart.
        self.raw.len() == other.raw.len()
            && self.raw.last() == other.raw.last()
            && self.settings == other.settings
            && Arc::ptr_eq(&self.exemplar, &other.exemplar)
            && Arc::ptr_eq(&self.session, &other.session)
    }
}

impl LiveJob {
    /// Whether the stroke so far is long enough to carry a pattern (cheap:
    /// the UI asks every frame).
    pub fn long_enough(raw: &[DVec2]) -> bool {
        long_enough(raw, CONTROL_SPACING_MM)
    }

    /// The curve the stroke so far becomes (open, smoothed as a finished
    /// curve is), or `None` while it is too short.
    pub fn curve(raw: &[DVec2]) -> Option<Curve> {
        let (points, _) = stroke_to_control_points(raw, CONTROL_SPACING_MM, 0.0)?;
        Curve::from_stroke(&points, false, SMOOTHING_SPACING_MM).ok()
    }
}

impl Job for LiveJob {
    type Output = Product;
    type Error = SynthesisError;

    fn run(&self, control: &Control) -> Result<Product, SynthesisError> {
        let curve =
            LiveJob::curve(&self.raw).ok_or(SynthesisError::Curve(tracery_core::curve::CurveError::TooShort))?;
        // Jobs of one stroke run one after another: the lock is never contended.
        let mut session = self.session.lock().unwrap_or_else(|e| e.into_inner());
        if session.is_none() {
            *session = Some(Growing::new(&self.exemplar, &self.settings)?);
        }
        let growing = session.as_mut().expect("made above");
        let mut product = growing.grow(&curve, control)?;
        product.facts.push("stroke_samples", Fact::Count(self.raw.len()));
        product.facts.push("pieces_kept", Fact::Count(growing.kept()));
        Ok(product)
    }
}
