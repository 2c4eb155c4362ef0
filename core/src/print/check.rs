//! The printability check on final planar geometry: thin features, narrow
//! gaps and weak bridges, each with where it is.

use rustc_hash::FxHashMap;

use glam::DVec2;
use serde::Serialize;

use super::PrintSettings;
use super::edge_grid::EdgeGrid;
use super::thickness::{Narrow, Side, narrow_places};
use crate::geom::{Region, closest_on_segment};

/// A group of narrow places is a flaw when, somewhere in it, the two sides
/// are at least this many minimum widths apart along the outline: a neck
/// between two parts, a long thin strip, a slot. Sharp tips and V notches,
/// whose sides meet close by, are narrow only at their very end, which no
/// nozzle resolves and no one expects it to.
const FLAW_SIDES_APART_WIDTHS: f64 = 4.0;

/// Outline samples per minimum width: fine enough that a neck as short as a
/// fifth of the nozzle is sampled.
const SAMPLES_PER_WIDTH: f64 = 5.0;

/// A thin feature or a narrow gap: neighbouring narrow places grouped.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Flaw {
    /// Where it is narrowest (the disc's centre there), mm.
    pub at_mm: DVec2,
    /// Its narrowest width, mm.
    pub width_mm: f64,
    /// Its narrow cross-sections, outline to outline, mm (for drawing).
    #[serde(skip)]
    pub spans_mm: Vec<[DVec2; 2]>,
    /// The discs that fit there: (centre, radius), mm (for thickening).
    #[serde(skip)]
    pub discs_mm: Vec<(DVec2, f64)>,
}

/// Material across a seam between two pieces: a portal as printed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Bridge {
    /// Its middle, mm.
    pub at_mm: DVec2,
    /// Its width along the seam, mm.
    pub width_mm: f64,
    /// Its two ends on the seam, mm (for drawing).
    #[serde(skip)]
    pub ends_mm: [DVec2; 2],
}

/// What the check found.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Printability {
    /// The nozzle checked against, mm.
    pub nozzle_mm: f64,
    /// The thinnest feature, mm, when one is thinner than the nozzle.
    pub thinnest_feature_mm: Option<f64>,
    /// The narrowest gap, mm, when one is narrower than the nozzle.
    pub narrowest_gap_mm: Option<f64>,
    /// Features thinner than the nozzle, thinnest first.
    pub thin_features: Vec<Flaw>,
    /// Gaps narrower than the nozzle, narrowest first.
    pub narrow_gaps: Vec<Flaw>,
    /// Bridges between pieces narrower than the limit, weakest first.
    pub weak_bridges: Vec<Bridge>,
    /// Layers in the pattern's thickness.
    pub layers: f64,
    /// Whether thin features were thickened to the nozzle.
    pub thickened: bool,
}

/// Checks `region` (printed `thickness_mm` thick) against `settings`.
/// `seams_mm` are the cut lines between pieces, across the band: the
/// material on each is a bridge.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::print::{PrintSettings, check};
/// let rect = |x0: f64, y0: f64, x1: f64, y1: f64| vec![DVec2::new(x0, y0), DVec2::new(x1, y0), DVec2::new(x1, y1), DVec2::new(x0, y1)];
/// // Two 3 mm squares joined by a 0.2 mm neck.
/// let shape = resolve(&[rect(0.0, 0.0, 3.0, 3.0), rect(3.0, 1.4, 5.0, 1.6), rect(5.0, 0.0, 8.0, 3.0)]);
/// # fn resolve(r: &[Vec<DVec2>]) -> Region { tracery_core::geom::resolve_contours(r, tracery_core::geom::FillRule::NonZero) }
/// let found = check(&shape, &[], &PrintSettings::default(), 2.0);
/// assert_eq!(found.thin_features.len(), 1);
/// assert!((found.thinnest_feature_mm.unwrap() - 0.2).abs() < 1e-6);
/// assert!((found.thin_features[0].at_mm.x - 4.0).abs() < 1.0);
/// ```
pub fn check(region: &Region, seams_mm: &[[DVec2; 2]], settings: &PrintSettings, thickness_mm: f64) -> Printability {
    let width = settings.min_width_mm();
    let spacing = width / SAMPLES_PER_WIDTH;
    let thin_features = group(narrow_places(region, Side::Material, width, spacing), width);
    let narrow_gaps = group(narrow_places(region, Side::Gap, width, spacing), width);
    let seam_length = seams_mm.iter().map(|[a, b]| a.distance(*b)).fold(0.0, f64::max);
    let edges = EdgeGrid::new(region, (seam_length / 8.0).max(width));
    let mut weak_bridges: Vec<Bridge> = seams_mm
        .iter()
        .flat_map(|s| bridges_on(region, &edges, *s))
        .filter(|b| b.width_mm < settings.min_bridge_mm())
        .collect();
    weak_bridges.sort_by(|a, b| a.width_mm.total_cmp(&b.width_mm));
    Printability {
        nozzle_mm: settings.nozzle_mm,
        thinnest_feature_mm: thin_features.first().map(|f| f.width_mm),
        narrowest_gap_mm: narrow_gaps.first().map(|f| f.width_mm),
        thin_features,
        narrow_gaps,
        weak_bridges,
        layers: thickness_mm / settings.layer_height_mm,
        thickened: false,
    }
}

/// Narrow places whose discs lie within `width` of each other are one flaw.
fn group(places: Vec<Narrow>, width: f64) -> Vec<Flaw> {
    let mut sets = crate::disjoint_sets::DisjointSets::new(places.len());
    // Cells half a width wide: any two discs in one cell are within a width
    // of each other, so a cell's discs are joined at once, and a disc's
    // neighbours within a width lie in the 5 × 5 cells around its own. Two
    // cells are compared disc by disc only until a pair within a width
    // joins them, and not at all once they are joined. (Comparing every
    // pair within 3 × 3 cells of a width took a dense loop's check
    // quadratic: 100 of its 400 ms.)
    let cell = 0.5 * width;
    let cell_of = |p: DVec2| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: FxHashMap<(i64, i64), Vec<usize>> = FxHashMap::default();
    for (i, p) in places.iter().enumerate() {
        grid.entry(cell_of(p.centre_mm)).or_default().push(i);
    }
    for members in grid.values() {
        for &j in &members[1..] {
            sets.join(members[0], j);
        }
    }
    // In any order: the sets joined, and their representatives (the least
    // index), do not depend on it.
    for (&(cx, cy), members) in &grid {
        for x in cx - 2..=cx + 2 {
            for y in cy - 2..=cy + 2 {
                // Each pair of cells once.
                if (x, y) <= (cx, cy) {
                    continue;
                }
                let Some(others) = grid.get(&(x, y)) else { continue };
                if sets.find(members[0]) == sets.find(others[0]) {
                    continue;
                }
                let near = members
                    .iter()
                    .any(|&i| others.iter().any(|&j| places[j].centre_mm.distance(places[i].centre_mm) <= width));
                if near {
                    sets.join(members[0], others[0]);
                }
            }
        }
    }
    let mut flaws: FxHashMap<usize, Flaw> = FxHashMap::default();
    for (i, p) in places.iter().enumerate() {
        let root = sets.find(i);
        let flaw = flaws.entry(root).or_insert_with(|| Flaw {
            at_mm: p.centre_mm,
            width_mm: p.width_mm,
            spans_mm: Vec::new(),
            discs_mm: Vec::new(),
        });
        if p.width_mm < flaw.width_mm {
            flaw.width_mm = p.width_mm;
            flaw.at_mm = p.centre_mm;
        }
        flaw.spans_mm.push([p.from_mm, p.to_mm]);
        flaw.discs_mm.push((p.centre_mm, p.width_mm / 2.0));
    }
    let mut significant: FxHashMap<usize, bool> = FxHashMap::default();
    for (i, p) in places.iter().enumerate() {
        let root = sets.find(i);
        *significant.entry(root).or_default() |= p.apart_along_outline_mm >= FLAW_SIDES_APART_WIDTHS * width;
    }
    flaws.retain(|root, _| significant[root]);
    let mut flaws: Vec<Flaw> = flaws.into_values().collect();
    flaws.sort_by(|a, b| a.width_mm.total_cmp(&b.width_mm).then(a.at_mm.x.total_cmp(&b.at_mm.x)));
    flaws
}

/// The stretches of material along one seam: the seam is split where it
/// crosses the outline, and each piece is material when its middle lies
/// left of the nearest outline edge (material lies left of every ring),
/// with the usual rule at a vertex: left of both edges at a convex corner,
/// of either at a reflex one.
fn bridges_on(region: &Region, edges: &EdgeGrid<'_>, [a, b]: [DVec2; 2]) -> Vec<Bridge> {
    let ab = b - a;
    let near = edges.near(a, b);
    let mut ts = vec![0.0, 1.0];
    let along = |x: DVec2| (x - a).dot(ab) / ab.length_squared();
    for &e in &near {
        let (p, q) = (edges.edges[e].a, edges.edges[e].b);
        // Which side of the seam's line each end lies on, with zero counted
        // as one side: an edge ending on the line, or of no length, then
        // crosses once or not at all, never twice.
        let (dp, dq) = (ab.perp_dot(p - a), ab.perp_dot(q - a));
        if (dp > 0.0) == (dq > 0.0) {
            continue;
        }
        let t = along(p) + (along(q) - along(p)) * (dp / (dp - dq));
        if (0.0..=1.0).contains(&t) {
            ts.push(t);
        }
    }
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    let is_material = |m: DVec2| -> bool {
        let mut best: Option<(f64, usize, f64)> = None;
        for &e in &near {
            let (u, closest) = closest_on_segment(m, edges.edges[e].a, edges.edges[e].b);
            let d = m.distance_squared(closest);
            if best.is_none_or(|(bd, _, _)| d < bd) {
                best = Some((d, e, u));
            }
        }
        let Some((_, e, u)) = best.filter(|(d, _, _)| d.sqrt() < edges.cell_mm()) else { return region.contains(m) };
        let (o, p, q, r) = edges.with_neighbours(e);
        let left = |x: DVec2, y: DVec2| (y - x).perp_dot(m - x) > 0.0;
        // At a vertex, the corner decides with both of its edges.
        let corner = |before: DVec2, at: DVec2, after: DVec2| {
            let convex = (at - before).perp_dot(after - at) > 0.0;
            if convex { left(before, at) && left(at, after) } else { left(before, at) || left(at, after) }
        };
        if u <= 0.0 {
            corner(o, p, q)
        } else if u >= 1.0 {
            corner(p, q, r)
        } else {
            left(p, q)
        }
    };
    let mut bridges: Vec<Bridge> = Vec::new();
    let mut open: Option<f64> = None;
    // Stretches shorter than a micrometre (where the seam grazes a vertex)
    // are neither material nor gap: they join their neighbours.
    let shortest = 1e-3 / ab.length().max(1e-12);
    for w in ts.windows(2) {
        if w[1] - w[0] < shortest {
            continue;
        }
        let inside = is_material(a + ab * (0.5 * (w[0] + w[1])));
        match (inside, open) {
            (true, None) => open = Some(w[0]),
            (false, Some(start)) => {
                bridges.push(bridge(a, ab, start, w[0]));
                open = None;
            }
            _ => {}
        }
    }
    if let Some(start) = open {
        bridges.push(bridge(a, ab, start, 1.0));
    }
    bridges
}

fn bridge(a: DVec2, ab: DVec2, t0: f64, t1: f64) -> Bridge {
    let ends_mm = [a + ab * t0, a + ab * t1];
    Bridge { at_mm: (ends_mm[0] + ends_mm[1]) * 0.5, width_mm: ends_mm[0].distance(ends_mm[1]), ends_mm }
}
