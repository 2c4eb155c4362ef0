//! Strokes as hands draw them, for tests and sweeps: pointer samples along
//! a loop or an open stroke, sparse (a fast hand, 10 to 20 samples a loop)
//! or dense (a slow hand, a sample every half millimetre), wobbling off the
//! shape meant as a hand does. [`Curve::from_stroke`] smooths them as the
//! app smooths what the pointer gives.
//!
//! Generated curves (`circle:`, the frames) are exact; what people draw is
//! not, and a rule that holds on the first can fail on the second.
//!
//! ```
//! use tracery_core::curve::{DrawnStroke, Hand, StrokeShape};
//! let stroke = DrawnStroke::new(StrokeShape::Ellipse { width_mm: 52.0, height_mm: 32.0 }, Hand::Fast, 7);
//! assert!((10..=20).contains(&stroke.samples_mm.len()));
//! let curve = stroke.curve().unwrap();
//! assert!(curve.is_closed());
//! // An ellipse 52 × 32 mm is about 133 mm round.
//! assert!((curve.length() - 133.0).abs() < 6.0, "{}", curve.length());
//! ```

use glam::DVec2;

use super::{Curve, CurveError};
use crate::random::SplitMix64;

/// Spacing of the points [`DrawnStroke::curve`] smooths a stroke to, mm:
/// the app's own.
pub const STROKE_SPACING_MM: f64 = 0.5;

/// How far a fast hand's samples wander off the shape meant, mm (standard
/// deviation, roughly).
const FAST_JITTER_MM: f64 = 0.35;

/// How far a slow hand's samples wander off the shape meant, mm: a slow
/// hand is steadier, but its samples are close, so even a little jitter
/// turns sharply from one to the next.
const SLOW_JITTER_MM: f64 = 0.08;

/// Spacing of a slow hand's samples, mm.
const SLOW_SAMPLE_MM: f64 = 0.5;

/// A shape a person means to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum StrokeShape {
    /// A loop: a circle of this diameter.
    Circle {
        /// Across, mm.
        diameter_mm: f64,
    },
    /// A loop: an ellipse.
    Ellipse {
        /// Along x, mm.
        width_mm: f64,
        /// Along y, mm.
        height_mm: f64,
    },
    /// A loop: a heart this wide, with a point and a dip.
    Heart {
        /// Across, mm.
        width_mm: f64,
    },
    /// A loop: a bean (an ellipse bent so one long side is hollow).
    Bean {
        /// End to end, mm.
        length_mm: f64,
    },
    /// A loop: a drop, round at one end and pointed at the other.
    Drop {
        /// End to end, mm.
        length_mm: f64,
    },
    /// Open: an S, two arcs turning opposite ways.
    SCurve {
        /// End to end, mm.
        length_mm: f64,
    },
    /// Open: an arc of a circle of this radius, turning 200°.
    Arc {
        /// Of the circle, mm.
        radius_mm: f64,
    },
    /// Open: a spiral winding out from this inner radius, one turn and a half.
    Spiral {
        /// Where it starts, mm.
        inner_radius_mm: f64,
    },
    /// Open: a zigzag of four legs, each this long, turning 70° at its
    /// corners: corners a person means.
    Zigzag {
        /// Each leg, mm.
        leg_mm: f64,
    },
}

impl StrokeShape {
    /// Whether the shape is a loop.
    pub fn is_loop(&self) -> bool {
        matches!(
            self,
            Self::Circle { .. } | Self::Ellipse { .. } | Self::Heart { .. } | Self::Bean { .. } | Self::Drop { .. }
        )
    }

    /// A short name: `ellipse52x32`, `zigzag25`.
    pub fn name(&self) -> String {
        match *self {
            Self::Circle { diameter_mm } => format!("circle{diameter_mm}"),
            Self::Ellipse { width_mm, height_mm } => format!("ellipse{width_mm}x{height_mm}"),
            Self::Heart { width_mm } => format!("heart{width_mm}"),
            Self::Bean { length_mm } => format!("bean{length_mm}"),
            Self::Drop { length_mm } => format!("drop{length_mm}"),
            Self::SCurve { length_mm } => format!("s{length_mm}"),
            Self::Arc { radius_mm } => format!("arc{radius_mm}"),
            Self::Spiral { inner_radius_mm } => format!("spiral{inner_radius_mm}"),
            Self::Zigzag { leg_mm } => format!("zigzag{leg_mm}"),
        }
    }

    /// The point at `t` in `[0, 1]` of the shape meant (a loop goes round
    /// once, counter-clockwise, `t = 1` back at the start), mm.
    pub fn point(&self, t: f64) -> DVec2 {
        use std::f64::consts::{PI, TAU};
        let a = TAU * t;
        match *self {
            Self::Circle { diameter_mm } => DVec2::from_angle(a) * 0.5 * diameter_mm,
            Self::Ellipse { width_mm, height_mm } => DVec2::new(0.5 * width_mm * a.cos(), 0.5 * height_mm * a.sin()),
            Self::Heart { width_mm } => {
                // The classic heart curve, 32 units wide; its point at the
                // bottom (t = 0.5 after the turn below), its dip at the top.
                let s = width_mm / 32.0;
                let a = a + PI;
                DVec2::new(
                    -16.0 * a.sin().powi(3),
                    13.0 * a.cos() - 5.0 * (2.0 * a).cos() - 2.0 * (3.0 * a).cos() - (4.0 * a).cos(),
                ) * s
            }
            Self::Bean { length_mm } => {
                let (half_length, half_width) = (0.5 * length_mm, 0.2 * length_mm);
                let x = half_length * a.cos();
                // The ellipse bent along a parabola: the top side dips in.
                DVec2::new(x, half_width * a.sin() - 0.55 * half_width * (1.0 - (x / half_length).powi(2)))
            }
            Self::Drop { length_mm } => {
                // Round at x < 0, pointed at x = +length/2.
                let half = 0.5 * length_mm;
                DVec2::new(half * a.cos(), 0.62 * half * a.sin() * (0.5 * (1.0 - a.cos())).sqrt())
            }
            Self::SCurve { length_mm } => DVec2::new(length_mm * t, 0.22 * length_mm * (TAU * t).sin()),
            Self::Arc { radius_mm } => DVec2::from_angle(200f64.to_radians() * t - 0.5 * PI) * radius_mm,
            Self::Spiral { inner_radius_mm } => {
                let turn = 1.5 * TAU * t;
                DVec2::from_angle(turn) * (inner_radius_mm + 2.2 * inner_radius_mm * t)
            }
            Self::Zigzag { leg_mm } => {
                let legs = 4.0;
                let k = (t * legs).floor().min(legs - 1.0);
                let along = t * legs - k;
                let corner = |j: f64| {
                    // Legs alternate 35° above and below the x axis: 70° turns.
                    let step = DVec2::from_angle(35f64.to_radians()) * leg_mm;
                    let x = step.x * j;
                    let y = if (j as i64) % 2 == 0 { 0.0 } else { step.y };
                    DVec2::new(x, y)
                };
                corner(k).lerp(corner(k + 1.0), along)
            }
        }
    }

    /// The shape meant, as a fine polyline (a loop not repeating its start).
    fn dense(&self) -> Vec<DVec2> {
        let n = 4000;
        let last = if self.is_loop() { n - 1 } else { n };
        (0..=last).map(|k| self.point(k as f64 / n as f64)).collect()
    }
}

/// How a stroke is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Hand {
    /// Quickly: 10 to 20 samples a loop (an open stroke, one every 5 to 9
    /// mm), unevenly spaced.
    Fast,
    /// Slowly: a sample every half millimetre.
    Slow,
}

/// Pointer samples of a stroke, as a person's hand gives them.
#[derive(Clone, Debug)]
pub struct DrawnStroke {
    /// What was meant.
    pub shape: StrokeShape,
    /// How it was drawn.
    pub hand: Hand,
    /// The pointer samples, mm (a loop does not repeat its start).
    pub samples_mm: Vec<DVec2>,
    /// Whether it is a loop.
    pub closed: bool,
}

impl DrawnStroke {
    /// The samples of `shape` as `hand` draws it, `seed` choosing the
    /// wobble: the same seed, the same samples. Loops are drawn
    /// counter-clockwise; [`DrawnStroke::reversed`] draws them the other way.
    pub fn new(shape: StrokeShape, hand: Hand, seed: u64) -> DrawnStroke {
        let mut random = SplitMix64::new(seed ^ 0x5eed_0fa4_a4d0);
        let closed = shape.is_loop();
        let dense = shape.dense();
        let meant = Curve::from_polyline(&dense, closed).expect("the shapes are finite and long");
        let length = meant.length();
        let mut gauss = move || {
            // The sum of three uniforms: near enough a normal for a wobble.
            (0..3).map(|_| random.next_unit() - 0.5).sum::<f64>() * 2.0
        };
        // Where along the shape each sample lies.
        let at: Vec<f64> = match hand {
            Hand::Fast => {
                let count = if closed {
                    10 + (gauss().abs() * 4.0) as usize % 11
                } else {
                    ((length / (7.0 + gauss())).round() as usize).max(4)
                };
                let step = length / if closed { count as f64 } else { (count - 1) as f64 };
                (0..count).map(|k| (k as f64 * step + 0.3 * step * gauss()).clamp(0.0, length)).collect()
            }
            Hand::Slow => {
                let count = (length / SLOW_SAMPLE_MM).round() as usize;
                let step = length / if closed { count as f64 } else { (count - 1) as f64 };
                (0..count).map(|k| k as f64 * step).collect()
            }
        };
        let mut at = at;
        at.sort_by(f64::total_cmp);
        at.dedup_by(|a, b| (*a - *b).abs() < 1e-6);
        // A slow hand wobbles smoothly; a fast one from sample to sample.
        let (jitter, phase) = match hand {
            Hand::Fast => (FAST_JITTER_MM, 0.0),
            Hand::Slow => (SLOW_JITTER_MM, gauss() * 10.0),
        };
        let samples_mm = at
            .iter()
            .map(|&u| {
                let off = match hand {
                    Hand::Fast => gauss() * jitter,
                    Hand::Slow => jitter * ((u * 0.7 + phase).sin() + 0.5 * gauss()),
                };
                meant.point(u) + meant.normal(u) * off
            })
            .collect();
        DrawnStroke { shape, hand, samples_mm, closed }
    }

    /// The same stroke drawn the other way round.
    pub fn reversed(&self) -> DrawnStroke {
        let mut samples_mm = self.samples_mm.clone();
        samples_mm.reverse();
        DrawnStroke { samples_mm, ..self.clone() }
    }

    /// A name for reports: `ellipse52x32-fast`.
    pub fn name(&self) -> String {
        let hand = match self.hand {
            Hand::Fast => "fast",
            Hand::Slow => "slow",
        };
        format!("{}-{hand}", self.shape.name())
    }

    /// The curve the app makes of these samples ([`Curve::from_stroke`],
    /// every [`STROKE_SPACING_MM`]).
    pub fn curve(&self) -> Result<Curve, CurveError> {
        Curve::from_stroke(&self.samples_mm, self.closed, STROKE_SPACING_MM)
    }

    /// The shapes of [`DrawnStroke::set`]: loops of 8 to 60 mm and open
    /// strokes.
    pub fn shapes() -> Vec<StrokeShape> {
        use StrokeShape::*;
        vec![
            Circle { diameter_mm: 8.0 },
            Circle { diameter_mm: 20.0 },
            Circle { diameter_mm: 45.0 },
            Ellipse { width_mm: 52.0, height_mm: 32.0 },
            Ellipse { width_mm: 60.0, height_mm: 24.0 },
            Heart { width_mm: 40.0 },
            Bean { length_mm: 55.0 },
            Drop { length_mm: 40.0 },
            SCurve { length_mm: 90.0 },
            Arc { radius_mm: 25.0 },
            Spiral { inner_radius_mm: 10.0 },
            Zigzag { leg_mm: 30.0 },
        ]
    }

    /// Every shape of [`DrawnStroke::shapes`], by a fast and by a slow hand.
    pub fn set(seed: u64) -> Vec<DrawnStroke> {
        let mut out = Vec::new();
        for (k, shape) in Self::shapes().into_iter().enumerate() {
            for hand in [Hand::Fast, Hand::Slow] {
                out.push(DrawnStroke::new(shape, hand, seed.wrapping_add(k as u64 * 31 + hand as u64)));
            }
        }
        out
    }
}
