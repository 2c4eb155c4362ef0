//! The topology solver: exactness against exhaustive search, targets, and control.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};

use tracery_core::control::Control;
use tracery_core::vector_brush::{
    BAND_MARGIN, BUILTIN_NAMES, CurveKind, Exemplar, LoadOptions, PieceSet, SliceOptions, SlicingMode, Solution,
    SolveError, SolveOptions, Target, TopologyDescriptor, Unmet, builtin, solve, tolerance_levels,
};

/// The best objective over every piece sequence, by brute force, with true
/// lengths, the same tolerance levels and the same length term as the solver.
fn exhaustive(set: &PieceSet, options: &SolveOptions) -> Option<f64> {
    for tolerance in tolerance_levels(options) {
        let target = options.target_length;
        // The solver's window has a hair of slack (1e-9 of the length), so
        // that sums of the same widths in another order are accepted alike.
        let slack = 1e-9 * target;
        let (lo, hi) = ((target - tolerance - slack).max(0.0), target + tolerance + slack);
        let mut best: Option<f64> = None;
        let starts: Vec<usize> = match options.curve {
            CurveKind::Open => (0..set.len()).filter(|&i| set.pieces[i].left.is_empty()).collect(),
            CurveKind::Closed => (0..set.len()).collect(),
        };
        struct Walk<'a> {
            set: &'a PieceSet,
            options: &'a SolveOptions,
            lo: f64,
            hi: f64,
            target: f64,
            epsilon: f64,
        }
        fn dfs(w: &Walk, seq: &mut Vec<usize>, len: f64, cost: f64, d: &TopologyDescriptor, best: &mut Option<f64>) {
            let last = *seq.last().unwrap();
            if len >= w.lo {
                let term = w.options.length_weight * ((len - w.target) / w.epsilon).powi(2);
                let score = match w.options.curve {
                    CurveKind::Open => d.is_finished().then(|| (d.components(), d.holes(), 1)).map(|t| (t, cost)),
                    CurveKind::Closed => w.set.pair(last, seq[0]).and_then(|closing| {
                        d.close_loop().map(|t| ((t.components, t.holes, t.wraps), cost + closing.cost))
                    }),
                };
                if let Some(((c, h, wraps), total)) = score {
                    let loop_ok = !w.options.closed_pattern || wraps > 0;
                    if w.options.components.accepts(c) && w.options.holes.accepts(h) && loop_ok {
                        let total = total + term;
                        if best.is_none_or(|b| total < b) {
                            *best = Some(total);
                        }
                    }
                }
            }
            for j in 0..w.set.len() {
                let Some(pair) = w.set.pair(last, j) else { continue };
                let next_len = len + w.set.pieces[j].width;
                if next_len > w.hi {
                    continue;
                }
                let joined = d.join(&w.set.pieces[j].descriptor).unwrap();
                seq.push(j);
                dfs(w, seq, next_len, cost + pair.cost, &joined, best);
                seq.pop();
            }
        }
        let walk = Walk { set, options, lo, hi, target, epsilon: tolerance };
        for s in starts {
            let width = set.pieces[s].width;
            if width <= hi {
                dfs(&walk, &mut vec![s], width, 0.0, &set.pieces[s].descriptor, &mut best);
            }
        }
        if best.is_some() {
            return best;
        }
    }
    None
}

#[test]
fn dp_equals_exhaustive_search_on_small_instances() {
    let mut compared = 0;
    let mut solved = 0;
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).unwrap();
        for cuts in [2, 4] {
            let mut slicing = SliceOptions::default();
            slicing.mode = SlicingMode::Uniform { cuts };
            let set = PieceSet::new(&exemplar, &slicing).unwrap();
            for factor in [0.5, 0.9] {
                for curve in [CurveKind::Open, CurveKind::Closed] {
                    for (components, holes, closed_pattern) in [
                        (Target::Exactly(1), Target::Any, false),
                        (Target::Any, Target::Any, false),
                        (Target::Exactly(1), Target::Exactly(0), false),
                        (Target::Exactly(1), Target::Any, true),
                        (Target::Exactly(2), Target::Any, false),
                        // Searched first without descriptors, leaving out
                        // the pieces and seams a loop cannot run through.
                        (Target::Any, Target::Any, true),
                    ] {
                        let mut options = SolveOptions::new(factor * exemplar.width());
                        options.curve = curve;
                        options.components = components;
                        options.holes = holes;
                        options.closed_pattern = closed_pattern;
                        // A fine length key: partial solutions merge only
                        // when their true lengths agree to 1e-4 of the exemplar.
                        options.length_quantum = Some(1e-4 * exemplar.width());
                        let expected = exhaustive(&set, &options);
                        let got = solve(&set, &options, &Control::default());
                        let context = format!(
                            "{name} cuts={cuts} x{factor} {curve:?} {components:?} {holes:?} loop={closed_pattern}"
                        );
                        match (expected, got) {
                            (Some(best), Ok(solution)) => {
                                assert!(
                                    (best - solution.cost).abs() < 1e-9,
                                    "{context}: exhaustive {best}, DP {}",
                                    solution.cost
                                );
                                assert!(components.accepts(solution.components), "{context}");
                                assert!(holes.accepts(solution.holes), "{context}");
                                solved += 1;
                            }
                            (None, Err(SolveError::NoSolution(_))) => {}
                            (e, g) => panic!("{context}: exhaustive {e:?}, DP {g:?}"),
                        }
                        compared += 1;
                    }
                }
            }
        }
    }
    assert_eq!(compared, 8 * 2 * 2 * 2 * 6);
    assert!(solved > compared / 3, "only {solved} of {compared} instances had a solution");
}

/// The default length key merges partial solutions whose lengths agree to
/// about a piece, which makes the search approximate: on every instance small
/// enough for brute force, it must still find a pattern whenever one exists,
/// and cost at most a few percent more than the best.
#[test]
fn the_default_length_key_stays_close_to_exact() {
    let (mut compared, mut worst_gap, mut total_gap) = (0, 0.0f64, 0.0);
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).unwrap();
        // Cut where the topology changes, but into few pieces of unequal
        // widths, so that brute force stays feasible and lengths differ.
        let mut slicing = SliceOptions::default();
        slicing.event_grouping = 0.6;
        let set = PieceSet::new(&exemplar, &slicing).unwrap();
        if set.len() > 9 {
            continue;
        }
        for factor in [0.4, 0.6] {
            for curve in [CurveKind::Open, CurveKind::Closed] {
                for components in [Target::Exactly(1), Target::Any] {
                    let mut options = SolveOptions::new(factor * exemplar.width());
                    options.curve = curve;
                    options.components = components;
                    let context = format!("{name} x{factor} {curve:?} {components:?}");
                    let Some(best) = exhaustive(&set, &options) else { continue };
                    let got = solve(&set, &options, &Control::default())
                        .unwrap_or_else(|e| panic!("{context}: brute force found {best}, the search {e}"));
                    let gap = (got.cost - best) / best.abs().max(1e-3);
                    assert!(gap > -1e-9, "{context}: better than the best? {} < {best}", got.cost);
                    worst_gap = worst_gap.max(gap);
                    total_gap += gap;
                    compared += 1;
                }
            }
        }
    }
    eprintln!("{compared} instances, mean gap {:.4}, worst {:.4}", total_gap / f64::from(compared), worst_gap);
    assert!(compared >= 8, "only {compared} instances");
    assert!(worst_gap < 0.10, "worst gap {worst_gap}");
}

fn dots() -> Exemplar {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 20">
        <circle cx="10" cy="10" r="4"/><circle cx="30" cy="10" r="4"/><circle cx="50" cy="10" r="4"/>
        <circle cx="70" cy="10" r="4"/><circle cx="90" cy="10" r="4"/></svg>"#;
    Exemplar::from_svg_str("dots", svg, &LoadOptions::default()).unwrap()
}

#[test]
fn impossible_targets_say_which_target_fails() {
    let exemplar = dots();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(20.0 * exemplar.width());
    options.components = Target::Exactly(1);
    let error = solve(&set, &options, &Control::default()).unwrap_err();
    assert_eq!(error, SolveError::NoSolution(Unmet::Components(Target::Exactly(1))));
    assert!(error.to_string().contains("component"), "{error}");
    // Relaxing the target that was named makes it solvable.
    options.components = Target::Any;
    let solution = solve(&set, &options, &Control::default()).unwrap();
    assert!(solution.components > 10);

    // Holes from an exemplar that has none.
    let vine = builtin("vine").unwrap();
    let set = PieceSet::new(&vine, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(4.0 * vine.width());
    options.holes = Target::Exactly(3);
    let error = solve(&set, &options, &Control::default()).unwrap_err();
    assert_eq!(error, SolveError::NoSolution(Unmet::Holes(Target::Exactly(3))));

    // A loop that runs all around, from separate dots.
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(10.0 * exemplar.width());
    options.curve = CurveKind::Closed;
    options.components = Target::Any;
    options.closed_pattern = true;
    let error = solve(&set, &options, &Control::default()).unwrap_err();
    assert_eq!(error, SolveError::NoSolution(Unmet::ClosedPattern));
}

#[test]
fn loops_run_all_around_when_asked() {
    for name in ["lace", "vine", "braid", "meander"] {
        let exemplar = builtin(name).unwrap();
        let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
        let mut options = SolveOptions::new(6.0 * exemplar.width());
        options.curve = CurveKind::Closed;
        options.closed_pattern = true;
        let solution = solve(&set, &options, &Control::default()).unwrap();
        assert_eq!(solution.components, 1, "{name}");
        assert_eq!(solution.wraps, 1, "{name}");
        let first = solution.pieces[0];
        let last = *solution.pieces.last().unwrap();
        assert!(set.pair(last, first).is_some(), "{name}: the loop must close");
        assert!((solution.length - solution.target_length).abs() <= solution.tolerance + 1e-9);
    }
}

#[test]
fn hole_targets_are_met_exactly() {
    let exemplar = builtin("lace").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(3.0 * exemplar.width());
    let natural = solve(&set, &options, &Control::default()).unwrap().holes;
    let mut met = 0;
    for holes in [natural - 1, natural + 1, natural - 4, natural + 5] {
        options.holes = Target::Exactly(holes);
        match solve(&set, &options, &Control::default()) {
            Ok(solution) => {
                assert_eq!((solution.components, solution.holes), (1, holes));
                met += 1;
            }
            Err(e) => assert!(matches!(e, SolveError::NoSolution(Unmet::Holes(_) | Unmet::Combination { .. })), "{e}"),
        }
    }
    assert!(met >= 3, "only {met} of 4 hole targets near {natural} were met");
}

#[test]
fn cancellation_stops_the_search() {
    let exemplar = builtin("braid").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(8.0 * exemplar.width());
    options.curve = CurveKind::Closed;
    let cancel = AtomicBool::new(true);
    let control = Control { cancel: Some(&cancel), progress: None };
    assert_eq!(solve(&set, &options, &control).unwrap_err(), SolveError::Cancelled(tracery_core::control::Cancelled));
    // Cancelling from the progress callback, midway, also stops it.
    let cancel = AtomicBool::new(false);
    let stop_halfway = |f: f32| {
        if f > 0.3 {
            cancel.store(true, Ordering::Relaxed);
        }
    };
    let control = Control { cancel: Some(&cancel), progress: Some(&stop_halfway) };
    assert_eq!(solve(&set, &options, &control).unwrap_err(), SolveError::Cancelled(tracery_core::control::Cancelled));
}

#[test]
fn progress_is_reported_up_to_done() {
    let exemplar = builtin("lace").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let seen = Mutex::new(Vec::new());
    let record = |f: f32| seen.lock().unwrap().push(f);
    let options = SolveOptions::new(5.0 * exemplar.width());
    solve(&set, &options, &Control { cancel: None, progress: Some(&record) }).unwrap();
    let seen = seen.into_inner().unwrap();
    assert!(seen.len() > 3);
    assert!(seen.iter().all(|f| (0.0..=1.0).contains(f)));
    assert_eq!(*seen.last().unwrap(), 1.0);
}

#[test]
fn state_cap_ends_with_an_error() {
    let exemplar = builtin("lace").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(5.0 * exemplar.width());
    options.max_states = 100;
    let error = solve(&set, &options, &Control::default()).unwrap_err();
    assert!(matches!(error, SolveError::TooManyStates { limit: 100, .. }), "{error:?}");
}

#[test]
fn bad_options_are_rejected() {
    let exemplar = builtin("lace").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    for length in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let options = SolveOptions::new(length);
        assert!(matches!(solve(&set, &options, &Control::default()), Err(SolveError::InvalidOption(_))));
    }
    let mut options = SolveOptions::new(100.0);
    options.variety = -1.0;
    assert!(matches!(solve(&set, &options, &Control::default()), Err(SolveError::InvalidOption(_))));
}

#[test]
fn variety_lowers_autocorrelation_and_seeds_vary_the_result() {
    let exemplar = builtin("lace").unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(6.0 * exemplar.width());
    let plain = solve(&set, &options, &Control::default()).unwrap();
    options.variety = 1.0;
    let varied = solve(&set, &options, &Control::default()).unwrap();
    assert!(varied.autocorrelation < plain.autocorrelation, "{} vs {}", varied.autocorrelation, plain.autocorrelation);
    assert_eq!(varied.components, 1);
    options.seed = 7;
    let seeded = solve(&set, &options, &Control::default()).unwrap();
    assert_ne!(seeded.pieces, varied.pieces);
    assert_eq!(seeded.components, 1);
}

#[test]
fn band_height_bounds_the_accumulated_offsets() {
    // A tilted exemplar climbs with every jump back in it.
    let tilted = builtin("tilted").unwrap();
    let set = PieceSet::new(&tilted, &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(5.0 * tilted.width());
    let free = solve(&set, &options, &Control::default()).unwrap();
    let reach = |s: &Solution| {
        s.pieces.iter().zip(&s.offsets).map(|(&p, d)| d.abs() + set.pieces[p].extent()).fold(0.0, f64::max)
    };
    assert!(reach(&free) > 0.75 * tilted.height(), "{}", reach(&free));
    // With the band, every piece stays in it (held back at the edge where
    // the alignment would take it out, paying for the mismatch).
    options.band_height = tilted.height();
    let bounded = solve(&set, &options, &Control::default()).unwrap();
    assert!(reach(&bounded) <= 0.5 * tilted.height() * (1.0 + BAND_MARGIN) + 1e-6, "{}", reach(&bounded));
    assert!(bounded.cost >= free.cost - 1e-9);

    // A band far narrower than the pieces' own steps says so instead of
    // blaming the topology targets.
    options.band_height = 0.05 * tilted.height();
    let error = solve(&set, &options, &Control::default()).unwrap_err();
    assert_eq!(error, SolveError::NoSolution(Unmet::Band));
}

/// Where the exact search needs more states than the cap, a bounded search
/// answers instead: the pattern must still meet every target (recounted
/// here from the pieces' own descriptors), be marked as bounded, and cost
/// little more than the exact answer on instances where both run.
///
/// The targets are ones the search follows descriptors for: with any
/// number of parts and holes it leaves them out and needs a small fraction
/// of the states (at most 34 k on the corpus, against a cap of 2 M), so a
/// cap at half of those says little about the bounded search users meet.
///
/// The worst gap is taken over searches that keep at least two states per
/// length. At half the states of these small instances a loop's beam can
/// come out at one (each of the loop's parallel searches gets its share of
/// the cap): a greedy search, which on the corpus's loops (beams of about
/// 1800 to 2700) never happens. Those still have to meet every target, but
/// count in neither the worst gap nor the mean: since seams that do not fit
/// cost what they do to the pattern (`MISFIT_WEIGHT`), a greedy step onto
/// one costs several times what the braid's whole best pattern does (gaps
/// of 4.6 and 7.8 on its two greedy instances, where every search with a
/// beam of two or more stays within 13 %).
#[test]
fn a_bounded_search_answers_past_the_cap_close_to_exact() {
    let (mut compared, mut worst_gap, mut total_gap) = (0, 0.0f64, 0.0);
    let targets = [
        (Target::Exactly(1), Target::Any),
        (Target::Exactly(2), Target::Any),
        (Target::Exactly(1), Target::Exactly(0)),
    ];
    for name in BUILTIN_NAMES {
        let set = PieceSet::new(&builtin(name).unwrap(), &SliceOptions::default()).unwrap();
        for curve in [CurveKind::Open, CurveKind::Closed] {
            for (components, holes) in targets {
                let mut options = SolveOptions::new(60.0 * set.exemplar_width / set.len() as f64);
                options.curve = curve;
                options.components = components;
                options.holes = holes;
                options.closed_pattern = curve == CurveKind::Closed;
                options.variety = 0.3;
                options.band_height = 1.2 * set.exemplar_height;
                let context = format!("{name} {curve:?} {components:?}");
                let Ok(exact) = solve(&set, &options, &Control::default()) else { continue };
                assert_eq!(exact.bounded, None, "{context}");
                // A cap at half of what the exact search used.
                options.max_states = (exact.states / 2).max(200);
                let bounded = match solve(&set, &options, &Control::default()) {
                    Ok(s) => s,
                    Err(SolveError::TooManyStates { .. }) => {
                        eprintln!("{context}: cap {} still reached", options.max_states);
                        continue;
                    }
                    Err(e) => panic!("{context}: {e}"),
                };
                if bounded.bounded.is_none() {
                    eprintln!("{context}: exact within {} states", options.max_states);
                    continue;
                }
                let mut d = set.pieces[bounded.pieces[0]].descriptor.clone();
                for w in bounded.pieces.windows(2) {
                    assert!(set.pair(w[0], w[1]).is_some(), "{context}: incompatible seam");
                    d = d.join(&set.pieces[w[1]].descriptor).unwrap();
                }
                let counted = match curve {
                    CurveKind::Open => {
                        assert!(d.is_finished(), "{context}");
                        (d.components(), d.holes(), 1)
                    }
                    _ => d.close_loop().map(|t| (t.components, t.holes, t.wraps)).unwrap(),
                };
                assert!(components.accepts(counted.0) && holes.accepts(counted.1) && counted.2 > 0, "{context}");
                let gap = (bounded.cost - exact.cost) / exact.cost.abs().max(1e-3);
                eprintln!("{context}: cap {}, beam {:?}, cost gap {gap:.4}", options.max_states, bounded.bounded);
                if bounded.bounded.is_some_and(|beam| beam >= 2) {
                    worst_gap = worst_gap.max(gap);
                    total_gap += gap;
                    compared += 1;
                }
            }
        }
    }
    eprintln!("{compared} bounded instances, mean gap {:.4}, worst {:.4}", total_gap / f64::from(compared), worst_gap);
    assert!(compared >= 6, "only {compared} instances went past the cap");
    assert!(total_gap / f64::from(compared) < 0.08, "mean gap {}", total_gap / f64::from(compared));
    assert!(worst_gap < 0.3, "worst gap {worst_gap}");
}

/// A search projects where its states will end and stops early when it is
/// bound to pass the cap on its own. A search that fits the cap with a
/// fifth to spare must never be stopped: it answers exactly, as without
/// the projection.
#[test]
fn a_search_that_fits_the_cap_is_never_stopped_early() {
    let mut compared = 0;
    for name in BUILTIN_NAMES {
        let set = PieceSet::new(&builtin(name).unwrap(), &SliceOptions::default()).unwrap();
        for curve in [CurveKind::Open, CurveKind::Closed] {
            for components in [Target::Exactly(1), Target::Exactly(2)] {
                let mut options = SolveOptions::new(60.0 * set.exemplar_width / set.len() as f64);
                options.curve = curve;
                options.components = components;
                options.closed_pattern = curve == CurveKind::Closed;
                options.band_height = 1.2 * set.exemplar_height;
                let context = format!("{name} {curve:?} {components:?}");
                let Ok(exact) = solve(&set, &options, &Control::default()) else { continue };
                assert_eq!(exact.bounded, None, "{context}");
                // Each running search takes states from the cap a thousand at a time.
                options.max_states = exact.states * 6 / 5 + 4096;
                let again = solve(&set, &options, &Control::default()).unwrap_or_else(|e| panic!("{context}: {e}"));
                assert_eq!(again.bounded, None, "{context}: stopped early with a cap of {}", options.max_states);
                assert_eq!(again.pieces, exact.pieces, "{context}");
                compared += 1;
            }
        }
    }
    assert!(compared >= 16, "only {compared} instances");
}

/// A search bound to pass the cap on its own stops once its growth shows
/// it (from a fifth of its lengths on), not when it meets the cap: with
/// the cap at half of what the search needs, it would meet the cap about
/// half way through its lengths. The bounded search then answers.
#[test]
fn a_search_bound_to_pass_the_cap_stops_early() {
    let set = PieceSet::new(&builtin("lace").unwrap(), &SliceOptions::default()).unwrap();
    let mut options = SolveOptions::new(60.0 * set.exemplar_width / set.len() as f64);
    options.band_height = 1.2 * set.exemplar_height;
    let exact = solve(&set, &options, &Control::default()).unwrap();
    options.max_states = exact.states / 2;
    let seen = Mutex::new(Vec::new());
    let record = |f: f32| seen.lock().unwrap().push(f);
    let bounded = solve(&set, &options, &Control { cancel: None, progress: Some(&record) }).unwrap();
    assert!(bounded.bounded.is_some(), "{} states needed, cap {}", exact.states, options.max_states);
    // The bounded search reports its progress from zero again.
    let seen = seen.into_inner().unwrap();
    let restart = seen.windows(2).position(|w| w[1] < w[0]).expect("a second search") + 1;
    let reached = seen[..restart].iter().copied().fold(0.0, f32::max);
    eprintln!("{} states needed, cap {}: the exact search stopped at {reached:.2}", exact.states, options.max_states);
    assert!(restart >= 3, "too few reports to tell: {seen:?}");
    assert!(reached < 0.35, "the exact search went on to {reached}");
}

/// With any number of parts and holes the search first leaves the
/// descriptors out. On a loop that must run all around, what it finds is
/// then checked: here the exemplar's own order, whose seams all fit, is two
/// bars each broken once, and runs all around nowhere.
#[test]
fn a_loop_searched_without_descriptors_still_runs_all_around() {
    use glam::DVec2;
    use tracery_core::geom::{Polygon, Region};
    let bar = |x0: f64, x1: f64, y0: f64| Polygon {
        outer: vec![DVec2::new(x0, y0), DVec2::new(x1, y0), DVec2::new(x1, y0 + 1.0), DVec2::new(x0, y0 + 1.0)],
        holes: vec![],
    };
    // The top bar broken at 2..3, the bottom one at 6..7.
    let region = Region::new(vec![bar(0.0, 2.0, 2.0), bar(3.0, 10.0, 2.0), bar(0.0, 6.0, 0.0), bar(7.0, 10.0, 0.0)]);
    let exemplar = Exemplar::from_region("broken bars", region).unwrap();
    let set = PieceSet::new(&exemplar, &SliceOptions::default()).unwrap();
    for length in [20.0, 30.0, 40.0] {
        let mut options = SolveOptions::new(length);
        options.curve = CurveKind::Closed;
        options.components = Target::Any;
        options.holes = Target::Any;
        options.closed_pattern = true;
        let solution = solve(&set, &options, &Control::default()).unwrap();
        // Counted again from the pieces' own descriptors.
        let mut d = set.pieces[solution.pieces[0]].descriptor.clone();
        for &p in &solution.pieces[1..] {
            d = d.join(&set.pieces[p].descriptor).unwrap();
        }
        let counted = d.close_loop().unwrap();
        assert!(counted.wraps > 0, "length {length}: {:?} runs all around nowhere", solution.pieces);
        assert_eq!(counted.wraps, solution.wraps);
    }
}
