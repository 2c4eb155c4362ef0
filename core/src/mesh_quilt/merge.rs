//! Merging a placed patch into the output (the paper's sections 2.5 to
//! 2.7): element correspondences from vertex–face pairs, deformation of
//! both sides towards each other, then for each corresponding pair either
//! one element whole or the two stitched along a graph cut.

use rustc_hash::FxHashMap;

use glam::DVec3;
use rayon::prelude::*;

use super::cut::{FORCED, min_cut_keep};
use super::deform::{Constraint, deform};
use super::faces::{Closest, ElementFaces, Faces};
use super::give_way::{allowed_heights, give_way};
use super::self_crossing::crosses_itself;
use super::stitch::stitch;
use super::zones::{Zone, Zones, boxes_overlap};
use super::{Element, Settings};

/// Pairs needed before two elements are taken to correspond: one stray
/// vertex near another element is not a correspondence.
const MIN_PAIRS: usize = 3;

/// Weight holding vertices away from the seam where they are, against the
/// constraints pulling the seam together: the deformation stays local.
const ANCHOR_WEIGHT: f64 = 0.1;

/// Cells around a patch's footprint within which an output element may move.
const WORK_CELLS: f64 = 2.0;

/// Parts of a cut element with fewer triangles are specks of the cut, not
/// pieces of the element.
const SPECK_TRIANGLES: usize = 12;

/// The gap left between the two pieces of a stitch, in the swatch
/// element's mean edge lengths, for the strip to bridge.
const SEAM_GAP_EDGES: f64 = 1.0;

/// A stitch's strip may have edges this many times the longest edge of
/// the two pieces it joins.
const STRIP_LONGEST_EDGES: f64 = 2.0;

/// Rounds of bending an element over and under what it would cross before
/// it is left out.
const GIVE_WAY_ROUNDS: usize = 3;

/// What merging did, summed over patches.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MergeCounts {
    /// Swatch elements added whole, with nothing of the output near them.
    pub added: usize,
    /// Output elements replaced whole by a swatch element.
    pub replaced: usize,
    /// Output elements kept whole, their swatch element left out.
    pub kept: usize,
    /// Pairs stitched into one element.
    pub stitched: usize,
    /// Pairs that could not be stitched; one of the two was kept whole.
    pub unstitched: usize,
    /// Elements left out because they would have crossed another.
    pub collided: usize,
}

impl MergeCounts {
    /// Adds `other`'s counts to these.
    pub fn add(&mut self, other: &MergeCounts) {
        self.added += other.added;
        self.replaced += other.replaced;
        self.kept += other.kept;
        self.stitched += other.stitched;
        self.unstitched += other.unstitched;
        self.collided += other.collided;
    }
}

/// An element to admit into the output: the output element it replaces
/// (none when it is added), the element, and whether it is a thread.
type Change = (Option<usize>, Element, bool);

/// A vertex of one element close to a face of another.
#[derive(Clone, Copy, Debug)]
struct Pair {
    vertex: u32,
    other: usize,
    point: DVec3,
}

/// Close pairs from the vertices of `from` (passing `wanted`) to `to`.
fn pairs(
    from: &Element,
    closest_within: impl Fn(DVec3, f64) -> Option<Closest>,
    reach_mm: f64,
    wanted: impl Fn(DVec3) -> bool,
) -> Vec<Pair> {
    let normals = from.vertex_normals();
    from.vertices
        .iter()
        .enumerate()
        .filter(|(_, v)| wanted(**v))
        .filter_map(|(i, &v)| {
            let hit = closest_within(v, reach_mm)?;
            // Opposite normals are two sides of a thin part, not one surface.
            (hit.normal.dot(normals[i]) > 0.0).then_some(Pair {
                vertex: i as u32,
                other: hit.element as usize,
                point: hit.point_mm,
            })
        })
        .collect()
}

/// The closest point to `query_mm` within `max_mm` among several sets of
/// faces, its `element` the set's place in `sets` (each set here holds
/// one element).
fn closest_among(sets: &[&Faces], query_mm: DVec3, max_mm: f64) -> Option<Closest> {
    sets.iter()
        .enumerate()
        .filter_map(|(k, faces)| faces.closest_within(query_mm, max_mm).map(|hit| (k, hit)))
        .min_by(|a, b| a.1.distance_mm.total_cmp(&b.1.distance_mm))
        .map(|(k, hit)| Closest { element: k as u32, ..hit })
}

/// Merges the swatch's elements `placed` in output space into `output`.
pub(super) fn merge_patch(
    output: &mut Vec<Element>,
    output_faces: &mut ElementFaces,
    placed: Vec<Element>,
    grid: &impl Zones,
    settings: &Settings,
    reach_mm: f64,
) -> MergeCounts {
    let mut counts = MergeCounts::default();
    let in_patch = |v: DVec3| grid.zone(v).in_patch();
    let placed: Vec<Element> = placed.into_iter().filter(|e| e.vertices.iter().any(|&v| in_patch(v))).collect();
    let area = grid.near_box(reach_mm);
    let near: Vec<usize> = (0..output.len()).filter(|&k| boxes_overlap(output[k].bounds(), area)).collect();
    // The output's elements near the patch, each by its own faces, kept
    // from patch to patch while it does not change.
    for &k in &near {
        output_faces.get(k, &output[k]);
    }
    let out_faces: Vec<&Faces> = near.iter().filter_map(|&k| output_faces.built(k)).collect();
    let in_faces = Faces::new(&placed);
    let to_in = |p: DVec3, max_mm: f64| in_faces.closest_within(p, max_mm);
    let to_out = |p: DVec3, max_mm: f64| closest_among(&out_faces, p, max_mm);
    // Every element's pairs, and below every pair's merge, depend only on
    // the output as it was before this patch: they go to every core.
    let current: &[Element] = output;
    let forward: Vec<Vec<Pair>> = near.par_iter().map(|&k| pairs(&current[k], to_in, reach_mm, in_patch)).collect();
    let backward: Vec<Vec<Pair>> = placed.par_iter().map(|e| pairs(e, to_out, reach_mm, |_| true)).collect();
    let mut related: FxHashMap<(usize, usize), usize> = FxHashMap::default();
    for (o, list) in forward.iter().enumerate() {
        for p in list {
            *related.entry((o, p.other)).or_default() += 1;
        }
    }
    for (i, list) in backward.iter().enumerate() {
        for p in list {
            *related.entry((p.other, i)).or_default() += 1;
        }
    }
    // Each element corresponds to the one it has most pairs with, when that
    // one returns the favour: a ring interlocked with another is near it,
    // but nearer its own twin.
    let mut best_in: FxHashMap<usize, (usize, usize)> = FxHashMap::default();
    let mut best_out: FxHashMap<usize, (usize, usize)> = FxHashMap::default();
    let mut links: Vec<((usize, usize), usize)> = related.into_iter().filter(|(_, n)| *n >= MIN_PAIRS).collect();
    links.sort_unstable();
    for &((o, i), n) in &links {
        if best_in.get(&o).is_none_or(|&(_, m)| n > m) {
            best_in.insert(o, (i, n));
        }
        if best_out.get(&i).is_none_or(|&(_, m)| n > m) {
            best_out.insert(i, (o, n));
        }
    }
    let matched: FxHashMap<usize, usize> = best_out
        .iter()
        .filter(|&(&i, &(o, _))| best_in.get(&o).is_some_and(|&(j, _)| j == i))
        .map(|(&i, &(o, _))| (i, o))
        .collect();
    // Each change says whether its swatch element is a thread, which may
    // bend over and under what it would cross. Changes come in the placed
    // elements' order, whatever core merged each.
    let merged: Vec<(Option<Change>, MergeCounts)> = placed
        .par_iter()
        .enumerate()
        .map(|(i, element)| {
            let mut counts = MergeCounts::default();
            let Some(&o) = matched.get(&i) else {
                counts.added += 1;
                return (Some((None, element.clone(), element.is_thread())), counts);
            };
            let k = near[o];
            let to_in: Vec<Pair> = forward[o].iter().filter(|p| p.other == i).copied().collect();
            let to_out: Vec<Pair> = backward[i].iter().filter(|p| p.other == o).copied().collect();
            let change =
                match merge_pair(&current[k], element, &to_in, &to_out, grid, settings.mu, reach_mm, &mut counts) {
                    Merged::Out => None,
                    Merged::In => Some((Some(k), element.clone(), element.is_thread())),
                    Merged::Stitched(e) => Some((Some(k), e, element.is_thread())),
                };
            (change, counts)
        })
        .collect();
    let mut changes: Vec<Change> = Vec::with_capacity(merged.len());
    for (change, merge_counts) in merged {
        counts.add(&merge_counts);
        changes.extend(change);
    }
    // Nothing goes in that would cross what is there: the print would not
    // be sound.
    for (replaces, element, thread) in changes {
        let Some((element, faces)) = admit(element, replaces, thread, output, output_faces, grid) else {
            counts.collided += 1;
            continue;
        };
        match replaces {
            Some(k) => {
                output_faces.set(k, faces);
                output[k] = element;
            }
            None => {
                output_faces.set(output.len(), faces);
                output.push(element);
            }
        }
    }
    counts
}

/// `element` as it may go into `output` (replacing element `replaces`)
/// without crossing what is there, with its faces: as it is, or, a
/// `thread`, bent over and under what it would cross. None when it cannot
/// go in. Only threads bend: a ring or a rivet bent over its neighbour is
/// no longer the swatch's.
pub(super) fn admit(
    mut element: Element,
    replaces: Option<usize>,
    thread: bool,
    output: &[Element],
    output_faces: &mut ElementFaces,
    grid: &impl Zones,
) -> Option<(Element, Faces)> {
    // A bend moves the element by less than its least extent: what it may
    // meet then lies in its box grown by that.
    let (lo, hi) = element.bounds();
    let margin = if thread { DVec3::splat((hi - lo).min_element()) } else { DVec3::ZERO };
    let others: Vec<usize> = (0..output.len())
        .filter(|&k| Some(k) != replaces && boxes_overlap(output[k].bounds(), (lo - margin, hi + margin)))
        .collect();
    for &k in &others {
        output_faces.get(k, &output[k]);
    }
    let mut bent = false;
    let mut allowed_mm = None;
    for round in 0..=GIVE_WAY_ROUNDS {
        let faces = Faces::new([&element]);
        let hits: Vec<usize> =
            others.iter().copied().filter(|&k| output_faces.built(k).is_some_and(|o| faces.intersects(o))).collect();
        if hits.is_empty() {
            // A bend that folds the element through itself would print
            // wrong.
            return (!bent || !crosses_itself(&element)).then_some((element, faces));
        }
        if round == GIVE_WAY_ROUNDS || !thread {
            return None;
        }
        let in_the_way: Vec<&Faces> = hits.iter().filter_map(|&k| output_faces.built(k)).collect();
        let allowed_mm = *allowed_mm.get_or_insert_with(|| allowed_heights(&element, grid));
        // Only what merging may move moves: the rest of a long thread is
        // done.
        element = give_way(&element, &in_the_way, grid, allowed_mm, |v| grid.near_footprint(v, WORK_CELLS))?;
        bent = true;
    }
    None
}

/// Moves `element` halfway to its pairs' points (the paper's equation 5),
/// holding the vertices `anchored` near where they are and those `fixed`
/// exactly there.
fn meet(element: &mut Element, pairs: &[Pair], anchored: impl Fn(DVec3) -> bool, fixed: &[bool], mu: f64) {
    let mut constraints: Vec<Constraint> = pairs
        .iter()
        .map(|p| Constraint {
            vertex: p.vertex,
            target_mm: 0.5 * (element.vertices[p.vertex as usize] + p.point),
            weight: mu,
        })
        .collect();
    let paired: rustc_hash::FxHashSet<u32> = pairs.iter().map(|p| p.vertex).collect();
    constraints.extend(
        (0..element.vertices.len() as u32)
            .filter(|v| !paired.contains(v) && anchored(element.vertices[*v as usize]))
            .map(|v| Constraint { vertex: v, target_mm: element.vertices[v as usize], weight: ANCHOR_WEIGHT * mu }),
    );
    deform(element, &constraints, |v| fixed[v as usize]);
}

enum Merged {
    Out,
    In,
    Stitched(Element),
}

/// One output element and the swatch element corresponding to it, made
/// one: either stays whole where the other has nothing of its own, or both
/// are deformed to meet (the paper's equation 5) and stitched.
#[allow(clippy::too_many_arguments)]
fn merge_pair(
    c_out: &Element,
    c_in: &Element,
    to_in: &[Pair],
    to_out: &[Pair],
    grid: &impl Zones,
    mu: f64,
    reach_mm: f64,
    counts: &mut MergeCounts,
) -> Merged {
    let out_home = c_out.vertices.iter().filter(|&&v| !grid.zone(v).in_patch()).count();
    let in_home = c_in.vertices.iter().filter(|&&v| grid.zone(v) == Zone::New).count();
    if out_home == 0 {
        counts.replaced += 1;
        return Merged::In;
    }
    if in_home == 0 {
        counts.kept += 1;
        return Merged::Out;
    }
    // Whole elements stay exact; only the two about to be stitched move.
    // Of a long output element (a thread), only the part near the patch
    // moves or is cut: the rest is done.
    let (mut c_out, mut c_in) = (c_out.clone(), c_in.clone());
    let fixed: Vec<bool> = c_out.vertices.iter().map(|&v| !grid.near_footprint(v, WORK_CELLS)).collect();
    meet(&mut c_out, to_in, |v| !grid.zone(v).in_patch(), &fixed, mu);
    let free = vec![false; c_in.vertices.len()];
    // The swatch's element is held where it stays: its new part, and any
    // part beyond the area, which nothing else holds and which would
    // otherwise swing about the seam like a lever.
    meet(&mut c_in, to_out, |v| matches!(grid.zone(v), Zone::New | Zone::Outside), &free, mu);
    match cut_and_stitch(&c_out, &c_in, grid, reach_mm) {
        Some(joined) => {
            counts.stitched += 1;
            Merged::Stitched(joined)
        }
        None => {
            counts.unstitched += 1;
            if in_home > out_home { Merged::In } else { Merged::Out }
        }
    }
}

/// Cuts the output element along a minimum cut and the swatch's where it
/// is not covered by what stays, then stitches the two.
fn cut_and_stitch(c_out: &Element, c_in: &Element, grid: &impl Zones, reach_mm: f64) -> Option<Element> {
    let c = grid.cell_mm();
    // The output's triangles over the patch take part in the cut; the rest
    // stay. On a curved base the patches' faces do not tile as a grid's
    // cells do, and an output thread often ended just short of the new
    // footprint, on faces an earlier patch claimed: nothing over the patch
    // lay by the swatch element's new part, there was nothing to cut, and
    // the thread's continuation was refused. So the triangles near enough
    // to the footprint to move take part as well, when the element reaches
    // beyond them: an element lying wholly that near (a link, a scale)
    // would have nothing left to hold it, and the cut would take all of it.
    let held = c_out.vertices.iter().any(|&v| !grid.near_footprint(v, WORK_CELLS + 1.0));
    let active: Vec<u32> = (0..c_out.triangles.len() as u32)
        .filter(|&f| {
            let centre = c_out.face_centre(f as usize);
            grid.zone(centre).in_patch() || (held && grid.near_footprint(centre, WORK_CELLS))
        })
        .collect();
    let mut node = vec![u32::MAX; c_out.triangles.len()];
    for (k, &f) in active.iter().enumerate() {
        node[f as usize] = k as u32;
    }
    let is_nearby: Vec<bool> = (0..c_out.triangles.len())
        .map(|f| grid.near_footprint(c_out.face_centre(f), WORK_CELLS + reach_mm / c))
        .collect();
    let nearby: Vec<u32> = (0..c_out.triangles.len() as u32).filter(|&f| is_nearby[f as usize]).collect();
    let out_faces = Faces::new([&c_out.subset(|f| is_nearby[f])]);
    let in_faces = Faces::new([c_in]);
    // The swatch's faces that the output covers, and the frontier of them.
    // Each swatch face's closest output face, asked once: it says both what
    // the output covers and, after the cut, what of the swatch stays.
    let over: Vec<Option<u32>> = (0..c_in.triangles.len())
        .map(|f| out_faces.closest_within(c_in.face_centre(f), reach_mm).map(|h| h.face))
        .collect();
    let matched: Vec<bool> = over.iter().map(Option::is_some).collect();
    let in_neighbours = c_in.face_neighbours();
    let frontier: Vec<bool> = (0..c_in.triangles.len())
        .map(|f| matched[f] && in_neighbours[f].iter().any(|&g| !matched[g as usize]))
        .collect();
    let mut distance = vec![4.0 * reach_mm; c_out.vertices.len()];
    let mut sink_vertex = vec![false; c_out.vertices.len()];
    let mut asked = vec![false; c_out.vertices.len()];
    for &f in &active {
        for v in c_out.triangles[f as usize] {
            // A corner is shared by several triangles: asked once.
            if std::mem::replace(&mut asked[v as usize], true) {
                continue;
            }
            let Some(h) = in_faces.closest(c_out.vertices[v as usize]) else { continue };
            distance[v as usize] = h.distance_mm;
            sink_vertex[v as usize] = h.distance_mm <= reach_mm
                && (grid.zone(c_in.face_centre(h.face as usize)) == Zone::New || frontier[h.face as usize]);
        }
    }
    // An output thread that ends over the swatch's, its part that may move
    // stopping short of where the swatch's runs on alone, had nothing to
    // cut: the pair went unstitched, and one of the two threads lost its
    // continuation (117 of 253 unstitched pairs of the vase's weave). The
    // part of it that lies along the swatch's then gives way to it.
    if c_in.is_thread() && !sink_vertex.contains(&true) && frontier.contains(&true) {
        sink_vertex = distance.iter().map(|&d| d <= reach_mm).collect();
    }
    let drop: Vec<(u32, i64)> = active
        .iter()
        .enumerate()
        .filter(|&(_, &f)| c_out.triangles[f as usize].iter().any(|&v| sink_vertex[v as usize]))
        .map(|(k, _)| (k as u32, FORCED))
        .collect();
    if drop.is_empty() {
        return None;
    }
    // The paper's equation 7, lengths in grid cells, scaled to integers. An
    // edge to a triangle outside the graph ties its neighbour to the side
    // that stays.
    let neighbours = c_out.face_neighbours();
    let mut weights = Vec::new();
    let mut keep = Vec::new();
    for &f in &active {
        for &g in &neighbours[f as usize] {
            let shared: Vec<u32> = c_out.triangles[f as usize]
                .iter()
                .copied()
                .filter(|v| c_out.triangles[g as usize].contains(v))
                .collect();
            let [a, b] = shared[..] else { continue };
            let (pa, pb) = (c_out.vertices[a as usize], c_out.vertices[b as usize]);
            let w = (1.0 + pa.distance(pb) / c) * (1.0 + (distance[a as usize] + distance[b as usize]) / c);
            let w = (w * 100.0).round().max(1.0) as i64;
            match node[g as usize] {
                u32::MAX => keep.push((node[f as usize], w)),
                k if k > node[f as usize] => weights.push((node[f as usize], k, w)),
                _ => {}
            }
        }
    }
    let cut = min_cut_keep(active.len(), &weights, &keep, &drop)?;
    let mut kept_out = vec![true; c_out.triangles.len()];
    for (k, &f) in active.iter().enumerate() {
        kept_out[f as usize] = cut[k];
    }
    // The swatch's element stays wherever the output's does not.
    let kept_in: Vec<bool> =
        over.iter().map(|h| h.is_none_or(|face| !kept_out[nearby[face as usize] as usize])).collect();
    let a = without_specks(c_out.subset(|f| kept_out[f]));
    // Where the two surfaces lie together, the swatch's faces just past the
    // cut interleave with the output's: a strip zipped between them would
    // fold through both. A gap of a few edges between the pieces leaves
    // the strip a clean band to bridge.
    let gap_mm = SEAM_GAP_EDGES * c_in.mean_edge_mm();
    let kept_a = Faces::new([&a]);
    let mut clear = vec![None; c_in.vertices.len()];
    let mut is_clear = |v: u32| {
        *clear[v as usize].get_or_insert_with(|| kept_a.closest_within(c_in.vertices[v as usize], gap_mm).is_none())
    };
    let kept_b: Vec<bool> =
        (0..c_in.triangles.len()).map(|f| kept_in[f] && c_in.triangles[f].iter().all(|&v| is_clear(v))).collect();
    let b = without_specks(c_in.subset(|f| kept_b[f]));
    if a.triangles.is_empty() || b.triangles.is_empty() {
        return None;
    }
    // A stitch that passes through itself would print wrong and make the
    // booleans refuse the print: the pair is left unstitched instead.
    // A strip whose edges are longer than the pieces' own bridges two
    // pieces that do not meet (on a top across which patches lie, a scale's
    // strip spanned 6 mm where its edges are 1.9): it would print as a torn
    // sheet, and the pair is left unstitched as well.
    let longest_mm = STRIP_LONGEST_EDGES * a.longest_edge_mm().max(b.longest_edge_mm());
    stitch(&a, &b, 3.0 * reach_mm).filter(|joined| joined.longest_edge_mm() <= longest_mm && !crosses_itself(joined))
}

fn without_specks(element: Element) -> Element {
    let mut out = Element::default();
    for part in element.parts() {
        if part.triangles.len() >= SPECK_TRIANGLES {
            out.append(&part);
        }
    }
    out
}
