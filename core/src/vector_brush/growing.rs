//! A pattern that grows under the pointer while a stroke is drawn.

use super::pipeline::{analyse, laid_out};
use super::product::to_product;
use super::{Exemplar, PieceSet, Settings, SynthesisError};
use crate::Product;
use crate::control::Control;
use crate::curve::{Along, Curve};

/// How many of the last laid pieces are laid again when the stroke grows:
/// the stroke's smoothing still moves its last millimetres, and the pattern
/// needs room to end well.
const RELAID_PIECES: usize = 2;

/// A vector-brush pattern along a stroke that is still being drawn.
///
/// The exemplar is analysed once. Each time the stroke grows, the pieces
/// already laid are kept but for the last few, and the search only extends
/// them: its work grows with what was added, not with the whole stroke.
/// Where the kept pieces cannot be extended to meet the targets, the search
/// starts again from nothing. Its products are previews: triangles to draw,
/// no solid (the finished stroke is made as any curve is).
///
/// ```
/// use tracery_core::control::Control;
/// use tracery_core::curve::Curve;
/// use tracery_core::vector_brush::{Growing, Settings, builtin};
/// let mut growing = Growing::new(&builtin("vine").unwrap(), &Settings::default()).unwrap();
/// let short = growing.grow(&Curve::line(60.0).unwrap(), &Control::default()).unwrap();
/// let long = growing.grow(&Curve::line(90.0).unwrap(), &Control::default()).unwrap();
/// assert_eq!(long.topology.components, 1);
/// assert!(long.region_mm.area() > short.region_mm.area());
/// assert!(growing.kept() > 0, "the pieces laid along the first 60 mm were kept");
/// ```
pub struct Growing {
    exemplar: Exemplar,
    settings: Settings,
    scale: f64,
    set: PieceSet,
    laid: Vec<usize>,
    kept: usize,
}

impl Growing {
    /// Analyses `exemplar` for `settings` (the best pattern: alternatives
    /// are for finished curves).
    pub fn new(exemplar: &Exemplar, settings: &Settings) -> Result<Self, SynthesisError> {
        settings.validate()?;
        let mut settings = settings.clone();
        settings.alternative = 0;
        let scale = settings.mm_per_unit(exemplar.height());
        let (set, _) = analyse(exemplar, &settings, scale, None)?;
        Ok(Growing { exemplar: exemplar.clone(), settings, scale, set, laid: Vec::new(), kept: 0 })
    }

    /// The pattern along `curve`, the stroke as drawn so far.
    pub fn grow(&mut self, curve: &Curve, control: &Control) -> Result<Product, SynthesisError> {
        let length = curve.length() / self.scale;
        let widest = self.set.pieces.iter().map(|p| p.width).fold(0.0, f64::max);
        let mut prefix = Vec::new();
        let mut reach = 0.0;
        for &p in self.laid.iter().take(self.laid.len().saturating_sub(RELAID_PIECES)) {
            reach += self.set.pieces[p].width;
            // Leave at least a piece's room at the end.
            if reach > length - widest {
                break;
            }
            prefix.push(p);
        }
        let mut all = laid_out(
            &self.set,
            &self.exemplar,
            curve,
            &self.settings,
            self.scale,
            1,
            false,
            &prefix,
            0,
            Default::default(),
            control,
        )?;
        let synthesis = all.pop().expect("one pattern");
        let pieces = &synthesis.solution.pieces;
        self.kept = prefix.iter().zip(pieces).take_while(|(a, b)| a == b).count();
        self.laid = pieces.clone();
        // A preview: drawn, not printed, so no solid.
        to_product(synthesis, &Along::Curve(curve.clone()), &self.settings, false)
    }

    /// How many pieces the last [`Growing::grow`] kept from the one before.
    pub fn kept(&self) -> usize {
        self.kept
    }
}
