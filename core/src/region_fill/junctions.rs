//! Junctions an exemplar never has, undone: where the synthesis joins two
//! spirals by a stray branch, each sample where three or more branches meet
//! keeps the two that continue each other most nearly straight.

use rustc_hash::FxHashSet;

use super::SampleGraph;

/// The most path branches any sample of `graph` has (elements have none).
pub fn greatest_degree(graph: &SampleGraph) -> usize {
    graph.neighbours.iter().map(|n| n.len()).max().unwrap_or(0)
}

/// Undoes every junction among the samples from `first` on (those before
/// are a person's strokes, whose joins stay): a sample with three or more
/// branches keeps the two most nearly opposite, the line that runs through
/// it, and loses the others, which then end a sample spacing away. For
/// an exemplar without junctions (`greatest_degree` at most 2). Returns how
/// many branches were removed.
///
/// ```
/// use tracery_core::DVec2;
/// use tracery_core::region_fill::{CurvePath, SampleGraph, greatest_degree, undo_junctions};
/// let line = |a: DVec2, b: DVec2| CurvePath { points_mm: vec![a, b], closed: false };
/// // A T: a bar along x, and a stem ending on it from below.
/// let mut t = SampleGraph::new(
///     &[line(DVec2::new(-4.0, 0.0), DVec2::new(4.0, 0.0)), line(DVec2::new(0.0, -4.0), DVec2::new(0.0, 0.0))],
///     1.0,
/// )
/// .unwrap();
/// assert_eq!(greatest_degree(&t), 3);
/// assert_eq!(undo_junctions(&mut t, 0), 1);
/// assert_eq!(greatest_degree(&t), 2);
/// // The bar runs on; the stem is a path of its own.
/// assert_eq!(t.to_paths().len(), 2);
/// ```
pub fn undo_junctions(graph: &mut SampleGraph, first: usize) -> usize {
    let mut removed: FxHashSet<(u32, u32)> = FxHashSet::default();
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    for s in first..graph.samples.len() {
        let branches: Vec<u32> =
            graph.neighbours[s].iter().copied().filter(|&n| !removed.contains(&key(s as u32, n))).collect();
        if branches.len() < 3 {
            continue;
        }
        let at = graph.samples[s].position_mm;
        let direction = |n: u32| (graph.samples[n as usize].position_mm - at).normalize_or_zero();
        let mut straightest = (f64::INFINITY, 0, 1);
        for i in 0..branches.len() {
            for j in i + 1..branches.len() {
                let turn = direction(branches[i]).dot(direction(branches[j]));
                if turn < straightest.0 {
                    straightest = (turn, i, j);
                }
            }
        }
        for (k, &n) in branches.iter().enumerate() {
            if k != straightest.1 && k != straightest.2 {
                removed.insert(key(s as u32, n));
            }
        }
    }
    if !removed.is_empty() {
        graph.disconnect_where(|a, b| removed.contains(&key(a, b)));
    }
    removed.len()
}
