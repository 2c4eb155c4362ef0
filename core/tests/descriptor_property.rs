//! The merged topology descriptor of a piece sequence predicts exactly the
//! components and holes of the assembled geometry, counted independently
//! (polygon union, then counting rings).

use proptest::prelude::*;
use tracery_core::DVec2;
use tracery_core::geom::{Polygon, Region, count_topology};
use tracery_core::vector_brush::{
    BUILTIN_NAMES, Exemplar, PieceSet, SliceOptions, SlicingMode, TopologyDescriptor, builtin,
};

/// Lays the pieces out left to right with a gap between them, and bridges
/// each gap with one quadrilateral per matched portal. Portals on both sides
/// are ordered top to bottom, so the bridges never cross; this realises the
/// joins the descriptors assume without any stitching code.
fn assemble(set: &PieceSet, sequence: &[usize]) -> Region {
    let gap = 0.25 * set.exemplar_height;
    let overlap = 1e-3 * gap;
    let mut polygons = Vec::new();
    let mut x = 0.0;
    for (k, &i) in sequence.iter().enumerate() {
        let piece = &set.pieces[i];
        let shift = DVec2::new(x - piece.u_start, 0.0);
        polygons.extend(piece.region.translated(shift).polygons);
        let right_x = x + piece.width;
        if let Some(&j) = sequence.get(k + 1) {
            let next = &set.pieces[j];
            for (a, b) in piece.right.iter().zip(&next.left) {
                let (x0, x1) = (right_x - overlap, right_x + gap + overlap);
                polygons.push(Polygon {
                    outer: vec![
                        DVec2::new(x0, a.bottom),
                        DVec2::new(x1, b.bottom),
                        DVec2::new(x1, b.top),
                        DVec2::new(x0, a.top),
                    ],
                    holes: vec![],
                });
            }
        }
        x = right_x + gap;
    }
    Region::new(polygons)
}

/// A random sequence of compatible pieces, from a left end or from anywhere.
fn random_sequence(set: &PieceSet, choices: &[usize], from_start: bool) -> Vec<usize> {
    let n = set.len();
    let starts: Vec<usize> =
        if from_start { (0..n).filter(|&i| set.pieces[i].left.is_empty()).collect() } else { (0..n).collect() };
    let mut sequence = vec![starts[choices[0] % starts.len()]];
    for &c in &choices[1..] {
        let last = *sequence.last().unwrap();
        let next: Vec<usize> = (0..n).filter(|&j| set.pair(last, j).is_some()).collect();
        if next.is_empty() {
            break;
        }
        sequence.push(next[c % next.len()]);
    }
    sequence
}

fn merged(set: &PieceSet, sequence: &[usize]) -> TopologyDescriptor {
    sequence[1..].iter().fold(set.pieces[sequence[0]].descriptor.clone(), |d, &i| {
        d.join(&set.pieces[i].descriptor).expect("compatible pieces join")
    })
}

fn piece_sets() -> Vec<(String, PieceSet)> {
    let mut sets = Vec::new();
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).unwrap();
        sets.push((format!("{name}/topology"), PieceSet::new(&exemplar, &SliceOptions::default()).unwrap()));
        let mut uniform = SliceOptions::default();
        uniform.mode = SlicingMode::Uniform { cuts: 9 };
        sets.push((format!("{name}/uniform"), PieceSet::new(&exemplar, &uniform).unwrap()));
    }
    let mut uniform = SliceOptions::default();
    uniform.mode = SlicingMode::Uniform { cuts: 7 };
    sets.push(("close zigzags/uniform".into(), PieceSet::new(&close_zigzags(), &uniform).unwrap()));
    sets
}

/// Two thin strokes close together, zigzagging steeply: pieces cut from it
/// have portals a fraction of a piece apart, and a rising end joined to a
/// falling one needs a hard bend over a short span of the seam.
fn close_zigzags() -> Exemplar {
    let (stroke, spacing) = (0.3, 1.0);
    let strip = |y0: f64| {
        let centre: Vec<DVec2> =
            (0..=8).map(|k| DVec2::new(5.0 * k as f64, y0 + if k % 2 == 0 { -4.0 } else { 4.0 })).collect();
        let mut outer: Vec<DVec2> = centre.iter().map(|p| *p + DVec2::new(0.0, 0.5 * stroke)).collect();
        outer.extend(centre.iter().rev().map(|p| *p - DVec2::new(0.0, 0.5 * stroke)));
        outer.reverse();
        Polygon { outer, holes: vec![] }
    };
    Exemplar::from_region("close zigzags", Region::new(vec![strip(0.0), strip(spacing)])).unwrap()
}

#[test]
fn each_piece_descriptor_matches_its_geometry() {
    for (name, set) in piece_sets() {
        for piece in &set.pieces {
            let t = count_topology(&piece.region);
            let d = &piece.descriptor;
            assert_eq!(t.components as u32, d.components(), "{name} piece {}", piece.index);
            assert_eq!(t.holes as u32, d.holes(), "{name} piece {}", piece.index);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn merged_descriptor_predicts_assembled_topology(
        which in 0usize..17,
        choices in proptest::collection::vec(0usize..1000, 2..14),
        from_start in any::<bool>(),
    ) {
        let sets = piece_sets_cached();
        let (name, set) = &sets[which % sets.len()];
        let sequence = random_sequence(set, &choices, from_start);
        let predicted = merged(set, &sequence);
        let counted = count_topology(&assemble(set, &sequence));
        prop_assert_eq!(
            (counted.components as u32, counted.holes as u32),
            (predicted.components(), predicted.holes()),
            "{} sequence {:?}", name, sequence
        );
    }
}

fn piece_sets_cached() -> &'static [(String, PieceSet)] {
    static SETS: std::sync::OnceLock<Vec<(String, PieceSet)>> = std::sync::OnceLock::new();
    SETS.get_or_init(piece_sets)
}

#[test]
fn finished_open_sequences_from_the_solver_agree_with_geometry() {
    use tracery_core::control::Control;
    use tracery_core::vector_brush::{SolveOptions, Target, solve};
    for (name, set) in piece_sets_cached() {
        for components in [Target::Exactly(1), Target::Any] {
            let mut options = SolveOptions::new(3.0 * set.exemplar_width);
            options.components = components;
            let Ok(solution) = solve(set, &options, &Control::default()) else { continue };
            let counted = count_topology(&assemble(set, &solution.pieces));
            assert_eq!(
                (counted.components as u32, counted.holes as u32),
                (solution.components, solution.holes),
                "{name} {components:?}"
            );
            assert!(components.accepts(counted.components as u32), "{name}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Stitching bends pieces to weld their portals, however far apart the
    /// solver raised them: the welded geometry still has the topology the
    /// descriptors planned (a bend that folds material over itself splits
    /// or merges parts).
    #[test]
    fn stitched_topology_matches_the_plan_under_any_offsets(
        which in 0usize..17,
        choices in proptest::collection::vec(0usize..1000, 2..10),
        raise in proptest::collection::vec(-1.0f64..1.0, 10),
        stretch in 0.9f64..1.1,
    ) {
        use tracery_core::vector_brush::{CurveKind, stitch};
        let sets = piece_sets_cached();
        let (name, set) = &sets[which % sets.len()];
        let sequence = random_sequence(set, &choices, true);
        let predicted = merged(set, &sequence);
        // Up to a third of the exemplar's height either way: far more than
        // the band lets the solver use, so every seam bends hard.
        let offsets: Vec<f64> = sequence.iter().zip(&raise).map(|(_, r)| r * set.exemplar_height / 3.0).collect();
        let length = stretch * sequence.iter().map(|&i| set.pieces[i].width).sum::<f64>();
        let band = stitch(set, &sequence, &offsets, length, CurveKind::Open, 1e-3 * set.exemplar_height);
        let counted = count_topology(&band.region);
        prop_assert_eq!(
            (counted.components as u32, counted.holes as u32),
            (predicted.components(), predicted.holes()),
            "{} sequence {:?} offsets {:?}", name, sequence, offsets
        );
    }
}
