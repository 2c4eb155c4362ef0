//! Thickening thin features to the nozzle's width.

use super::Flaw;
use crate::geom::{Polygon, Region, disc, union};

/// Sides of the discs added: the chord error is under 1% of the radius.
const DISC_SIDES: usize = 24;
/// Discs are a little larger than half the minimum width, so that the
/// polygon's chords still leave the full width.
const DISC_MARGIN: f64 = 1.02;

/// `region` with every thin feature grown to `min_width_mm`: a disc of that
/// diameter is added at the centre of each narrow cross-section, so the
/// feature becomes a stroke at least that wide along its middle.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::print::{PrintSettings, check, thicken};
/// let bar = vec![DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0), DVec2::new(10.0, 0.2), DVec2::new(0.0, 0.2)];
/// let region = Region::new(vec![Polygon { outer: bar, holes: vec![] }]);
/// let settings = PrintSettings::default();
/// let found = check(&region, &[], &settings, 2.0);
/// let thick = thicken(&region, &found.thin_features, 0.4);
/// assert!(check(&thick, &[], &settings, 2.0).thin_features.is_empty());
/// ```
pub fn thicken(region: &Region, thin: &[Flaw], min_width_mm: f64) -> Region {
    let radius = 0.5 * min_width_mm * DISC_MARGIN;
    let discs: Vec<Polygon> =
        thin.iter().flat_map(|f| f.discs_mm.iter()).map(|&(centre, _)| disc(centre, radius, DISC_SIDES)).collect();
    if discs.is_empty() {
        return region.clone();
    }
    union(&[region, &Region::new(discs)])
}
