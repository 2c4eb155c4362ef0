//! Planar mesh quilting (the paper's section 2): the output grows patch by
//! patch from the most constrained grid cell; each patch is the swatch at
//! the translation that best matches what is already there, merged in
//! element by element.

use glam::{DVec2, DVec3};

use super::curved::ShellReport;
use super::faces::{ElementFaces, Faces};
use super::matching::{Input, MARGIN_CELLS, Neighbourhood, best_translation, reach_mm, thin};
use super::merge::{MergeCounts, merge_patch};
use super::zones::{Zone, Zones};
use super::{Element, QuiltError, Settings, Swatch};
use crate::control::Control;
use crate::random::SplitMix64;

/// The most triangles a quilt may have.
pub const MAX_QUILT_TRIANGLES: usize = 4_000_000;

/// What quilting made.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Quilt {
    /// The output elements, each closed.
    pub elements: Vec<Element>,
    /// What happened on the way.
    pub counts: QuiltCounts,
    /// The shell's stretch and the patches' distortion, on a curved base.
    pub shell: Option<ShellReport>,
}

/// Counts of what quilting did, for reports and tests.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuiltCounts {
    /// Patches placed.
    pub patches: usize,
    /// Element merges: copied whole, replaced, stitched, and stitches given up.
    pub merges: MergeCounts,
    /// Elements left out at the end because they lay mostly outside the area.
    pub outside: usize,
    /// Fragments removed at the end: pieces far smaller than any swatch element.
    pub fragments: usize,
}

/// The output's grid and the patch being merged.
pub(super) struct Grid {
    cell_mm: f64,
    nx: i64,
    ny: i64,
    processed: Vec<bool>,
    /// The patch's claimed cells, `[low, high)` in cells.
    footprint: [i64; 4],
}

impl Grid {
    fn cell(&self, p: DVec2) -> (i64, i64) {
        ((p.x / self.cell_mm).floor() as i64, (p.y / self.cell_mm).floor() as i64)
    }

    fn inside(&self, (i, j): (i64, i64)) -> bool {
        (0..self.nx).contains(&i) && (0..self.ny).contains(&j)
    }

    fn is_processed(&self, c: (i64, i64)) -> bool {
        self.inside(c) && self.processed[(c.1 * self.nx + c.0) as usize]
    }

    fn in_footprint(&self, (i, j): (i64, i64)) -> bool {
        let [i0, j0, i1, j1] = self.footprint;
        self.inside((i, j)) && (i0..i1).contains(&i) && (j0..j1).contains(&j)
    }

    /// The unprocessed cell with the most processed neighbours.
    fn seed(&self) -> Option<(i64, i64)> {
        let mut best: Option<((i64, i64), usize)> = None;
        for j in 0..self.ny {
            for i in 0..self.nx {
                if self.is_processed((i, j)) {
                    continue;
                }
                let around = (-1..=1)
                    .flat_map(|dj| (-1..=1).map(move |di| (i + di, j + dj)))
                    .filter(|&c| self.is_processed(c))
                    .count();
                if best.is_none_or(|(_, n)| around > n) {
                    best = Some(((i, j), around));
                }
            }
        }
        best.map(|(c, _)| c)
    }
}

impl Zones for Grid {
    fn cell_mm(&self) -> f64 {
        self.cell_mm
    }

    fn near_footprint(&self, p: DVec3, cells: f64) -> bool {
        let [i0, j0, i1, j1] = self.footprint;
        let (x, y) = (p.x / self.cell_mm, p.y / self.cell_mm);
        x >= i0 as f64 - cells && x <= i1 as f64 + cells && y >= j0 as f64 - cells && y <= j1 as f64 + cells
    }

    fn zone(&self, p: DVec3) -> Zone {
        let c = self.cell(p.truncate());
        match (self.is_processed(c), self.in_footprint(c)) {
            (true, true) => Zone::Overlap,
            (true, false) => Zone::Old,
            (false, true) => Zone::New,
            (false, false) => Zone::Outside,
        }
    }

    fn near_box(&self, margin_mm: f64) -> (DVec3, DVec3) {
        let [i0, j0, i1, j1] = self.footprint;
        let c = self.cell_mm;
        (
            DVec3::new(i0 as f64 * c - margin_mm, j0 as f64 * c - margin_mm, f64::NEG_INFINITY),
            DVec3::new(i1 as f64 * c + margin_mm, j1 as f64 * c + margin_mm, f64::INFINITY),
        )
    }

    fn base(&self, p: DVec3) -> (DVec3, DVec3) {
        (p.with_z(0.0), DVec3::Z)
    }

    fn model_below(&self) -> bool {
        false
    }
}

/// Quilts a `width_mm` × `depth_mm` area of the plane with `swatch`
/// (already scaled), from `(0, 0)`.
pub fn quilt_plane(
    swatch: &Swatch,
    width_mm: f64,
    depth_mm: f64,
    settings: &Settings,
    control: &Control,
) -> Result<Quilt, QuiltError> {
    settings.validate()?;
    crate::setting::positive_mm("base", "the width", width_mm)?;
    crate::setting::positive_mm("base", "the depth", depth_mm)?;
    let size = swatch.size_mm();
    let estimate = (swatch.triangle_count() as f64 * width_mm * depth_mm / (size.x * size.y)) as usize;
    if estimate > MAX_QUILT_TRIANGLES {
        return Err(QuiltError::OutputTooLarge { triangles: estimate, max: MAX_QUILT_TRIANGLES });
    }
    let cell_mm = size.x.min(size.y) / settings.cells_across as f64;
    let input = Input::new(swatch, cell_mm);
    let mut grid = Grid {
        cell_mm,
        nx: (width_mm / cell_mm).ceil() as i64,
        ny: (depth_mm / cell_mm).ceil() as i64,
        processed: Vec::new(),
        footprint: [0; 4],
    };
    grid.processed = vec![false; (grid.nx * grid.ny) as usize];
    let reach_mm = reach_mm(swatch);
    let (sx, sy) = input.cells;
    let half = input.window_half();
    let mut random = SplitMix64::new(settings.seed);
    let mut quilt = Quilt::default();
    let mut output_faces = ElementFaces::default();
    let total = grid.processed.len() as f32;
    while let Some(seed) = grid.seed() {
        control.check()?;
        let window: Vec<(i64, i64)> = (-half..=half)
            .flat_map(|dj| (-half..=half).map(move |di| (seed.0 + di, seed.1 + dj)))
            .filter(|&c| grid.is_processed(c))
            .collect();
        let around = neighbourhood(&quilt.elements, &grid, &window);
        let to_output = |p: DVec3, n: DVec3| Some((p, n));
        let (a, b, offset) =
            best_translation(&input, &around, seed, settings, reach_mm, to_output, (false, false), &mut random);
        grid.footprint = [a + MARGIN_CELLS, b + MARGIN_CELLS, a + sx - MARGIN_CELLS, b + sy - MARGIN_CELLS];
        let placed: Vec<Element> = swatch.elements.iter().map(|e| e.translated(offset.offset_mm.extend(0.0))).collect();
        let counts = merge_patch(&mut quilt.elements, &mut output_faces, placed, &grid, settings, reach_mm);
        quilt.counts.merges.add(&counts);
        let [i0, j0, i1, j1] = grid.footprint;
        for j in j0.max(0)..j1.min(grid.ny) {
            for i in i0.max(0)..i1.min(grid.nx) {
                grid.processed[(j * grid.nx + i) as usize] = true;
            }
        }
        quilt.counts.patches += 1;
        control.report(grid.processed.iter().filter(|&&p| p).count() as f32 / total);
    }
    finish(&mut quilt, swatch, width_mm, depth_mm);
    Ok(quilt)
}

/// The output around the seed: its vertices in the window, sampled, and
/// its faces for the reverse term.
fn neighbourhood<'a>(output: &[Element], grid: &Grid, window: &'a [(i64, i64)]) -> Neighbourhood<'a> {
    let in_window = |p: DVec3| window.contains(&grid.cell(p.truncate()));
    let window_box = window_box(window, grid.cell_mm);
    let near: Vec<&Element> = output.iter().filter(|e| overlaps(e.footprint(), window_box)).collect();
    let mut samples: Vec<(DVec3, DVec3)> = Vec::new();
    for e in &near {
        samples.extend(e.vertices.iter().zip(e.vertex_normals()).filter(|(v, _)| in_window(**v)).map(|(v, n)| (*v, n)));
    }
    Neighbourhood { window, samples: thin(samples), faces: Faces::new(near.iter().copied()) }
}

fn window_box(window: &[(i64, i64)], c: f64) -> (DVec2, DVec2) {
    window.iter().fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &(i, j)| {
        (lo.min(DVec2::new(i as f64, j as f64) * c), hi.max(DVec2::new((i + 1) as f64, (j + 1) as f64) * c))
    })
}

/// Whether two boxes seen from above overlap.
fn overlaps(a: (DVec2, DVec2), b: (DVec2, DVec2)) -> bool {
    a.0.x <= b.1.x && b.0.x <= a.1.x && a.0.y <= b.1.y && b.0.y <= a.1.y
}

/// Leaves out elements lying mostly outside the area, open ones, and
/// fragments far smaller than the swatch's smallest element.
fn finish(quilt: &mut Quilt, swatch: &Swatch, width_mm: f64, depth_mm: f64) {
    let before = quilt.elements.len();
    quilt.elements.retain(|e| {
        let (lo, hi) = e.footprint();
        let centre = 0.5 * (lo + hi);
        (0.0..=width_mm).contains(&centre.x) && (0.0..=depth_mm).contains(&centre.y)
    });
    quilt.counts.outside = before - quilt.elements.len();
    // Deformation may push a stitched element a hair out of the shell the
    // swatch filled; it goes back in, so what sat on the base still does.
    let height = swatch.size_mm().z;
    for e in &mut quilt.elements {
        for v in &mut e.vertices {
            v.z = v.z.clamp(0.0, height);
        }
    }
    keep_whole(quilt, swatch);
}

/// Leaves out open elements and fragments far smaller than the swatch's
/// smallest element.
pub(super) fn keep_whole(quilt: &mut Quilt, swatch: &Swatch) {
    let least_mm3 = swatch.fragment_volume_mm3();
    let before = quilt.elements.len();
    quilt.elements.retain(|e| e.is_closed() && e.to_mesh().signed_volume().abs() >= least_mm3);
    quilt.counts.fragments = before - quilt.elements.len();
}
