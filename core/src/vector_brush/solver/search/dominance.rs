//! Dropping partial patterns another one of the same length and last piece
//! dominates: cheaper, and connected at least as much.

use super::narrowing::total;
use super::{Search, State, Topology};
use crate::vector_brush::{Autocorrelation, TopologyDescriptor};

impl Search<'_> {
    /// Whether this search drops dominated partial patterns: when asked
    /// to, following the descriptors, and where the targets allow it
    /// ([`crate::vector_brush::SolveOptions::dominance_is_sound`]).
    pub(super) fn dominance_applies(&self) -> bool {
        let problem = self.problem;
        problem.dominance && problem.topology == Topology::Followed && problem.options.dominance_is_sound()
    }

    /// Drops every open state of one length that a cheaper one with the
    /// same last piece dominates ([`dominates`]), past the
    /// [`KEPT_REGARDLESS`] cheapest of that piece where the variety term is
    /// on.
    pub(super) fn drop_dominated(&mut self, open: &mut Vec<State>, autos: &mut Vec<Autocorrelation>) {
        let beta = self.problem.options.variety;
        let floor = if self.variety() { KEPT_REGARDLESS } else { 0 };
        let total = |i: usize| total(open, autos, beta, i);
        let mut order: Vec<usize> = (0..open.len()).collect();
        // Of equal totals the less divided first, so that it is the one kept.
        let list = &self.interner.list;
        let parts = |i: usize| list[open[i].descriptor as usize].open_components();
        order.sort_unstable_by(|&i, &j| {
            open[i].piece.cmp(&open[j].piece).then(total(i).total_cmp(&total(j))).then(parts(i).cmp(&parts(j)))
        });
        let mut kept_states: Vec<usize> = Vec::with_capacity(open.len());
        let mut kept: Vec<u32> = Vec::new();
        let mut piece = u16::MAX;
        for &i in &order {
            if open[i].piece != piece {
                piece = open[i].piece;
                kept.clear();
            }
            let d = &list[open[i].descriptor as usize];
            if kept.len() >= floor && kept.iter().any(|&k| dominates(&list[k as usize], d)) {
                continue;
            }
            kept.push(open[i].descriptor);
            kept_states.push(i);
        }
        kept_states.sort_unstable();
        self.keep_only(&kept_states, open, autos);
    }
}

/// Where the variety term is on, the cheapest states of each length and
/// last piece kept whether another dominates them or not. Dominance is
/// exact where the cost of a finish depends only on its pieces, but the
/// variety term depends on the pieces before too: a dominated state with
/// another history may finish cheaper. Dropping every dominated state left
/// `vectorian105`'s loops (any number of parts, 16–19 M states exactly)
/// 23–27 k states and an objective 0.3–2.3 % above the search without a
/// cap; keeping the 4 cheapest, 42–49 k states and −0.2 to +0.5 %; the 16
/// cheapest, 108–123 k states and 0 to −0.4 %; the 64 cheapest, 358–410 k
/// states and the same objective.
const KEPT_REGARDLESS: usize = 16;

/// Whether `a` connects every pair of portals `b` connects, with no more
/// parts closed inside: whatever finishes `b`, the same pieces finish `a`
/// with no more parts and, on a loop, with a part running all around
/// wherever `b`'s has one.
fn dominates(a: &TopologyDescriptor, b: &TopologyDescriptor) -> bool {
    let same_portals = a.left().len() == b.left().len() && a.right().len() == b.right().len();
    if !same_portals || a.closed_components() > b.closed_components() {
        return false;
    }
    let mut map = [u16::MAX; 256];
    for (&x, &y) in b.left().iter().chain(b.right()).zip(a.left().iter().chain(a.right())) {
        let slot = &mut map[usize::from(x).min(255)];
        if *slot == u16::MAX {
            *slot = y;
        } else if *slot != y {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::Control;
    use crate::vector_brush::solver::search::search_all;
    use crate::vector_brush::solver::{CurveKind, Goal, SolveOptions, Target};
    use crate::vector_brush::{BUILTIN_NAMES, Exemplar, LoadOptions, PieceSet, SliceOptions, SlicingMode, builtin};

    fn d(left: &[u16], right: &[u16], closed: u16) -> TopologyDescriptor {
        TopologyDescriptor::new(left, right, closed, 0)
    }

    /// Six rails bridged once in each eighth of the width, each time
    /// between another pair: partial patterns with the same last piece
    /// connect the rails in many ways.
    fn ladder() -> Exemplar {
        let rails: String =
            (0..6).map(|r| format!(r#"<rect x="0" y="{}" width="120" height="4"/>"#, 2 + 10 * r)).collect();
        let rungs: String = (0..8)
            .map(|k| format!(r#"<rect x="{}" y="{}" width="3" height="8"/>"#, 5 + 15 * k, 5 + 10 * (k % 5)))
            .collect();
        let svg = format!(r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 120 60">{rails}{rungs}</svg>"#);
        Exemplar::from_svg_str("ladder", &svg, &LoadOptions::default()).unwrap()
    }

    /// Without the variety term, and with pieces of one width keyed by it,
    /// so that only partial patterns of the same true length compete,
    /// dropping the dominated ones changes no answer: the cost of a finish
    /// then depends on its pieces alone. Checked against the search that
    /// keeps them, on every built-in and a ladder whose rails connect in
    /// many ways, for the targets dominance is used for, open and closed.
    #[test]
    fn dropping_dominated_partial_patterns_finds_the_same_cost() {
        let (mut compared, mut exact_states, mut dominance_states) = (0, 0, 0);
        let exemplars = BUILTIN_NAMES.iter().map(|name| builtin(name).unwrap()).chain([ladder()]);
        for exemplar in exemplars {
            // Pieces of one width: partial patterns of the same key have
            // the same true length.
            let slicing = SliceOptions { mode: SlicingMode::Uniform { cuts: 7 }, ..SliceOptions::default() };
            let set = PieceSet::new(&exemplar, &slicing).unwrap();
            let width = set.pieces[0].width;
            for (curve, factor) in [(CurveKind::Open, 2.5), (CurveKind::Open, 4.0), (CurveKind::Closed, 2.5)] {
                for (components, closed_pattern) in [(Target::Exactly(1), false), (Target::Any, true)] {
                    let mut options = SolveOptions::new(factor * set.exemplar_width);
                    options.curve = curve;
                    options.components = components;
                    options.closed_pattern = closed_pattern && curve == CurveKind::Closed;
                    options.length_quantum = Some(width);
                    let control = Control::default();
                    let exact = search_all(&set, &options, Goal::Best, &control).unwrap();
                    let pruned = search_all(&set, &options, Goal::Dominated, &control).unwrap();
                    let context =
                        format!("{} {curve:?} x{factor} {components:?} loop={}", exemplar.name, options.closed_pattern);
                    match (exact, pruned) {
                        (Some(e), Some(p)) => {
                            assert!((e.cost - p.cost).abs() < 1e-9, "{context}: {} against {}", e.cost, p.cost);
                            assert!(p.dominance && !e.dominance, "{context}");
                            assert!(components.accepts(p.components), "{context}");
                            assert!(!options.closed_pattern || p.wraps > 0, "{context}");
                            exact_states += e.states;
                            dominance_states += p.states;
                            compared += 1;
                        }
                        (None, None) => {}
                        (e, p) => panic!("{context}: {e:?} against {p:?}"),
                    }
                }
            }
        }
        assert!(compared >= 30, "only {compared} instances had a pattern");
        // Dropping is real: far fewer states created in all.
        assert!(4 * dominance_states < 3 * exact_states, "{dominance_states} states against {exact_states}");
    }

    /// The same with seam costs drawn at random on the ladder: a search
    /// that kept only the cheapest state of each length and last piece,
    /// whatever its partition, would lose the cheapest pattern with one
    /// part here, where the cheapest partial patterns leave rails apart
    /// that only dearer seams can join later.
    #[test]
    fn dropping_dominated_partial_patterns_finds_the_same_cost_whatever_the_seams_cost() {
        let slicing = SliceOptions { mode: SlicingMode::Uniform { cuts: 7 }, ..SliceOptions::default() };
        let base = PieceSet::new(&ladder(), &slicing).unwrap();
        let width = base.pieces[0].width;
        let (mut compared, mut dropped) = (0, 0);
        for seed in 1..=24u64 {
            let mut set = base.clone();
            let mut state = seed;
            for a in 0..set.len() {
                for b in 0..set.len() {
                    state = crate::random::splitmix64(state);
                    set.set_pair_cost(a, b, (state >> 11) as f64 / (1u64 << 53) as f64);
                }
            }
            for curve in [CurveKind::Open, CurveKind::Closed] {
                let mut options = SolveOptions::new(3.0 * set.exemplar_width);
                options.curve = curve;
                options.length_quantum = Some(width);
                let control = Control::default();
                let exact = search_all(&set, &options, Goal::Best, &control).unwrap();
                let pruned = search_all(&set, &options, Goal::Dominated, &control).unwrap();
                match (exact, pruned) {
                    (Some(e), Some(p)) => {
                        assert!((e.cost - p.cost).abs() < 1e-9, "seed {seed} {curve:?}: {} against {}", e.cost, p.cost);
                        assert_eq!(p.components, 1, "seed {seed} {curve:?}");
                        dropped += e.states - p.states;
                        compared += 1;
                    }
                    (None, None) => {}
                    (e, p) => panic!("seed {seed} {curve:?}: {e:?} against {p:?}"),
                }
            }
        }
        assert!(compared >= 24, "only {compared} instances had a pattern");
        assert!(dropped > 0, "nothing dropped");
    }

    #[test]
    fn a_coarser_partition_dominates_a_finer_one_and_not_the_other_way() {
        // Everything in one part against the start's top portal apart.
        let (one, two) = (d(&[0, 0], &[0, 0], 0), d(&[0, 1], &[1, 1], 0));
        assert!(dominates(&one, &two));
        assert!(!dominates(&two, &one));
        assert!(dominates(&two, &two));
        // Partitions that neither refines.
        let (a, b) = (d(&[0, 0], &[1, 1], 0), d(&[0, 1], &[0, 1], 0));
        assert!(!dominates(&a, &b) && !dominates(&b, &a));
        // A part already closed inside is one more part at the end.
        assert!(!dominates(&d(&[0, 0], &[0, 0], 1), &two));
        // Other portal counts on the right: never compared.
        assert!(!dominates(&d(&[0, 0], &[0], 0), &two));
    }

    #[test]
    fn what_a_finer_partition_finishes_into_a_coarser_one_does_too() {
        // Every descriptor of two left and two right portals, closed on
        // every piece of the same shape: the coarser wraps at least as
        // often and has no more parts.
        let partitions: [[u16; 4]; 15] = [
            [0, 0, 0, 0],
            [0, 0, 0, 1],
            [0, 0, 1, 0],
            [0, 1, 0, 0],
            [0, 1, 1, 1],
            [0, 0, 1, 1],
            [0, 1, 0, 1],
            [0, 1, 1, 0],
            [0, 0, 1, 2],
            [0, 1, 0, 2],
            [0, 1, 2, 0],
            [0, 1, 1, 2],
            [0, 1, 2, 1],
            [0, 1, 2, 2],
            [0, 1, 2, 3],
        ];
        let all: Vec<TopologyDescriptor> = partitions.iter().map(|p| d(&p[..2], &p[2..], 0)).collect();
        let mut pairs = 0;
        for a in &all {
            for b in all.iter().filter(|b| dominates(a, b)) {
                for next in &all {
                    let (ta, tb) =
                        (a.join(next).unwrap().close_loop().unwrap(), b.join(next).unwrap().close_loop().unwrap());
                    assert!(ta.wraps >= tb.wraps.min(1), "{a:?} over {b:?} then {next:?}");
                    assert!(ta.components <= tb.components, "{a:?} over {b:?} then {next:?}");
                    pairs += 1;
                }
            }
        }
        assert!(pairs > 15 * 15, "{pairs}");
    }
}
