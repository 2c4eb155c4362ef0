//! Pieces cut from an exemplar, with their portals and descriptors.

use glam::DVec2;

use super::{
    Exemplar, PairCost, Portal, PortalId, SliceError, SliceOptions, TopologyDescriptor, cut_positions, portals_at,
};
use crate::geom::{Rect, Region, clip_to_rect, closest_on_segment};

/// One piece of an exemplar, between two cut lines (or an end of the exemplar).
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    /// Position in the exemplar, left to right.
    pub index: usize,
    /// `u` of the left side, in exemplar coordinates.
    pub u_start: f64,
    /// Width along `u`.
    pub width: f64,
    /// The material between the two sides, in exemplar coordinates.
    pub region: Region,
    /// Portals on the left side, top to bottom (none at the exemplar's left end).
    pub left: Vec<Portal>,
    /// Portals on the right side, top to bottom (none at the exemplar's right end).
    pub right: Vec<Portal>,
    /// How the portals connect through the material.
    pub descriptor: TopologyDescriptor,
}

impl Piece {
    /// `u` of the right side, in exemplar coordinates.
    pub fn u_end(&self) -> f64 {
        self.u_start + self.width
    }

    /// How far the piece's material reaches from the band's axis (`v = 0`).
    pub fn extent(&self) -> f64 {
        self.region.reach_from_axis()
    }

    /// Portal endpoint heights on the left side, top to bottom (two per portal).
    pub fn left_endpoints(&self) -> impl Iterator<Item = f64> + '_ {
        self.left.iter().flat_map(|p| [p.top, p.bottom])
    }

    /// Portal endpoint heights on the right side, top to bottom.
    pub fn right_endpoints(&self) -> impl Iterator<Item = f64> + '_ {
        self.right.iter().flat_map(|p| [p.top, p.bottom])
    }
}

/// An exemplar cut into pieces, with the matching cost of every compatible pair.
#[derive(Clone, Debug)]
pub struct PieceSet {
    /// Pieces, left to right.
    pub pieces: Vec<Piece>,
    /// The cut positions used, in exemplar `u`.
    pub cuts: Vec<f64>,
    /// Height of the exemplar, the scale that matching costs are measured in.
    pub exemplar_height: f64,
    /// Width of the exemplar.
    pub exemplar_width: f64,
    pairs: Vec<Option<PairCost>>,
    /// For each piece, the index of the first piece with the same shape.
    shape_classes: Vec<usize>,
}

/// Two pieces have the same shape when their outlines, widths and portals
/// agree within this fraction of the exemplar's height once moved to the same `u`.
pub const SHAPE_TOLERANCE: f64 = 1e-4;

/// A piece's geometry moved to `u = 0` and rounded to the shape tolerance:
/// equal keys mean the same shape, whatever the vertex order of the rings.
fn shape_key(piece: &Piece, step: f64) -> Vec<(i64, i64)> {
    let round = |p: DVec2| (((p.x - piece.u_start) / step).round() as i64, (p.y / step).round() as i64);
    let mut key: Vec<(i64, i64)> = piece.region.rings().flatten().map(|&p| round(p)).collect();
    key.sort_unstable();
    key.push((i64::MIN, (piece.width / step).round() as i64));
    for p in piece.left.iter().chain(&piece.right) {
        key.push((i64::MIN + 1, (p.top / step).round() as i64));
        key.push((i64::MIN + 2, (p.bottom / step).round() as i64));
    }
    key.push((i64::MIN + 3, piece.left.len() as i64 * 1000 + piece.right.len() as i64));
    key
}

/// Groups pieces of the same shape (see [`SHAPE_TOLERANCE`]).
fn shape_classes(pieces: &[Piece], exemplar_height: f64) -> Vec<usize> {
    let step = SHAPE_TOLERANCE * exemplar_height.max(f64::MIN_POSITIVE);
    let mut first: rustc_hash::FxHashMap<Vec<(i64, i64)>, usize> = Default::default();
    pieces.iter().map(|p| *first.entry(shape_key(p, step)).or_insert(p.index)).collect()
}

/// Finds which polygon of `region` a portal belongs to, probing just inside
/// the piece next to the portal's middle.
fn polygon_of(region: &Region, u: f64, portal: &Portal, inward: f64) -> usize {
    let probe = DVec2::new(u + inward, portal.middle());
    if let Some(i) = region.polygons.iter().position(|p| p.contains(probe)) {
        return i;
    }
    // A sliver thinner than the probe step: take the nearest polygon.
    let probe = DVec2::new(u, portal.middle());
    let distance = |ring: &Vec<DVec2>| {
        (0..ring.len())
            .map(|i| closest_on_segment(probe, ring[i], ring[(i + 1) % ring.len()]).1.distance(probe))
            .fold(f64::INFINITY, f64::min)
    };
    (0..region.polygons.len())
        .min_by(|&a, &b| distance(&region.polygons[a].outer).total_cmp(&distance(&region.polygons[b].outer)))
        .unwrap_or(0)
}

impl PieceSet {
    /// Cuts `exemplar` as `options` say and analyses every piece.
    ///
    /// ```
    /// use tracery_core::vector_brush::{builtin, PieceSet, SliceOptions};
    /// let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
    /// assert!(set.pieces.len() >= 4);
    /// assert!(set.pieces[0].left.is_empty());
    /// ```
    pub fn new(exemplar: &Exemplar, options: &SliceOptions) -> Result<Self, SliceError> {
        let cuts = cut_positions(exemplar, options)?;
        let width = exemplar.width();
        let mut bounds: Vec<f64> = Vec::with_capacity(cuts.len() + 2);
        bounds.push(0.0);
        bounds.extend(&cuts);
        bounds.push(width);
        let side_portals: Vec<Vec<Portal>> = cuts.iter().map(|&c| portals_at(&exemplar.region, c)).collect();
        let margin = exemplar.height().max(width);
        let inward = width * 1e-6;
        let pieces = (0..bounds.len() - 1)
            .map(|i| {
                let (a, b) = (bounds[i], bounds[i + 1]);
                let rect = Rect::new(
                    DVec2::new(a, exemplar.bounds.min.y - margin),
                    DVec2::new(b, exemplar.bounds.max.y + margin),
                );
                let region = clip_to_rect(&exemplar.region, &rect);
                let left = if i == 0 { Vec::new() } else { side_portals[i - 1].clone() };
                let right = if i + 1 == bounds.len() - 1 { Vec::new() } else { side_portals[i].clone() };
                let left_polygons: Vec<usize> = left.iter().map(|p| polygon_of(&region, a, p, inward)).collect();
                let right_polygons: Vec<usize> = right.iter().map(|p| polygon_of(&region, b, p, -inward)).collect();
                // Dense ids for the polygons that reach a portal (at most
                // 2 × MAX_PORTALS of them), however many the piece holds: a
                // polygon index past the id type must not wrap onto another.
                let mut touching: Vec<usize> = left_polygons.iter().chain(&right_polygons).copied().collect();
                touching.sort_unstable();
                touching.dedup();
                let id = |k: &usize| touching.binary_search(k).unwrap_or(0) as PortalId;
                let left_ids: Vec<PortalId> = left_polygons.iter().map(id).collect();
                let right_ids: Vec<PortalId> = right_polygons.iter().map(id).collect();
                let closed = region.polygons.len() - touching.len();
                let descriptor =
                    TopologyDescriptor::new(&left_ids, &right_ids, closed as u16, region.hole_count() as u16);
                Piece { index: i, u_start: a, width: b - a, region, left, right, descriptor }
            })
            .collect::<Vec<_>>();
        let exemplar_height = exemplar.height();
        let n = pieces.len();
        let mut pairs = Vec::with_capacity(n * n);
        for a in &pieces {
            for b in &pieces {
                pairs.push(PairCost::between(a, b, exemplar_height));
            }
        }
        let shape_classes = shape_classes(&pieces, exemplar_height);
        Ok(PieceSet { pieces, cuts, exemplar_height, exemplar_width: width, pairs, shape_classes })
    }

    /// For each piece, the index of the first piece of the same shape: pieces
    /// with equal classes look the same wherever they are placed.
    ///
    /// ```
    /// use tracery_core::vector_brush::{builtin, PieceSet, SliceOptions};
    /// let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
    /// let classes = set.shape_classes();
    /// assert_eq!(classes.len(), set.len());
    /// assert!(classes.iter().enumerate().all(|(i, &c)| c <= i));
    /// ```
    pub fn shape_classes(&self) -> &[usize] {
        &self.shape_classes
    }

    /// The same set with one piece per shape (see [`PieceSet::shape_classes`]),
    /// and for each of its pieces the index of that piece here. Identical
    /// pieces give identical patterns, so the solver searches this smaller set.
    pub fn distinct_shapes(&self) -> (PieceSet, Vec<usize>) {
        let originals: Vec<usize> = (0..self.len()).filter(|&i| self.shape_classes[i] == i).collect();
        let pieces: Vec<Piece> =
            originals.iter().enumerate().map(|(k, &i)| Piece { index: k, ..self.pieces[i].clone() }).collect();
        let n = self.len();
        let pairs = originals.iter().flat_map(|&a| originals.iter().map(move |&b| self.pairs[a * n + b])).collect();
        let shape_classes = (0..pieces.len()).collect();
        let set = PieceSet {
            pieces,
            cuts: self.cuts.clone(),
            exemplar_height: self.exemplar_height,
            exemplar_width: self.exemplar_width,
            pairs,
            shape_classes,
        };
        (set, originals)
    }

    /// The cost of following piece `a` with piece `b` when their portals join
    /// them; `None` at a break (no portal, the pieces only sit side by side)
    /// and when they cannot follow each other.
    pub fn joining(&self, a: usize, b: usize) -> Option<&PairCost> {
        self.pair(a, b).filter(|_| !self.pieces[a].right.is_empty())
    }

    /// Number of pieces.
    pub fn len(&self) -> usize {
        self.pieces.len()
    }

    /// Whether there is no piece.
    pub fn is_empty(&self) -> bool {
        self.pieces.is_empty()
    }

    /// The cost of following piece `a` with piece `b`, or `None` when their
    /// portal counts differ.
    pub fn pair(&self, a: usize, b: usize) -> Option<&PairCost> {
        self.pairs[a * self.pieces.len() + b].as_ref()
    }

    /// Sets the cost of following piece `a` with piece `b`, where they can
    /// follow each other: the search's tests give seams costs no drawing
    /// would, to reach the cases that tell a sound search from a lucky one.
    #[cfg(test)]
    pub(crate) fn set_pair_cost(&mut self, a: usize, b: usize, cost: f64) {
        let n = self.pieces.len();
        if let Some(pair) = &mut self.pairs[a * n + b] {
            pair.cost = cost;
        }
    }
}
