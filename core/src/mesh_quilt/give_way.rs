//! Giving way: an element that would cross others where it goes in is bent,
//! at each place it crosses them, over or under them along the base's
//! normal, as a thread in a weave passes over or under another.
//!
//! Threads laid by a new patch meet the threads already there at the
//! right angle, but with the over-and-under out of step where the two
//! patches' swatches disagree: both pass a crossing at the same height.
//! Left out, such a thread leaves a gap in the weave; moved up or down by
//! a thread's thickness where it crosses, it is what a weaver would make.

use glam::DVec3;

use super::Element;
use super::deform::{Constraint, deform};
use super::faces::Faces;
use super::zones::Zones;

/// How strongly a crossing's section is held to its new height, against
/// the Laplacian keeping the element's shape: enough that the section goes
/// nearly all the way, and the next round finishes it.
const LIFT_WEIGHT: f64 = 10.0;

/// Cells beyond a crossing over which the element bends back to where it
/// was; farther vertices stay put.
const BEND_CELLS: f64 = 1.5;

/// How far below its lowest point an element may dip into a model, as a
/// share of its height: a thread passing under another where both were at
/// their lowest sinks into the model there rather than being left out
/// (0.74 mm for the weave at scale 0.6, with the sink 1.04 mm below the
/// surface: a wall thinner than that would show it inside). On a plane the
/// bed lies below, and nothing goes lower.
const DIP: f64 = 0.3;

/// How far above its highest point an element may rise, as a share of its
/// height: a thread passing over another where both were at their highest
/// rises by a thread's thickness, as in cloth. The section across a
/// crossing moves as one piece, so where it takes in the thread's crest
/// it must rise by the other thread's thickness, the gap and more. Half
/// the height (1.25 mm for the weave at scale 0.6) was less than a
/// thread's thickness and the gap (1.33 mm): such a thread could never
/// pass over, and 227 of the 259 elements left out of the vase's weave
/// were left out for want of room. The whole height (2.52 mm) was room
/// enough to pass over a thread that had itself passed over another: such
/// threads stood off the model in loops up to twice the weave's height,
/// plain on the vase's outline. 0.6 (1.51 mm) passes over one thread:
/// on the vase's weave (seeds 1–3) elements reaching more than 1.5 heights
/// off the model 36/29/46 → 6/7/6, left out for crossing 144/165/197 →
/// 188/215/166, and the base's share over 1 mm from any thread 0.122/
/// 0.142/0.135 → 0.136/0.134/0.134.
const HEADROOM: f64 = 0.6;

/// The heights above the base, mm, between which `element` may be bent
/// (see [`DIP`] and [`HEADROOM`]). Taken once, before the first round, so
/// rounds do not add up.
pub(super) fn allowed_heights(element: &Element, zones: &impl Zones) -> (f64, f64) {
    let (low_mm, high_mm) = element
        .vertices
        .iter()
        .map(|&v| height_above(zones, v))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), h| (lo.min(h), hi.max(h)));
    let dip = if zones.model_below() { DIP } else { 0.0 };
    (low_mm - dip * (high_mm - low_mm), high_mm + HEADROOM * (high_mm - low_mm))
}

fn height_above(zones: &impl Zones, p: DVec3) -> f64 {
    let (foot, up) = zones.base(p);
    (p - foot).dot(up)
}

/// `element` bent over or under the elements whose faces are `others` at
/// each place it comes within
/// its mean edge length of them, one round of bending; only vertices
/// `movable` says may move. None when nothing is near, when a crossing
/// cannot be passed within the heights `allowed_mm` (from
/// [`allowed_heights`]), or when the solve fails. The caller checks the
/// result.
pub(super) fn give_way(
    element: &Element,
    others: &[&Faces],
    zones: &impl Zones,
    allowed_mm: (f64, f64),
    movable: impl Fn(DVec3) -> bool,
) -> Option<Element> {
    let gap_mm = element.mean_edge_mm();
    let cell_mm = zones.cell_mm();
    // Vertices inside another element, or nearer it than the gap.
    let touching: Vec<bool> = element
        .vertices
        .iter()
        .map(|&v| {
            others.iter().any(|o| {
                o.closest_within(v, cell_mm)
                    .is_some_and(|hit| hit.distance_mm < gap_mm || (v - hit.point_mm).dot(hit.normal) < 0.0)
            })
        })
        .collect();
    let crossings = clusters(element, &touching);
    if crossings.is_empty() {
        return None;
    }
    let mut constraints = Vec::new();
    let mut bending = vec![false; element.vertices.len()];
    for crossing in &crossings {
        let centre = crossing.iter().map(|&v| element.vertices[v as usize]).sum::<DVec3>() / crossing.len() as f64;
        let (_, up) = zones.base(centre);
        let lateral = |p: DVec3| {
            let d = p - centre;
            (d - d.dot(up) * up).length()
        };
        let radius_mm = crossing.iter().map(|&v| lateral(element.vertices[v as usize])).fold(0.0, f64::max) + gap_mm;
        let reach_mm = radius_mm + 2.0 * cell_mm;
        // The element's whole section there moves, not just the faces that
        // touch.
        let section: Vec<u32> = (0..element.vertices.len() as u32)
            .filter(|&v| {
                let p = element.vertices[v as usize];
                p.distance(centre) <= reach_mm && lateral(p) <= radius_mm
            })
            .collect();
        // How far the section must go up to pass over the others, and down
        // to pass under: along the normal from each of its vertices to
        // where the others end, and the gap beyond.
        let clear = |direction: DVec3| {
            section
                .iter()
                .map(|&v| {
                    let p = element.vertices[v as usize];
                    let t = others.iter().map(|o| o.last_hit_along(p, direction, reach_mm)).fold(0.0, f64::max);
                    if t > 0.0 { t + gap_mm } else { 0.0 }
                })
                .fold(0.0, f64::max)
        };
        let (over, under) = (clear(up), -clear(-up));
        let (section_low, section_high) = section
            .iter()
            .map(|&v| height_above(zones, element.vertices[v as usize]))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), h| (lo.min(h), hi.max(h)));
        let fits = |shift: f64| section_low + shift >= allowed_mm.0 && section_high + shift <= allowed_mm.1;
        // The smaller move that keeps the element inside its heights.
        let shift =
            [over, under].into_iter().filter(|&s| s != 0.0 && fits(s)).min_by(|a, b| a.abs().total_cmp(&b.abs()))?;
        constraints.extend(section.iter().map(|&v| Constraint {
            vertex: v,
            target_mm: element.vertices[v as usize] + shift * up,
            weight: LIFT_WEIGHT,
        }));
        let bend_mm = radius_mm + BEND_CELLS * cell_mm;
        for (v, p) in element.vertices.iter().enumerate() {
            if p.distance(centre) <= reach_mm + BEND_CELLS * cell_mm && lateral(*p) <= bend_mm {
                bending[v] = true;
            }
        }
    }
    let mut bent = element.clone();
    let fixed = |v: u32| !bending[v as usize] || !movable(element.vertices[v as usize]);
    deform(&mut bent, &constraints, fixed).then_some(bent)
}

/// The connected groups of `element`'s vertices that `marked` says.
fn clusters(element: &Element, marked: &[bool]) -> Vec<Vec<u32>> {
    let ring = element.neighbours();
    let mut seen = vec![false; marked.len()];
    let mut out = Vec::new();
    for start in 0..marked.len() {
        if !marked[start] || seen[start] {
            continue;
        }
        seen[start] = true;
        let mut group = vec![start as u32];
        let mut k = 0;
        while k < group.len() {
            for &n in &ring[group[k] as usize] {
                if marked[n as usize] && !seen[n as usize] {
                    seen[n as usize] = true;
                    group.push(n);
                }
            }
            k += 1;
        }
        out.push(group);
    }
    out
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::super::builtin_swatch;
    use super::super::faces::ElementFaces;
    use super::super::merge::admit;
    use super::super::self_crossing::crosses_itself;
    use super::super::zones::{Zone, Zones};
    use super::Element;

    /// A plane whose every point is new to the patch, in cells of 2 mm, on
    /// the print bed.
    struct Flat;

    impl Zones for Flat {
        fn cell_mm(&self) -> f64 {
            2.0
        }
        fn zone(&self, _: DVec3) -> Zone {
            Zone::New
        }
        fn near_footprint(&self, _: DVec3, _: f64) -> bool {
            true
        }
        fn near_box(&self, _: f64) -> (DVec3, DVec3) {
            (DVec3::NEG_INFINITY, DVec3::INFINITY)
        }
        fn base(&self, p: DVec3) -> (DVec3, DVec3) {
            (p.with_z(0.0), DVec3::Z)
        }
        fn model_below(&self) -> bool {
            false
        }
    }

    /// `e` turned upside down about its middle height, still facing out.
    fn flipped(e: &Element) -> Element {
        let (lo, hi) = e.bounds();
        Element {
            vertices: e.vertices.iter().map(|v| v.with_z(lo.z + hi.z - v.z)).collect(),
            triangles: e.triangles.iter().map(|&[a, b, c]| [a, c, b]).collect(),
        }
    }

    fn both(a: &Element, b: &Element) -> Element {
        let mut joined = a.clone();
        joined.append(b);
        joined
    }

    /// A thread of the weave with its over-and-under out of step with a
    /// thread it crosses passes through it; let in, it is bent over or
    /// under at the crossings and nowhere else, and no longer crosses.
    #[test]
    fn a_thread_out_of_step_bends_over_and_under_what_it_crosses() {
        let swatch = builtin_swatch("weave").unwrap();
        let along = |e: &&Element, x: bool| {
            let (lo, hi) = e.bounds();
            ((hi - lo).x > (hi - lo).y) == x
        };
        let row = swatch.elements.iter().find(|e| along(e, true)).unwrap();
        let column = swatch.elements.iter().find(|e| along(e, false)).unwrap().clone();
        assert!(row.is_thread() && column.is_thread());
        assert!(!crosses_itself(&both(row, &column)), "the swatch's own threads clear each other");
        let out_of_step = flipped(row);
        assert!(crosses_itself(&both(&out_of_step, &column)), "flipped, the row passes through the column");

        let output = vec![column.clone()];
        let (bent, _) = admit(out_of_step.clone(), None, true, &output, &mut ElementFaces::default(), &Flat)
            .expect("the row bends round the column");
        assert!(bent.is_closed());
        assert!(!crosses_itself(&both(&bent, &column)), "bent, it clears the column");
        assert!(!crosses_itself(&bent));
        // Only the part near the crossing moved, and nowhere by more than
        // the thread's height.
        let crossing_x = 0.5 * (column.bounds().0.x + column.bounds().1.x);
        let height = row.bounds().1.z - row.bounds().0.z;
        let mut moved = 0;
        for (before, after) in out_of_step.vertices.iter().zip(&bent.vertices) {
            let shift = before.distance(*after);
            if (before.x - crossing_x).abs() > 8.0 {
                assert!(shift < 1e-9, "a vertex {:.1} mm from the crossing moved", (before.x - crossing_x).abs());
            }
            assert!(shift <= height, "a vertex moved {shift:.2} mm");
            assert!(after.z >= row.bounds().0.z - 1e-9, "a vertex went {:.2} mm below the bed", -after.z);
            moved += (shift > 0.1) as usize;
        }
        assert!(moved > 0);
        // What is not a thread is left out rather than bent, and links,
        // rivets and scales are not threads.
        assert!(admit(out_of_step, None, false, &output, &mut ElementFaces::default(), &Flat).is_none());
        for name in ["chainmail", "rivets", "scales"] {
            assert!(builtin_swatch(name).unwrap().elements.iter().all(|e| !e.is_thread()), "{name}");
        }
    }
}
