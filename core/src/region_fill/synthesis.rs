//! Synthesis of a curve texture in a rectangle (sections 4.3.2 to 4.3.5 of
//! the curve-texture paper): patches of the exemplar's samples copied in,
//! then search and assignment steps at each level, coarse to fine, the
//! graph made into paths and sampled again between levels.

use glam::DVec2;
use rayon::prelude::*;

use crate::control::Control;
use crate::geom::{Rect, Region};
use crate::random::SplitMix64;

use super::assignment::{MatchedPair, assign_edges, assign_positions, existence_votes, missing_samples};
use super::search::KindIndex;
use super::{
    CurvePath, EdgeTangents, Elements, FillError, JOIN_TOLERANCE_MM, LEVELS, NearestField, NeighbourhoodPair,
    Neighbourhoods, PlacedElement, SampleGraph, SampleGrid, SearchSettings, Settings, Similarity, assign_orientations,
    greatest_degree, search, undo_junctions,
};

/// Patches (section 4.3.2): the rectangle `size_mm` is tiled with squares
/// `patch_mm` wide, each filled with the samples (not the edges) of a
/// random square of the input, leaving out samples within half a spacing
/// of ones already placed. Also the input sample each was copied from:
/// the search starts from there rather than at random.
fn initialize(
    input: &SampleGraph,
    pinned: SampleGraph,
    (size_mm, mask): (DVec2, &Mask),
    patch_mm: f64,
    delta_mm: f64,
    rng: &mut SplitMix64,
) -> (SampleGraph, NearestField) {
    let (low, high) = bounds(input);
    // Patches go around what is already drawn; its samples start the search at random.
    let mut sources = NearestField::default();
    let of_kind = KindIndex::new(input);
    for sample in &pinned.samples {
        sources.input_of.push(of_kind.random(sample.element, rng));
        sources.cost.push(f64::MAX);
    }
    let mut output = pinned;
    let grid_of = |g: &SampleGraph| SampleGrid::new(g, delta_mm);
    let (nx, ny) = ((size_mm.x / patch_mm).ceil() as usize, (size_mm.y / patch_mm).ceil() as usize);
    for j in 0..ny {
        for i in 0..nx {
            let target = DVec2::new(i as f64, j as f64) * patch_mm;
            let room = (high - low - DVec2::splat(patch_mm)).max(DVec2::ZERO);
            let source = low + DVec2::new(rng.next_unit(), rng.next_unit()) * room;
            let placed = grid_of(&output);
            for (s, sample) in input.samples.iter().enumerate() {
                let local = sample.position_mm - source;
                if local.x < 0.0 || local.y < 0.0 || local.x >= patch_mm || local.y >= patch_mm {
                    continue;
                }
                let at = target + local;
                if at.x > size_mm.x
                    || at.y > size_mm.y
                    || !mask.contains(at)
                    || !placed.within(&output, at, 0.5 * delta_mm).is_empty()
                {
                    continue;
                }
                // An element is copied whole: it is one sample.
                output.add_of_kind(at, sample.element);
                sources.input_of.push(s as u32);
                sources.cost.push(f64::MAX);
            }
        }
    }
    (output, sources)
}

/// Where samples may lie, in the synthesis's frame: the whole rectangle,
/// or the region grown by the finest neighbourhood's radius, so that the
/// pattern along the region's edge is judged by whole neighbourhoods at
/// the finest level (more than the rectangle's own edge gets) while
/// nothing is made far outside it.
enum Mask {
    Everywhere,
    Within(Region),
}

impl Mask {
    fn contains(&self, p: DVec2) -> bool {
        match self {
            Mask::Everywhere => true,
            Mask::Within(region) => region.contains(p),
        }
    }
}

fn bounds(graph: &SampleGraph) -> (DVec2, DVec2) {
    graph.samples.iter().fold((DVec2::MAX, DVec2::MIN), |(lo, hi), s| (lo.min(s.position_mm), hi.max(s.position_mm)))
}

/// Fills a rectangle `width_mm × height_mm` (from the origin) with a curve
/// texture like `exemplar`; returns the paths.
///
/// ```no_run
/// use tracery_core::region_fill::{Settings, builtin_curves, fill_rectangle};
/// let paths = fill_rectangle(&builtin_curves("crackle").unwrap(), 60.0, 40.0, &Settings::default()).unwrap();
/// assert!(!paths.is_empty());
/// ```
pub fn fill_rectangle(
    exemplar: &[CurvePath],
    width_mm: f64,
    height_mm: f64,
    settings: &Settings,
) -> Result<Vec<CurvePath>, FillError> {
    let bounds = Rect::new(DVec2::ZERO, DVec2::new(width_mm, height_mm));
    synthesize(exemplar, &bounds, settings, &Control::default())
}

/// Synthesizes a curve texture like `exemplar` over the rectangle `bounds`
/// (sections 4.3.2 to 4.3.5): patches, then at each of three levels,
/// coarse to fine, `settings.iterations` steps of search and assignment,
/// the graph made into paths and sampled again between levels. Reports
/// progress after every step and stops when asked to.
pub fn synthesize(
    exemplar: &[CurvePath],
    bounds: &Rect,
    settings: &Settings,
    control: &Control,
) -> Result<Vec<CurvePath>, FillError> {
    synthesize_around(exemplar, bounds, &[], settings, control)
}

/// As [`synthesize`], around paths already drawn (`fixed`, mm): their
/// samples take part in every neighbourhood but never move, vanish or lose
/// an edge, so the texture grows out of them and joins them (the paper's
/// autocomplete, section 4.2: samples of what the person drew are always
/// matched). Returns the new paths only; one that continues a fixed path
/// ends exactly on it.
///
/// ```no_run
/// use tracery_core::DVec2;
/// use tracery_core::geom::Rect;
/// use tracery_core::control::Control;
/// use tracery_core::region_fill::{CurvePath, Settings, builtin_curves, synthesize_around};
/// let drawn = CurvePath { points_mm: vec![DVec2::new(5.0, 20.0), DVec2::new(35.0, 20.0)], closed: false };
/// let bounds = Rect::new(DVec2::ZERO, DVec2::new(40.0, 40.0));
/// let exemplar = builtin_curves("waves").unwrap();
/// let new = synthesize_around(&exemplar, &bounds, &[drawn], &Settings::default(), &Control::default()).unwrap();
/// assert!(!new.is_empty());
/// ```
pub fn synthesize_around(
    exemplar: &[CurvePath],
    bounds: &Rect,
    fixed: &[CurvePath],
    settings: &Settings,
    control: &Control,
) -> Result<Vec<CurvePath>, FillError> {
    Ok(synthesize_oriented(exemplar, &Elements::default(), (bounds, None), (fixed, &[]), settings, control)?.paths)
}

/// What the synthesis made: its paths, the orientations of the final
/// graph's edges that reconstruction follows, and its discrete elements.
#[derive(Clone, Debug, Default)]
pub struct Synthesized {
    /// The new paths, cut where they meet, mm.
    pub paths: Vec<CurvePath>,
    /// The orientations the final step assigned, by the samples' places.
    pub tangents: EdgeTangents,
    /// The discrete elements, of the exemplar's kinds, mm.
    pub elements: Vec<PlacedElement>,
}

/// As [`synthesize_around`], with the orientations of the final graph, and
/// the discrete `elements` of the exemplar synthesized with its paths:
/// each is one sample at its centre, at every level, matched only with
/// elements of its kind (sections 4.1 and 4.2.3). With a `region` (mm,
/// within `bounds`), samples are kept within it grown by the finest
/// neighbourhood's radius: a round or drawn region is not synthesized over
/// its whole bounding box. Elements already drawn (`fixed_elements`, of
/// the exemplar's kinds) are pinned as the drawn paths are, and are not
/// among the elements returned.
pub fn synthesize_oriented(
    exemplar: &[CurvePath],
    elements: &Elements,
    (bounds, region): (&Rect, Option<&Region>),
    (fixed, fixed_elements): (&[CurvePath], &[PlacedElement]),
    settings: &Settings,
    control: &Control,
) -> Result<Synthesized, FillError> {
    let size = bounds.size();
    let offset = bounds.min;
    let mask = match region {
        Some(region) => Mask::Within(crate::geom::offset(&region.translated(-offset), settings.radius_mm())),
        None => Mask::Everywhere,
    };
    let fixed: Vec<CurvePath> = fixed
        .iter()
        .map(|p| CurvePath { points_mm: p.points_mm.iter().map(|q| *q - offset).collect(), closed: p.closed })
        .collect();
    let fixed_elements: Vec<(DVec2, u32)> = fixed_elements.iter().map(|e| (e.centre_mm - offset, e.kind)).collect();
    let element_spacing_mm = element_spacing_mm(elements, settings.radius_mm());
    let mut rng = SplitMix64::new(settings.seed);
    let mut paths: Option<Vec<CurvePath>> = None;
    let mut carried: Vec<(DVec2, u32)> = Vec::new();
    let mut tangents = EdgeTangents::default();
    let steps = (LEVELS * settings.iterations) as f32;
    for level in 0..LEVELS {
        let delta = settings.delta_mm * 2f64.powi((LEVELS - 1 - level) as i32);
        let radius = settings.radius_spacings * delta;
        let mut input = SampleGraph::new(exemplar, delta)?;
        for e in &elements.placed {
            input.add_element(e.centre_mm, e.kind);
        }
        let (output, start, pinned) = match &paths {
            None => {
                let mut pinned = SampleGraph::new(&fixed, delta)?;
                for &(centre, kind) in &fixed_elements {
                    pinned.add_element(centre, kind);
                }
                let count = pinned.samples.len();
                let (output, sources) = initialize(&input, pinned, (size, &mask), 2.0 * radius, delta, &mut rng);
                (output, Some(sources), count)
            }
            Some(p) => {
                let all: Vec<CurvePath> = p.iter().chain(&fixed).cloned().collect();
                let mut graph = SampleGraph::new_without_corners(&all, delta)?;
                let mut on_fixed = on_paths(&graph, &fixed, JOIN_TOLERANCE_MM);
                // Elements go on to the next level as they are: one sample
                // at every level. The drawn ones are pinned.
                for (elements, drawn) in [(&fixed_elements, true), (&carried, false)] {
                    for &(centre, kind) in elements {
                        graph.add_element(centre, kind);
                        on_fixed.push(drawn);
                    }
                }
                let (graph, pinned) = graph.pinned_first(&on_fixed);
                (graph, None, pinned)
            }
        };
        let at = Level {
            size_mm: size,
            mask: &mask,
            delta_mm: delta,
            radius_mm: radius,
            iterations: settings.iterations,
            pinned,
            control,
            done: (level * settings.iterations) as f32,
            steps,
            last: level + 1 == LEVELS,
            element_spacing_mm,
        };
        let mut output = synthesize_level(&input, output, start, &at, &mut rng)?;
        // Where the exemplar's paths never meet, neither do the new ones:
        // a stray branch joining two spirals is cut off (what was drawn
        // keeps its joins).
        if at.last && greatest_degree(&input) <= 2 {
            undo_junctions(&mut output, pinned);
        }
        // What was drawn is added back whole at the next level: only the new
        // paths (and their edges onto what was drawn) are carried.
        output.disconnect_among(pinned);
        paths = Some(output.to_paths());
        // The pinned samples come first, and stay: the drawn elements are among them.
        carried = output.samples[pinned..].iter().filter_map(|s| s.element.map(|k| (s.position_mm, k))).collect();
        if level + 1 == LEVELS {
            tangents = EdgeTangents::of(&output, offset);
        }
    }
    let paths = paths
        .unwrap_or_default()
        .into_iter()
        .map(|p| CurvePath { points_mm: p.points_mm.iter().map(|q| *q + offset).collect(), ..p })
        .collect();
    let elements =
        carried.into_iter().map(|(centre, kind)| PlacedElement { kind, centre_mm: centre + offset }).collect();
    Ok(Synthesized { paths, tangents, elements })
}

/// Which samples of `graph` lie within `tolerance_mm` of one of `paths`.
fn on_paths(graph: &SampleGraph, paths: &[CurvePath], tolerance_mm: f64) -> Vec<bool> {
    let boxes: Vec<Option<Rect>> =
        paths.iter().map(|p| Rect::from_points(p.points_mm.iter().copied()).map(|b| b.inflate(tolerance_mm))).collect();
    graph
        .samples
        .iter()
        .map(|s| {
            let p = s.position_mm;
            paths
                .iter()
                .zip(&boxes)
                .any(|(path, b)| b.is_some_and(|b| b.contains(p)) && path.distance_to(p) <= tolerance_mm)
        })
        .collect()
}

/// A sample stays when matched in at least this share of the
/// neighbourhoods holding it. The paper's one half left rows of scales
/// broken (coverage 0.96 of the region) and thinned the spirals (0.89);
/// at 0.4 the scales fill (1.00) and the spirals cover 0.93, with the
/// other built-ins' measures and the corpus about the same
/// (`docs/region-fill.md`, *Existence*).
const MIN_EXISTENCE: f64 = 0.4;

/// One level of the synthesis: its area, spacing and radius, and its
/// steps' place in the whole for progress.
struct Level<'a, 'c> {
    size_mm: DVec2,
    /// Where samples may lie.
    mask: &'a Mask,
    delta_mm: f64,
    radius_mm: f64,
    iterations: usize,
    /// Samples `0..pinned` were drawn by the person: they stay as they are.
    pinned: usize,
    control: &'a Control<'c>,
    /// Steps done before this level.
    done: f32,
    /// Steps in the whole synthesis.
    steps: f32,
    /// Whether this is the finest level, whose orientations reconstruction reads.
    last: bool,
    /// The exemplar's [`element_spacing_mm`].
    element_spacing_mm: Option<f64>,
}

impl Level<'_, '_> {
    /// What leaving a discrete element unmatched costs: 1.5 times the mean
    /// distance from an element to its nearest fellow (the paper's choice,
    /// section 4.2.3), at least a path sample's cost and at most the
    /// radius; a lone element, with no fellow to space it, costs the most.
    /// Elements lie far apart next to path samples; at a path sample's cost
    /// they were left unmatched by most neighbourhoods round them and
    /// removed, and fills held half the elements of their exemplars.
    fn element_unmatched_mm(&self) -> f64 {
        let floor = Similarity::new(self.delta_mm).element_unmatched_mm;
        let most = self.radius_mm.max(floor);
        self.element_spacing_mm.map_or(most, |spacing| (1.5 * spacing).clamp(floor, most))
    }
}

/// The mean distance from an element to its nearest fellow, mm; `None`
/// with fewer than two elements. Read once per synthesis, for
/// [`Level::element_unmatched_mm`].
fn element_spacing_mm(elements: &Elements, cell_mm: f64) -> Option<f64> {
    if elements.placed.len() < 2 {
        return None;
    }
    let mut centres = SampleGraph::default();
    for e in &elements.placed {
        centres.add_element(e.centre_mm, e.kind);
    }
    let grid = SampleGrid::new(&centres, cell_mm);
    let (low, high) = bounds(&centres);
    let reach = (high - low).length() + 1.0;
    let nearest: Vec<f64> = (0..centres.samples.len() as u32)
        .filter_map(|s| {
            let at = centres.samples[s as usize].position_mm;
            grid.nearest_where(&centres, at, reach, &|t| t != s)
                .map(|t| centres.samples[t as usize].position_mm.distance(at))
        })
        .collect();
    Some(nearest.iter().sum::<f64>() / nearest.len().max(1) as f64)
}

/// Search and assignment steps at one level.
fn synthesize_level(
    input: &SampleGraph,
    mut output: SampleGraph,
    start: Option<NearestField>,
    level: &Level,
    rng: &mut SplitMix64,
) -> Result<SampleGraph, FillError> {
    let (size_mm, delta_mm, radius_mm) = (level.size_mm, level.delta_mm, level.radius_mm);
    let similarity = Similarity::new(delta_mm).with_element_unmatched(level.element_unmatched_mm());
    let project = |p: DVec2| p.clamp(DVec2::ZERO, size_mm);
    // The exemplar's neighbourhoods are the same at every step of a level.
    let input_near = Neighbourhoods::new(input, radius_mm);
    let of_kind = KindIndex::new(input);
    let mut field: Option<NearestField> = start;
    for step in 0..level.iterations {
        level.control.check()?;
        level.control.report((level.done + step as f32) / level.steps);
        let mut search_settings = SearchSettings::new(radius_mm, delta_mm);
        search_settings.iterations = if step == 0 { 5 } else { 2 };
        search_settings.seed = rng.state() ^ step as u64;
        search_settings.element_unmatched_mm = similarity.element_unmatched_mm;
        // The output's, found once for the search and the votes that follow it.
        let output_near = Neighbourhoods::new(&output, radius_mm);
        let found = search((&output, &output_near), (input, &input_near), field.as_ref(), &search_settings);
        // Each pair is matched alone: in parallel.
        let pairs: Vec<MatchedPair> = (0..output.samples.len())
            .into_par_iter()
            .map(|o| {
                let members_o = output_near.members[o].clone();
                let centre_i = found.input_of[o];
                let members_i = input_near.members[centre_i as usize].clone();
                let pair = NeighbourhoodPair {
                    output: &output,
                    output_edges: &output_near.edges,
                    s_o: o,
                    members_o: &members_o,
                    input,
                    input_edges: &input_near.edges,
                    s_i: centre_i as usize,
                    members_i: &members_i,
                };
                let matching = pair.distance_below(&similarity, f64::INFINITY).expect("no bound to exceed");
                MatchedPair { centre_o: o as u32, members_o, centre_i, members_i, matching }
            })
            .collect();
        assign_positions(&mut output, input, &pairs, level.pinned, &project);
        let inside = |p: DVec2| p.cmpge(DVec2::ZERO).all() && p.cmple(size_mm).all() && level.mask.contains(p);
        let added = missing_samples(&output, input, &pairs, delta_mm, radius_mm, &inside);
        assign_edges(&mut output, input, &pairs, level.pinned);
        // Orientations only shape the reconstruction, which follows the
        // last step of the finest level; coarser levels' graphs are
        // sampled again from their paths, which keep none.
        if level.last && step + 1 == level.iterations {
            assign_orientations(&mut output, input, &pairs);
        }
        // Existence: samples matched in too few of the neighbourhoods
        // holding them go, with their place in the field.
        let keep: Vec<bool> = existence_votes(output.samples.len(), &pairs)
            .iter()
            .enumerate()
            .map(|(s, &i)| {
                s < level.pinned || (i >= MIN_EXISTENCE && level.mask.contains(output.samples[s].position_mm))
            })
            .collect();
        let mut kept = found;
        kept.retain(&keep);
        output.retain(&keep);
        // New samples join the field at random; the next search places them.
        for (p, kind) in added {
            output.add_of_kind(p, kind);
            kept.input_of.push(of_kind.random(kind, rng));
            kept.cost.push(f64::MAX);
        }
        field = Some(kept);
    }
    Ok(output)
}
