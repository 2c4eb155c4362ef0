//! Choosing where to cut an exemplar (section 5 of the paper).

use serde::{Deserialize, Serialize};

use super::{Exemplar, SliceError, portals_at};
use crate::geom::Region;

/// How cut lines are placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[non_exhaustive]
pub enum SlicingMode {
    /// `cuts` lines evenly spaced along the exemplar's width (section 5.1).
    Uniform {
        /// Number of cut lines; the exemplar becomes `cuts + 1` pieces.
        cuts: usize,
    },
    /// One cut midway between successive topology events (section 5.2).
    Topology,
}

/// Options for cutting an exemplar into pieces.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct SliceOptions {
    /// Where cuts go.
    pub mode: SlicingMode,
    /// Cuts whose narrowest portal is thinner than this, in exemplar units,
    /// are dropped (section 5.2.1). Zero keeps every cut.
    pub min_portal: f64,
    /// Topology events within this fraction of the exemplar's height from
    /// the first event of a group join that group (section 5.2.2).
    pub event_grouping: f64,
    /// Most pieces allowed.
    pub max_pieces: usize,
}

impl Default for SliceOptions {
    fn default() -> Self {
        SliceOptions { mode: SlicingMode::Topology, min_portal: 0.0, event_grouping: 0.1, max_pieces: 64 }
    }
}

/// Most portals on one cut line. Not a limit of the descriptors (their
/// [`PortalId`](super::descriptor::PortalId)s hold four times this, what
/// joining two pieces numbers) but a guard against drawings no search could
/// handle: the tallest rectangles people make cross their first pass's
/// strips about a hundred times.
pub const MAX_PORTALS: usize = 4096;

/// The `u` positions where the topology of vertical cross-sections changes:
/// the local extrema of `u` along the boundary, where an interval of the cut
/// line begins, ends, splits or merges (the nodes of the Reeb graph of `u`).
///
/// This is the exact vector form of the paper's raster column scan, so it has
/// no aliasing to filter.
pub fn topology_events(region: &Region) -> Vec<f64> {
    let mut events = Vec::new();
    for ring in region.rings() {
        // Drop runs of equal u so a vertical edge counts as one turning point.
        let mut xs: Vec<f64> = Vec::with_capacity(ring.len());
        for p in ring {
            if xs.last() != Some(&p.x) {
                xs.push(p.x);
            }
        }
        while xs.len() > 1 && xs.first() == xs.last() {
            xs.pop();
        }
        let n = xs.len();
        if n < 2 {
            continue;
        }
        for i in 0..n {
            let prev = xs[(i + n - 1) % n];
            let next = xs[(i + 1) % n];
            let x = xs[i];
            if (prev < x && next < x) || (prev > x && next > x) {
                events.push(x);
            }
        }
    }
    events.sort_by(f64::total_cmp);
    events
}

/// Groups sorted events that lie within `distance` of their group's first
/// event and returns the mean of each group.
///
/// The paper chains events (each within the distance of the *previous* one);
/// on a lace with evenly spaced holes that chain swallows the whole exemplar
/// into one group, so a group here spans at most `distance`.
fn group_events(events: &[f64], distance: f64) -> Vec<f64> {
    let mut groups: Vec<(f64, f64, usize)> = Vec::new();
    for &e in events {
        match groups.last_mut() {
            Some((first, sum, count)) if e - *first <= distance => {
                *sum += e;
                *count += 1;
            }
            _ => groups.push((e, e, 1)),
        }
    }
    groups.into_iter().map(|(_, sum, count)| sum / count as f64).collect()
}

/// Moves `cut` off any vertex `u` so that cut lines cross edges cleanly.
fn avoid_vertices(cut: f64, sorted_xs: &[f64], tolerance: f64) -> f64 {
    let mut c = cut;
    for _ in 0..64 {
        let i = sorted_xs.partition_point(|&x| x < c - tolerance);
        match sorted_xs.get(i) {
            Some(&x) if (x - c).abs() <= tolerance => c = x + 2.0 * tolerance,
            _ => break,
        }
    }
    c
}

/// The `u` positions of the cut lines for `exemplar`, sorted, strictly inside it.
pub fn cut_positions(exemplar: &Exemplar, options: &SliceOptions) -> Result<Vec<f64>, SliceError> {
    let width = exemplar.width();
    let height = exemplar.height();
    if !(options.min_portal >= 0.0 && options.min_portal.is_finite()) {
        return Err(SliceError::InvalidOption(format!(
            "minimum portal width {} must be zero or more",
            options.min_portal
        )));
    }
    let raw: Vec<f64> = match options.mode {
        SlicingMode::Uniform { cuts } => {
            if cuts + 1 > options.max_pieces {
                return Err(SliceError::TooManyPieces { pieces: cuts + 1, limit: options.max_pieces });
            }
            (1..=cuts).map(|k| width * k as f64 / (cuts + 1) as f64).collect()
        }
        SlicingMode::Topology => {
            if !(options.event_grouping >= 0.0 && options.event_grouping.is_finite()) {
                return Err(SliceError::InvalidOption(format!(
                    "event grouping {} must be zero or more",
                    options.event_grouping
                )));
            }
            let attachers = group_events(&topology_events(&exemplar.region), options.event_grouping * height);
            attachers.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect()
        }
    };
    let mut xs: Vec<f64> = exemplar.region.rings().flatten().map(|p| p.x).collect();
    xs.sort_by(f64::total_cmp);
    let tolerance = width * 1e-7;
    let mut cuts = Vec::new();
    for c in raw {
        let c = avoid_vertices(c, &xs, tolerance);
        if c <= tolerance || c >= width - tolerance || cuts.last().is_some_and(|&l: &f64| c - l <= tolerance) {
            continue;
        }
        let portals = portals_at(&exemplar.region, c);
        if portals.len() > MAX_PORTALS {
            return Err(SliceError::TooManyPortals { portals: portals.len(), limit: MAX_PORTALS });
        }
        let narrowest = portals.iter().map(|p| p.width()).fold(f64::INFINITY, f64::min);
        if narrowest < options.min_portal {
            continue;
        }
        cuts.push(c);
    }
    if cuts.len() + 1 > options.max_pieces {
        return Err(SliceError::TooManyPieces { pieces: cuts.len() + 1, limit: options.max_pieces });
    }
    Ok(cuts)
}
