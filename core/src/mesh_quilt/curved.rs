//! Mesh quilting over a curved base (the paper's section 3.1). The base's
//! faces take the place of the plane's grid: the most constrained
//! unprocessed face seeds a patch grown along the surface, laid flat by
//! LSCM and turned to the guidance field; the swatch is matched over
//! translations in that flat frame, carried into the shell over the base,
//! and merged with what is there. Quilting ends when every face is covered.
//!
//! One departure from the paper: elements are kept in space (embedded in
//! the shell as each patch places them), not as face, barycentric
//! coordinates and height. Merging, deforming, stitching and the crossing
//! test then work where the print will be, and a thread that runs across
//! many patches never has to be laid flat whole again.

use std::sync::Mutex;

use rustc_hash::FxHashMap;

use glam::{DVec2, DVec3};

use super::faces::{ElementFaces, Faces};
use super::flat_cap::{FlatCap, FlatCaps, RIM_INSET_MM};
use super::matching::{Input, MARGIN_CELLS, Neighbourhood, Placement, best_translation, reach_mm, thin};
use super::merge::merge_patch;
use super::patch::{FaceGraph, Patch};
use super::shell::{Shell, ShellStretch};
use super::tear::{MAX_FOLD_DEG, MAX_STRETCH_SPREAD, largest_fold_deg, stretch_spread};
use super::zones::{Zone, Zones, boxes_overlap};
use super::{Element, GuidanceField, MAX_QUILT_TRIANGLES, Quilt, QuiltError, Settings, Swatch};
use crate::control::Control;
use crate::random::SplitMix64;
use crate::surface::{SurfaceMesh, SurfacePoint};

/// Tries at growing a patch, each smaller than the last, before a seed is
/// given up and left bare.
const PATCH_TRIES: usize = 6;

/// A model's faces are split until no edge is longer than this many grid
/// cells: no finer than the built-in models are for a swatch at scale 1
/// (their edges are at most 2.1 mm; a cell is 2.1 to 3.3 mm), so they are
/// left as they are.
const MAX_FACE_EDGE_CELLS: f64 = 2.0;

/// The width of the strip of faces along a crease sharper than
/// [`MAX_FOLD_DEG`] over which the shell fans out, mm.
const CREASE_STRIP_MM: f64 = 2.0;

/// How much smaller each try's patch is.
const PATCH_SHRINK: f64 = 0.7;

/// Cells around a patch's footprint whose faces' distances are kept:
/// merging asks how near the footprint a point is, up to a few cells.
const NEAR_CELLS: f64 = 4.0;

/// The step by which an element folding over a crease is moved off it, as
/// a share of its extent in the swatch's plane.
const CREASE_SHIFT: f64 = 0.1;

/// Patches of a swatch whose elements hang on each other keep to one side
/// of a crease sharper than this (the cosine of 35°, [`MAX_FOLD_DEG`]).
const CREASE_COS: f64 = 0.819;

/// How many steps an element folding over a crease may be moved: up to
/// 0.4 of its extent, so that it stays near where the swatch put it.
const CREASE_SHIFT_STEPS: usize = 4;

/// What the shell and the patches did, for the report.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShellReport {
    /// The shell offset along the base's normals.
    pub before: ShellStretch,
    /// The shell as used, tuned to the least stretch.
    pub after: ShellStretch,
    /// The largest area distortion of a patch laid flat.
    pub max_patch_distortion: f64,
    /// Seeds whose patch could not be laid flat at any size: left bare.
    pub bare_seeds: usize,
    /// Threads cut off at the rim of a flat top.
    pub cut_at_rim: usize,
    /// Threads on the side reaching up past a flat top's rim, cut off
    /// just under it.
    pub cut_under_rim: usize,
    /// Elements not laid because the shell would have folded them round a
    /// sharp crease or stretched them unevenly beside one (see
    /// [`MAX_FOLD_DEG`], [`MAX_STRETCH_SPREAD`]); threads running across
    /// the swatch bend and are laid.
    pub torn: usize,
}

/// Each asked point's closest point of the base, by the point's bits.
/// Merging asks both the zone and the nearness of the same vertices and
/// face centres several times over, and neighbourhoods ask again for the
/// same elements patch after patch; the query is the costliest part of
/// quilting a model. Elements only move where they are merged, and a moved
/// vertex is a new key.
struct Closest<'a> {
    surface: &'a SurfaceMesh,
    known: Mutex<FxHashMap<[u64; 3], SurfacePoint>>,
}

impl<'a> Closest<'a> {
    fn new(surface: &'a SurfaceMesh) -> Self {
        Closest { surface, known: Mutex::new(FxHashMap::default()) }
    }

    /// The base's closest point to `p`, remembered.
    fn point(&self, p: DVec3) -> SurfacePoint {
        let key = p.to_array().map(f64::to_bits);
        // A poisoned lock only means a panic elsewhere; the map is still sound.
        let mut known = self.known.lock().unwrap_or_else(|e| e.into_inner());
        *known.entry(key).or_insert_with(|| self.surface.closest_point(p.to_array()))
    }
}

/// The layout of the base for one patch: which faces are done, which the
/// patch claims, and how far each nearby face is from what it claims.
struct SurfaceZones<'a> {
    closest: &'a Closest<'a>,
    processed: &'a [bool],
    footprint: Vec<bool>,
    near: FxHashMap<u32, f64>,
    cell_mm: f64,
    near_box: (DVec3, DVec3),
}

impl Zones for SurfaceZones<'_> {
    fn cell_mm(&self) -> f64 {
        self.cell_mm
    }

    fn zone(&self, p: DVec3) -> Zone {
        let f = self.closest.point(p).face as usize;
        match (self.processed[f], self.footprint[f]) {
            (true, true) => Zone::Overlap,
            (true, false) => Zone::Old,
            (false, true) => Zone::New,
            (false, false) => Zone::Outside,
        }
    }

    fn near_footprint(&self, p: DVec3, cells: f64) -> bool {
        let f = self.closest.point(p).face;
        self.near.get(&f).is_some_and(|&d| d <= cells * self.cell_mm)
    }

    fn near_box(&self, margin_mm: f64) -> (DVec3, DVec3) {
        (self.near_box.0 - DVec3::splat(margin_mm), self.near_box.1 + DVec3::splat(margin_mm))
    }

    fn base(&self, p: DVec3) -> (DVec3, DVec3) {
        let on = self.closest.point(p);
        (on.position_mm, self.closest.surface.normal(on.face, on.barycentric))
    }

    fn model_below(&self) -> bool {
        true
    }
}

/// Quilts `surface` with `swatch` (already scaled) in a shell as thick as
/// the swatch, its bottom `settings.sink_mm` inside the model, the
/// swatch's `u` axis turned along `field` at each patch's seed. Faces the model stands on (facing down at its lowest
/// level) are left bare, so it still stands flat.
pub fn quilt_surface(
    swatch: &Swatch,
    surface: &SurfaceMesh,
    field: &GuidanceField,
    settings: &Settings,
    control: &Control,
) -> Result<Quilt, QuiltError> {
    settings.validate()?;
    if field.len() != surface.triangles().len() {
        return Err(QuiltError::BadField(format!(
            "it was made for a model of {} faces, not this one of {}",
            field.len(),
            surface.triangles().len()
        )));
    }
    let size = swatch.size_mm();
    let estimate = (swatch.triangle_count() as f64 * surface.area_mm2() / (size.x * size.y)) as usize;
    if estimate > MAX_QUILT_TRIANGLES {
        return Err(QuiltError::OutputTooLarge { triangles: estimate, max: MAX_QUILT_TRIANGLES });
    }
    let cell_mm = size.x.min(size.y) / settings.cells_across as f64;
    // A model drawn in CAD has few, long faces (a box has 12). Patches grow
    // face by face, and a patch claims the faces whose middle its cells
    // cover, so on faces many cells wide chain mail came out as a tangle
    // and a flat sheet of two faces as two blocks. Such faces are split
    // first; the built-in models' faces are smaller and left as they are.
    let split = surface.split_to(MAX_FACE_EDGE_CELLS * cell_mm);
    let (surface, field) = match &split {
        Some((fine, parents)) => (fine, field.on_split_faces(parents)),
        None => (surface, field.clone()),
    };
    // The shell fans out over the faces that touch a crease (its offset
    // directions are one per vertex), and bent the elements there: chain
    // mail's rings by a box's edge came out as hearts. Those faces are
    // split into a narrow strip.
    let creased = surface.split_along_creases(MAX_FOLD_DEG, CREASE_STRIP_MM);
    let (surface, field) = match &creased {
        Some((fine, parents)) => (fine, field.on_split_faces(parents)),
        None => (surface, field),
    };
    // Which of the swatch's elements may bend round a crease: threads at
    // least half as long as the swatch's shorter side.
    let bends: Vec<bool> = swatch
        .elements
        .iter()
        .map(|e| {
            let (lo, hi) = e.bounds();
            e.is_thread() && (hi - lo).truncate().max_element() >= 0.5 * size.x.min(size.y)
        })
        .collect();
    // A swatch whose elements hang on each other (chain mail's flat rings,
    // held up by the links through them) holds together only where each
    // patch's elements meet the last's exactly. Its patches keep to one
    // side of a crease: a patch run over the rim of a top narrower than
    // the swatch (not a cap of its own) was laid flat with the side's
    // lattice bent by up to four times in area, and the next patch's links
    // met the last's millimetres off. Other swatches' patches still run
    // over a rim, and their elements are moved off it (`off_the_crease`),
    // or, threads, bend round it.
    let interlocked = swatch.least_float_mm().is_some() && !bends.contains(&true);
    // Rows can follow a circle round the axis about as tight as the swatch
    // is wide; across a cap they lie straight (see `with_straight_caps`).
    // An interlocked swatch's patches keep to the top (above), so a top of
    // any width is straight for it: round, the rows turned from one patch
    // to the next and the cylinder's top, narrower than the swatch, was a
    // heap of rings.
    let turn_radius_mm = size.x.hypot(size.y);
    let least_across_mm = if interlocked { 0.0 } else { turn_radius_mm };
    let field = &field.with_straight_caps(surface, turn_radius_mm, least_across_mm);
    let triangles = surface.triangles();
    let input = Input::new(swatch, cell_mm);
    let reach = reach_mm(swatch);
    let graph = FaceGraph::new(surface);
    let before = Shell::along_normals(surface, size.z).stretch(surface);
    let shell = Shell::least_stretch(surface, size.z, settings.seed);
    let mut report = ShellReport {
        before,
        after: shell.stretch(surface),
        max_patch_distortion: 1.0,
        bare_seeds: 0,
        cut_at_rim: 0,
        cut_under_rim: 0,
        torn: 0,
    };
    let lowest = surface.positions().iter().map(|p| p.z).fold(f64::INFINITY, f64::min);
    let mut processed: Vec<bool> = (0..triangles.len() as u32)
        .map(|f| surface.face_normal(f).z < -0.9 && graph.centres[f as usize].z < lowest + 0.5 * cell_mm)
        .collect();
    let standing = processed.clone();
    let (sx, sy) = input.cells;
    let half = input.window_half();
    let radius_mm = (sx as f64).hypot(sy as f64) * cell_mm + 2.0 * reach;
    let mut random = SplitMix64::new(settings.seed);
    let mut quilt = Quilt::default();
    let mut output_faces = ElementFaces::default();
    let total = processed.len() as f32;
    let closest = Closest::new(surface);
    // The seed sits at the middle of cell (0, 0) of its patch.
    let seed_uv = DVec2::splat(0.5 * cell_mm);
    // The swatch's height 0 lies this far inside the model (see `Settings::sink_mm`).
    let sink_mm = settings.sink_mm;
    // Prisms past anything an element laid on a cap can reach.
    let caps = FlatCaps::new(surface, field, &graph, sink_mm + size.z, 2.0 * size.z);
    let fragment_mm3 = swatch.fragment_volume_mm3();
    while let Some(seed) = most_constrained(&graph, &processed) {
        control.check()?;
        let Some(patch) = grow_patch(surface, &graph, seed, field, (radius_mm, interlocked), seed_uv, &mut report)
        else {
            processed[seed as usize] = true;
            report.bare_seeds += 1;
            continue;
        };
        let to_output = |p: DVec3, n: DVec3| -> Option<(DVec3, DVec3)> {
            let (f, b) = patch.locate(p.truncate())?;
            let normal = surface.face_normal(f);
            let u = patch.u_axis(f)?;
            let v = normal.cross(u);
            Some((shell.point(surface, f, b, p.z - sink_mm), (u * n.x + v * n.y + normal * n.z).normalize_or_zero()))
        };
        let window: Vec<(i64, i64)> = (-half..=half)
            .flat_map(|dj| (-half..=half).map(move |di| (di, dj)))
            .filter(|&(i, j)| {
                let centre = DVec2::new(i as f64 + 0.5, j as f64 + 0.5) * cell_mm;
                patch.locate(centre).is_some_and(|(f, _)| processed[f as usize])
            })
            .collect();
        let around = neighbourhood(&closest, &patch, &quilt.elements, &window, cell_mm, sink_mm);
        let (_, _, placement) =
            best_translation(&input, &around, (0, 0), settings, reach, to_output, (true, interlocked), &mut random);
        // The swatch's cells it claims, in the swatch's own frame.
        let claimed = (
            DVec2::splat(MARGIN_CELLS as f64) * cell_mm,
            DVec2::new((sx - MARGIN_CELLS) as f64, (sy - MARGIN_CELLS) as f64) * cell_mm,
        );
        let mut footprint = vec![false; triangles.len()];
        let mut claimed_faces = vec![seed];
        for &f in patch.faces() {
            let centre = patch
                .to_flat(f, [1.0 / 3.0; 3])
                .map_or(DVec2::INFINITY, |p| placement.to_swatch(p.extend(0.0)).truncate());
            if centre.cmpge(claimed.0).all() && centre.cmplt(claimed.1).all() {
                claimed_faces.push(f);
            }
        }
        for &f in &claimed_faces {
            footprint[f as usize] = true;
        }
        let near: FxHashMap<u32, f64> =
            graph.within(&claimed_faces, (NEAR_CELLS + reach / cell_mm) * cell_mm).into_iter().collect();
        let near_box = claimed_faces.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &f| {
            let p = graph.centres[f as usize];
            (lo.min(p), hi.max(p))
        });
        let grow = DVec3::splat(size.z + cell_mm);
        let zones = SurfaceZones {
            closest: &closest,
            processed: &processed,
            footprint,
            near,
            cell_mm,
            near_box: (near_box.0 - grow, near_box.1 + grow),
        };
        let cap = caps.of_face(seed);
        let mut placed: Vec<Element> = Vec::new();
        for (k, e) in swatch.elements.iter().enumerate() {
            // The element laid on the patch moved by `shift_mm` in its flat
            // frame: each vertex in the shell, and the face under it.
            let lay = |shift_mm: DVec2| -> Option<Vec<(DVec3, u32)>> {
                e.vertices
                    .iter()
                    .map(|&v| {
                        let q = placement.to_frame(v);
                        let (f, b) = patch.locate(q.truncate() + shift_mm)?;
                        Some((shell.point(surface, f, b, q.z - sink_mm), f))
                    })
                    .collect()
            };
            // What lies under the floor, or over the faces the model stands
            // on, is cut off at the floor (`foot`): it does not count.
            let folds = |on_patch: &[(DVec3, u32)]| {
                let vertices: Vec<DVec3> = on_patch.iter().map(|&(p, _)| p).collect();
                let normals: Vec<DVec3> = on_patch.iter().map(|&(_, f)| surface.face_normal(f)).collect();
                let kept = |k: usize| vertices[k].z > lowest && !standing[on_patch[k].1 as usize];
                largest_fold_deg(e, &normals, kept) > MAX_FOLD_DEG
                    || stretch_spread(e, &vertices, kept) > MAX_STRETCH_SPREAD
            };
            if let Some(on_patch) = lay(DVec2::ZERO) {
                // A thread running across the swatch may bend: it is cut
                // and stitched to its neighbours, and one bent round a rim
                // is cut there. A short one (a leaf) is laid whole, as a
                // compact element is, or moved off the crease.
                let on_patch = if !bends[k] && folds(&on_patch) {
                    match off_the_crease(e, lay, folds) {
                        Some(moved) => moved,
                        None => {
                            report.torn += 1;
                            continue;
                        }
                    }
                } else {
                    on_patch
                };
                let vertices: Vec<DVec3> = on_patch.iter().map(|&(p, _)| p).collect();
                placed.push(Element { vertices, triangles: e.triangles.clone() });
            } else if let Some(cap) = cap {
                // Past the patch's edge on a flat cap: laid whole in its
                // plane, then fitted to the rim (see `flat_cap`).
                let vertices = e
                    .vertices
                    .iter()
                    .map(|&v| {
                        let q = placement.to_frame(v);
                        patch.on_seed_plane(surface, q.truncate()) + cap.normal() * (q.z - sink_mm)
                    })
                    .collect();
                let fitted = cap.fit(Element { vertices, triangles: e.triangles.clone() }, fragment_mm3);
                report.cut_at_rim += usize::from(fitted.cut);
                placed.extend(fitted.pieces);
            } else if let Some(pieces) =
                past_rim(e, &patch, &placement, &caps, (&shell, surface), sink_mm, fragment_mm3)
            {
                report.cut_under_rim += 1;
                placed.extend(pieces);
            }
        }
        let counts = merge_patch(&mut quilt.elements, &mut output_faces, placed, &zones, settings, reach);
        quilt.counts.merges.add(&counts);
        for &f in &claimed_faces {
            processed[f as usize] = true;
        }
        quilt.counts.patches += 1;
        control.report(processed.iter().filter(|&&p| p).count() as f32 / total);
    }
    report.cut_at_rim += caps.trim_overhangs(&mut quilt.elements, sink_mm + size.z, fragment_mm3);
    super::planar::keep_whole(&mut quilt, swatch);
    quilt.shell = Some(report);
    Ok(quilt)
}

/// A thread of the swatch, laid by `placement` on a patch of the side,
/// that reaches past the patch's edge only up past a flat top's rim: the
/// part past the edge carried on along the side's last faces, and the
/// whole cut off flat under the top's plane, by the sink and
/// [`RIM_INSET_MM`] (clear of the top's own threads, sunk that deep).
/// Before, such a thread was left out, and the side's last few mm under
/// the rim had few threads running up it. `None` for an element that is
/// not a thread or that reaches past the patch elsewhere.
fn past_rim(
    e: &Element,
    patch: &Patch,
    placement: &Placement,
    caps: &FlatCaps,
    (shell, surface): (&Shell, &SurfaceMesh),
    sink_mm: f64,
    fragment_mm3: f64,
) -> Option<Vec<Element>> {
    if !e.is_thread() {
        return None;
    }
    let margin_mm = {
        let (lo, hi) = e.bounds();
        (hi - lo).length()
    };
    let mut cap = None;
    let mut vertices = Vec::with_capacity(e.vertices.len());
    for &v in &e.vertices {
        let q = placement.to_frame(v);
        if let Some((f, b)) = patch.locate(q.truncate()) {
            vertices.push(shell.point(surface, f, b, q.z - sink_mm));
            continue;
        }
        let (on, normal) = patch.carried_on(surface, q.truncate());
        let above = caps.above(on, margin_mm)?;
        if cap.is_some_and(|c: &FlatCap| !std::ptr::eq(c, above)) {
            return None;
        }
        cap = Some(above);
        vertices.push(on + normal * (q.z - sink_mm));
    }
    let element = Element { vertices, triangles: e.triangles.clone() };
    Some(cap?.cut_under(&element, sink_mm + RIM_INSET_MM, fragment_mm3))
}

/// The unprocessed face with the most processed faces within two steps
/// across edges; the first face when none is processed.
fn most_constrained(graph: &FaceGraph, processed: &[bool]) -> Option<u32> {
    let mut best: Option<(u32, usize)> = None;
    for f in 0..processed.len() {
        if processed[f] {
            continue;
        }
        let ring = &graph.neighbours[f];
        let mut score = ring.iter().filter(|&&g| processed[g as usize]).count();
        if score > 0 {
            score += ring
                .iter()
                .flat_map(|&g| graph.neighbours[g as usize].iter())
                .filter(|&&h| h as usize != f && processed[h as usize])
                .count();
        }
        if best.is_none_or(|(_, s)| score > s) {
            best = Some((f as u32, score));
        }
    }
    best.map(|(f, _)| f)
}

/// The patch around `seed`, within `radius_mm` and, when
/// `keep_off_creases`, on the seed's side of every crease sharper than
/// [`CREASE_COS`]; shrunk until it lays flat within the limits.
fn grow_patch(
    surface: &SurfaceMesh,
    graph: &FaceGraph,
    seed: u32,
    field: &GuidanceField,
    (radius_mm, keep_off_creases): (f64, bool),
    seed_uv: DVec2,
    report: &mut ShellReport,
) -> Option<Patch> {
    let mut radius = radius_mm;
    for _ in 0..PATCH_TRIES {
        // A patch keeps to its side of a straight cap's rim: the field jumps
        // there, and a swatch laid across it would run the wrong way on the
        // far side (see `GuidanceField::with_straight_caps`).
        let faces: Vec<u32> = graph
            .within_where(&[seed], radius, |f, g| {
                !keep_off_creases || surface.face_normal(f).dot(surface.face_normal(g)) >= CREASE_COS
            })
            .into_iter()
            .map(|(f, _)| f)
            .filter(|&f| field.on_cap(f) == field.on_cap(seed))
            .collect();
        if let Ok(patch) = Patch::lay_flat(surface, faces, seed, field, seed_uv) {
            report.max_patch_distortion = report.max_patch_distortion.max(patch.distortion);
            return Some(patch);
        }
        radius *= PATCH_SHRINK;
    }
    None
}

/// The output around the seed in the patch's flat frame: its vertices over
/// the window's cells, sampled, and its faces near the patch (in space).
/// Heights are measured from the shell's bottom, `sink_mm` inside the model,
/// as the swatch's are.
fn neighbourhood<'a>(
    closest: &Closest<'_>,
    patch: &Patch,
    output: &[Element],
    window: &'a [(i64, i64)],
    cell_mm: f64,
    sink_mm: f64,
) -> Neighbourhood<'a> {
    let surface = closest.surface;
    let faces: Vec<DVec3> = window
        .iter()
        .filter_map(|&(i, j)| {
            let (f, b) = patch.locate(DVec2::new(i as f64 + 0.5, j as f64 + 0.5) * cell_mm)?;
            Some(surface.point(f, b))
        })
        .collect();
    let window_box = faces.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let grow = DVec3::splat(2.0 * cell_mm);
    let window_box = (window_box.0 - grow, window_box.1 + grow);
    let near: Vec<&Element> = output.iter().filter(|e| boxes_overlap(e.bounds(), window_box)).collect();
    let mut samples: Vec<(DVec3, DVec3)> = Vec::new();
    for e in &near {
        for (&p, n) in e.vertices.iter().zip(e.vertex_normals()) {
            let on = closest.point(p);
            let Some(flat) = patch.to_flat(on.face, on.barycentric) else { continue };
            let cell = ((flat.x / cell_mm).floor() as i64, (flat.y / cell_mm).floor() as i64);
            if !window.contains(&cell) {
                continue;
            }
            let normal = surface.face_normal(on.face);
            let Some(u) = patch.u_axis(on.face) else { continue };
            let v = normal.cross(u);
            let height = (p - on.position_mm).dot(normal) + sink_mm;
            samples.push((flat.extend(height), DVec3::new(n.dot(u), n.dot(v), n.dot(normal))));
        }
    }
    Neighbourhood { window, samples: thin(samples), faces: Faces::new(near.iter().copied()) }
}

/// A compact element that would fold over a crease, laid instead at the
/// nearest of a few shifts in its patch's flat frame (up to
/// [`CREASE_SHIFT_STEPS`] steps of [`CREASE_SHIFT`] of its extent, in
/// eight directions) where it lies whole on one side of the crease, and
/// one step farther where that clears it too. Left out, such elements
/// left a bare band round every rim; moved a little, most of them fit
/// beside it. The element moves rigidly in the flat frame, so it stays the
/// swatch's. None when no shift clears the crease.
fn off_the_crease(
    element: &Element,
    lay: impl Fn(DVec2) -> Option<Vec<(DVec3, u32)>>,
    folds: impl Fn(&[(DVec3, u32)]) -> bool,
) -> Option<Vec<(DVec3, u32)>> {
    let (lo, hi) = element.footprint();
    let step_mm = CREASE_SHIFT * (hi - lo).max_element();
    let at = |d: usize, steps: usize| {
        let shift_mm = DVec2::from_angle(d as f64 * std::f64::consts::FRAC_PI_4) * steps as f64 * step_mm;
        lay(shift_mm).filter(|on_patch| !folds(on_patch))
    };
    (1..=CREASE_SHIFT_STEPS).find_map(|ring| {
        (0..8).find_map(|d| {
            let first = at(d, ring)?;
            // Just clear of the crease, the shell's spread at a rim still
            // lifts the element's upper side past it (scales stood over
            // the cylinder's rim): one step more, where that clears too.
            Some(at(d, ring + 1).unwrap_or(first))
        })
    })
}
