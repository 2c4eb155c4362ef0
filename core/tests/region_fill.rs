//! Region fill's first stages, checked by brute force and by the paths
//! themselves: robust matching against every partial assignment, and the
//! built-ins' sample graphs against their polylines.

use glam::DVec2;
use tracery_core::control::Control;
use tracery_core::region_fill::{
    BUILTIN_CURVES, CurveExemplar, CurvePath, JOIN_TOLERANCE_MM, SampleGraph, SampleGrid, SampleKind, Settings,
    builtin_curves, hierarchy, make_product, parse_region, robust_match,
};

/// The cheapest cost over every way of matching each output to a distinct
/// input or to nothing.
fn brute_force(outputs: usize, inputs: usize, cost: &dyn Fn(usize, usize) -> f64, unmatched: &[f64]) -> f64 {
    fn go(o: usize, used: &mut Vec<bool>, n: usize, cost: &dyn Fn(usize, usize) -> f64, unmatched: &[f64]) -> f64 {
        if o == n {
            return 0.0;
        }
        let mut best = unmatched[o] + go(o + 1, used, n, cost, unmatched);
        for i in 0..used.len() {
            if !used[i] {
                used[i] = true;
                best = best.min(cost(o, i) + go(o + 1, used, n, cost, unmatched));
                used[i] = false;
            }
        }
        best
    }
    go(0, &mut vec![false; inputs], outputs, cost, unmatched)
}

#[test]
fn robust_matching_is_as_cheap_as_a_brute_force_on_tiny_neighbourhoods() {
    let mut rng = tracery_core::random::SplitMix64::new(7);
    for case in 0..700 {
        let (outputs, inputs) = (case % 7, (case / 7) % 7);
        let costs: Vec<Vec<f64>> = (0..outputs)
            .map(|_| {
                (0..inputs)
                    .map(|_| {
                        let c = 3.0 * rng.next_unit();
                        // Now and then a forbidden pair (samples of different kinds).
                        if rng.next_unit() < 0.15 { f64::INFINITY } else { c }
                    })
                    .collect()
            })
            .collect();
        let unmatched: Vec<f64> = (0..outputs).map(|_| 0.5 + 2.0 * rng.next_unit()).collect();
        let cost = |o: usize, i: usize| costs[o][i];
        let m = robust_match(outputs, inputs, &cost, &unmatched);
        let best = brute_force(outputs, inputs, &cost, &unmatched);
        assert!((m.cost - best).abs() < 1e-5, "case {case}: matched {} but the best is {best}", m.cost);
        // A valid matching: each input at most once, and no forbidden pair.
        let mut used: Vec<usize> = m.input_of.iter().flatten().copied().collect();
        used.sort_unstable();
        used.dedup();
        assert_eq!(used.len(), m.input_of.iter().flatten().count(), "case {case}");
        assert!(m.input_of.iter().enumerate().all(|(o, i)| i.is_none_or(|i| costs[o][i].is_finite())));
    }
}

/// Distance from `p` to the nearest of `paths`, mm.
fn to_paths(paths: &[CurvePath], p: DVec2) -> f64 {
    let mut best = f64::MAX;
    for path in paths {
        for i in 0..path.segment_count() {
            let (a, b) = (path.segment_point(i, 0.0), path.segment_point(i, 1.0));
            let t = ((p - a).dot(b - a) / (b - a).length_squared().max(1e-300)).clamp(0.0, 1.0);
            best = best.min((a + (b - a) * t).distance(p));
        }
    }
    best
}

#[test]
fn the_built_ins_sample_graphs_follow_their_paths() {
    let delta_mm = 1.0;
    for name in BUILTIN_CURVES {
        let paths = builtin_curves(name).unwrap();
        let graph = SampleGraph::new(&paths, delta_mm).unwrap();
        assert!(graph.samples.len() > 50, "{name}: {} samples", graph.samples.len());
        for (s, sample) in graph.samples.iter().enumerate() {
            let off = to_paths(&paths, sample.position_mm);
            assert!(off <= JOIN_TOLERANCE_MM, "{name}: sample {s} is {off} mm off the paths");
            // In an exemplar each edge has its direction, and nothing else.
            assert_eq!(sample.orientations.len(), graph.neighbours[s].len(), "{name}: sample {s}");
        }
        let edges = graph.edges();
        let longest = edges
            .iter()
            .map(|[a, b]| graph.samples[*a as usize].position_mm.distance(graph.samples[*b as usize].position_mm))
            .fold(0.0, f64::max);
        assert!(longest <= delta_mm + 2.0 * JOIN_TOLERANCE_MM, "{name}: an edge is {longest} mm long");
        // The edges follow the paths: their length is the paths' less what chords cut off.
        let drawn: f64 = paths.iter().map(CurvePath::length_mm).sum();
        let sampled: f64 = edges
            .iter()
            .map(|[a, b]| graph.samples[*a as usize].position_mm.distance(graph.samples[*b as usize].position_mm))
            .sum();
        assert!(sampled <= drawn + 1e-6 && sampled > 0.9 * drawn, "{name}: edges {sampled:.1} mm, paths {drawn:.1} mm");
        // Ends: every open path end that touches no other path, counted on the polylines.
        let free_ends = paths
            .iter()
            .enumerate()
            .filter(|(_, p)| !p.closed)
            .flat_map(|(k, p)| [(k, p.points_mm[0]), (k, *p.points_mm.last().unwrap())])
            .filter(|&(k, end)| {
                let others: Vec<CurvePath> =
                    paths.iter().enumerate().filter(|(j, _)| *j != k).map(|(_, p)| p.clone()).collect();
                to_paths(&others, end) > JOIN_TOLERANCE_MM
            })
            .count();
        let ends = (0..graph.samples.len()).filter(|&s| graph.kind(s) == SampleKind::End).count();
        assert_eq!(ends, free_ends, "{name}");
    }
}

#[test]
fn crossings_and_touching_ends_are_junctions() {
    let line =
        |a: (f64, f64), b: (f64, f64)| CurvePath { points_mm: vec![DVec2::from(a), DVec2::from(b)], closed: false };
    // A plus: one junction of four branches; a T: one of three, the stem's end on the bar.
    let plus = SampleGraph::new(&[line((-5.0, 0.0), (5.0, 0.0)), line((0.0, -5.0), (0.0, 5.0))], 1.0).unwrap();
    let degrees = |g: &SampleGraph| {
        let mut d: Vec<usize> = g.neighbours.iter().map(|n| n.len()).filter(|&n| n > 2).collect();
        d.sort_unstable();
        d
    };
    assert_eq!(degrees(&plus), vec![4]);
    let tee = SampleGraph::new(&[line((-5.0, 0.0), (5.0, 0.0)), line((1.0, 5.0), (1.0, 0.02))], 1.0).unwrap();
    assert_eq!(degrees(&tee), vec![3]);
    // A loop touching nothing is sampled all round, every sample with two edges.
    let square = CurvePath {
        points_mm: vec![DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)],
        closed: true,
    };
    let ring = SampleGraph::new(&[square], 1.0).unwrap();
    assert_eq!(ring.samples.len(), 16);
    assert!(ring.neighbours.iter().all(|n| n.len() == 2));
}

#[test]
fn coarser_levels_keep_every_end_and_junction() {
    for name in BUILTIN_CURVES {
        // The curves the fill learns: small filled shapes are elements, not paths.
        let learned = CurveExemplar::builtin(name).unwrap().curves(1.0);
        let levels = hierarchy(&learned.paths, 1.0).unwrap();
        let special = |g: &SampleGraph| (0..g.samples.len()).filter(|&s| g.kind(s) != SampleKind::Path).count();
        assert_eq!(special(&levels[0]), special(&levels[2]), "{name}");
        assert!(levels[0].samples.len() * 2 < levels[2].samples.len(), "{name}");
    }
}

#[test]
fn a_neighbourhood_matches_itself_anywhere_and_differs_from_another_pattern() {
    use tracery_core::region_fill::{SampleGrid, Similarity, neighbourhood_distance};
    let (delta_mm, radius_mm) = (1.5, 4.5);
    let similarity = Similarity::new(delta_mm);
    let crackle = SampleGraph::new(&builtin_curves("crackle").unwrap(), delta_mm).unwrap();
    // The same pattern moved far away: offsets from the centres are the same.
    let moved_paths: Vec<CurvePath> = builtin_curves("crackle")
        .unwrap()
        .into_iter()
        .map(|p| CurvePath { points_mm: p.points_mm.iter().map(|q| *q + DVec2::new(300.0, -120.0)).collect(), ..p })
        .collect();
    let moved = SampleGraph::new(&moved_paths, delta_mm).unwrap();
    let (grid, moved_grid) = (SampleGrid::new(&crackle, radius_mm), SampleGrid::new(&moved, radius_mm));
    let waves = SampleGraph::new(&builtin_curves("waves").unwrap(), delta_mm).unwrap();
    let waves_grid = SampleGrid::new(&waves, radius_mm);
    let junction = (0..crackle.samples.len()).find(|&s| crackle.kind(s) == SampleKind::Junction).unwrap();
    for s in [junction, 10, 100, 200] {
        let centre = crackle.samples[s].position_mm;
        let members = grid.within(&crackle, centre, radius_mm);
        assert!(members.len() >= 5, "sample {s}: {} neighbours", members.len());
        let itself = neighbourhood_distance(&crackle, s, &members, &crackle, s, &members, &similarity);
        assert!(itself.cost < 1e-9, "sample {s} against itself: {}", itself.cost);
        assert!(itself.input_of.iter().enumerate().all(|(o, i)| *i == Some(o)), "each sample is matched to itself");
        // The moved copy: the same sample there, found by position.
        let twin = moved_grid.within(&moved, centre + DVec2::new(300.0, -120.0), 1e-6)[0] as usize;
        let twin_members = moved_grid.within(&moved, moved.samples[twin].position_mm, radius_mm);
        let across = neighbourhood_distance(&crackle, s, &members, &moved, twin, &twin_members, &similarity);
        assert!(across.cost < 1e-6, "sample {s} against its moved twin: {}", across.cost);
        // No neighbourhood of the waves is as like a crack's as itself.
        let best_wave = (0..waves.samples.len())
            .map(|w| {
                let wm = waves_grid.within(&waves, waves.samples[w].position_mm, radius_mm);
                neighbourhood_distance(&crackle, s, &members, &waves, w, &wm, &similarity).cost
            })
            .fold(f64::MAX, f64::min);
        assert!(best_wave > 0.1 * delta_mm, "sample {s}: a wave neighbourhood costs only {best_wave}");
    }
    // At the junction the waves have nothing alike: it costs more than along a crack.
    let at = |s: usize| {
        let members = grid.within(&crackle, crackle.samples[s].position_mm, radius_mm);
        (0..waves.samples.len())
            .map(|w| {
                let wm = waves_grid.within(&waves, waves.samples[w].position_mm, radius_mm);
                neighbourhood_distance(&crackle, s, &members, &waves, w, &wm, &similarity).cost
            })
            .fold(f64::MAX, f64::min)
    };
    let along = (0..crackle.samples.len())
        .find(|&s| {
            crackle.kind(s) == SampleKind::Path
                && grid
                    .within(&crackle, crackle.samples[s].position_mm, radius_mm)
                    .iter()
                    .all(|&n| crackle.kind(n as usize) == SampleKind::Path)
        })
        .unwrap();
    assert!(at(junction) > at(along), "junction {} vs along a crack {}", at(junction), at(along));
}

#[test]
fn patch_match_finds_each_sample_of_a_moved_copy() {
    use tracery_core::region_fill::{Neighbourhoods, SearchSettings, search};
    // Not a whole number of spacings: samples right on the rim would be in
    // one neighbourhood and out of its moved twin by a rounding.
    let (delta_mm, radius_mm) = (1.5, 4.7);
    for name in ["crackle", "vine"] {
        let paths = builtin_curves(name).unwrap();
        let input = SampleGraph::new(&paths, delta_mm).unwrap();
        // The input's own graph moved (not sampled again, which could decide
        // a borderline join differently and test the sampler instead).
        let shift = DVec2::new(500.0, 70.0);
        let mut output = input.clone();
        for sample in &mut output.samples {
            sample.position_mm += shift;
        }
        let settings = SearchSettings::new(radius_mm, delta_mm);
        let near = |g: &SampleGraph| Neighbourhoods::new(g, radius_mm);
        let field = search((&output, &near(&output)), (&input, &near(&input)), None, &settings);
        assert_eq!(field.input_of.len(), output.samples.len());
        // Found: matched to the very sample it was copied from, or to one
        // whose neighbourhood is as alike (along a smooth stem many are):
        // the twin costs 0.
        let twin = (0..output.samples.len())
            .filter(|&o| {
                let i = field.input_of[o] as usize;
                input.samples[i].position_mm.distance(output.samples[o].position_mm - shift) < 1e-6
            })
            .count();
        let found = field.cost.iter().filter(|&&c| c < 1e-6).count();
        let share = found as f64 / output.samples.len() as f64;
        eprintln!("{name}: of {} samples, {twin} matched their twin, {found} one as alike", output.samples.len());
        assert!(share > 0.9, "{name}: only {:.0}% found", 100.0 * share);
        let mean = field.cost.iter().sum::<f64>() / field.cost.len() as f64;
        assert!(mean < 0.1 * delta_mm, "{name}: mean neighbourhood distance {mean}");
    }
}

/// Shares of ends and junctions among the samples of `paths` sampled at `delta_mm`.
fn degree_shares(paths: &[CurvePath], delta_mm: f64) -> (f64, f64) {
    let graph = SampleGraph::new(paths, delta_mm).unwrap();
    let n = graph.samples.len() as f64;
    let count = |kind| (0..graph.samples.len()).filter(|&s| graph.kind(s) == kind).count() as f64 / n;
    (count(SampleKind::End), count(SampleKind::Junction))
}

#[test]
fn a_crackle_fill_stays_in_its_rectangle_and_keeps_the_exemplars_junctions() {
    use tracery_core::region_fill::{Settings, fill_rectangle};
    let exemplar = builtin_curves("crackle").unwrap();
    let settings = Settings::default();
    let (width, height) = (36.0, 24.0);
    let paths = fill_rectangle(&exemplar, width, height, &settings).unwrap();
    let all: Vec<DVec2> = paths.iter().flat_map(|p| p.points_mm.iter().copied()).collect();
    assert!(all.len() > 100, "{} points", all.len());
    assert!(all.iter().all(|p| p.x >= -1e-9 && p.y >= -1e-9 && p.x <= width + 1e-9 && p.y <= height + 1e-9));
    // Counted on the output's own paths, sampled again: junctions are as
    // common as in the exemplar, within a factor of two.
    let (_, exemplar_junctions) = degree_shares(&exemplar, settings.delta_mm);
    let (_, fill_junctions) = degree_shares(&paths, settings.delta_mm);
    eprintln!("junctions: exemplar {exemplar_junctions:.3}, fill {fill_junctions:.3}");
    assert!(
        fill_junctions > 0.5 * exemplar_junctions && fill_junctions < 2.0 * exemplar_junctions,
        "junctions: exemplar {exemplar_junctions:.3}, fill {fill_junctions:.3}"
    );
}

#[test]
fn a_bounded_comparison_gives_up_only_when_the_full_one_is_no_cheaper() {
    use tracery_core::region_fill::{NeighbourhoodPair, SampleGrid, Similarity, edge_vectors, neighbourhood_distance};
    let (delta_mm, radius_mm) = (1.5, 4.7);
    let similarity = Similarity::new(delta_mm);
    let crackle = SampleGraph::new(&builtin_curves("crackle").unwrap(), delta_mm).unwrap();
    let vine = SampleGraph::new(&builtin_curves("vine").unwrap(), delta_mm).unwrap();
    let (cg, vg) = (SampleGrid::new(&crackle, radius_mm), SampleGrid::new(&vine, radius_mm));
    let (crackle_edges, vine_edges) = (edge_vectors(&crackle), edge_vectors(&vine));
    let (mut pruned, mut kept) = (0, 0);
    for o in (0..crackle.samples.len()).step_by(17) {
        let members_o = cg.within(&crackle, crackle.samples[o].position_mm, radius_mm);
        for i in (0..vine.samples.len()).step_by(23) {
            let members_i = vg.within(&vine, vine.samples[i].position_mm, radius_mm);
            let full = neighbourhood_distance(&crackle, o, &members_o, &vine, i, &members_i, &similarity);
            let pair = NeighbourhoodPair {
                output: &crackle,
                output_edges: &crackle_edges,
                s_o: o,
                members_o: &members_o,
                input: &vine,
                input_edges: &vine_edges,
                s_i: i,
                members_i: &members_i,
            };
            for bound in [0.5 * full.cost, 0.999 * full.cost, 1.001 * full.cost + 1e-9, 2.0 * full.cost + 1e-9] {
                match pair.distance_below(&similarity, bound) {
                    None => {
                        assert!(full.cost >= bound - 1e-9, "gave up below {bound} on a pair costing {}", full.cost);
                        pruned += 1;
                    }
                    Some(m) => {
                        assert!((m.cost - full.cost).abs() < 1e-9, "{} against {}", m.cost, full.cost);
                        kept += 1;
                    }
                }
            }
        }
    }
    assert!(pruned > 0 && kept > 0, "both outcomes tried: {pruned} pruned, {kept} kept");
}

/// Fills of every built-in, measured by `quality::curve_statistics` (which
/// reads only the output's polylines, never the synthesis's graph) against
/// the exemplar measured the same way.
#[test]
fn fills_look_like_their_exemplars_by_independent_measures() {
    use tracery_core::control::Control;
    use tracery_core::geom::{Rect, Region};
    use tracery_core::quality::{
        CURVATURE_BIN, ORIENTATION_BINS, coverage, curve_statistics_within, histogram_emd, histogram_emd_circular,
    };
    use tracery_core::region_fill::{CurveExemplar, Settings, make_product, parse_region};
    let settings = Settings::default();
    let margin = settings.radius_mm();
    let region = parse_region("rect:50x35").unwrap();
    let bounds = region.bounds().unwrap();
    for name in BUILTIN_CURVES {
        let exemplar = CurveExemplar::builtin(name).unwrap();
        // Measured on what the fill learns as curves: the outlines of
        // elements (the berries) are drawn filled, not stroked.
        let learned = exemplar.curves(settings.delta_mm);
        let ex_paths: Vec<_> = learned.paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
        let ex_bounds = Rect::from_points(ex_paths.iter().flat_map(|p| p.0.iter().copied())).unwrap();
        let ex = curve_statistics_within(&ex_paths, &ex_bounds, margin);
        let ex_region = Region::rectangle(&ex_bounds);
        let product = make_product(&exemplar, &region, &settings, &Control::default()).unwrap();
        let paths: Vec<_> = product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
        let out = curve_statistics_within(&paths, &bounds, margin);
        let near = |a: f64, b: f64, what: &str| {
            assert!(
                (a - b).abs() <= 0.5 * b.max(a) + 1.5,
                "{name}: {what} {a:.1} per 100 mm against the exemplar's {b:.1}"
            );
        };
        near(out.ends_per_100mm, ex.ends_per_100mm, "free ends");
        near(out.junctions_per_100mm, ex.junctions_per_100mm, "junctions");
        if ex.junctions_per_100mm == 0.0 {
            assert_eq!(out.junctions_per_100mm, 0.0, "{name}: paths meet where the exemplar's never do");
        }
        if ex.crossings_per_100mm == 0.0 {
            assert_eq!(out.crossings_per_100mm, 0.0, "{name}: paths cross where the exemplar's never do");
        }
        let curvature = histogram_emd(&out.curvature, &ex.curvature, CURVATURE_BIN);
        let orientation = histogram_emd_circular(&out.orientation, &ex.orientation, 180.0 / ORIENTATION_BINS as f64);
        // Within 0.05 /mm: the meander's square corners, rounded off, were 0.10.
        assert!(curvature < 0.05, "{name}: curvature {curvature:.3} /mm from the exemplar's");
        assert!(orientation < 12.0, "{name}: orientation {orientation:.1}° from the exemplar's");
        let (cover, ex_cover) = (coverage(&paths, &region, margin), coverage(&ex_paths, &ex_region, margin));
        assert!(
            cover >= 0.8 * ex_cover,
            "{name}: covers {cover:.2} of the region, the exemplar {ex_cover:.2} of its own"
        );
    }
}

/// The spirals never meet in their exemplar. Seeds 1 and 2 used to join
/// two spirals by a stray loop; counted on the final paths by
/// `quality::curve_statistics`, no path now meets another.
#[test]
fn spirals_fills_have_no_junctions_as_their_exemplar_has_none() {
    use tracery_core::control::Control;
    use tracery_core::quality::curve_statistics;
    use tracery_core::region_fill::{CurveExemplar, Settings, make_product, parse_region};
    let exemplar = CurveExemplar::builtin("spirals").unwrap();
    let ex_paths: Vec<_> = exemplar.curves(1.5).paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
    assert_eq!(curve_statistics(&ex_paths).junctions_per_100mm, 0.0);
    let region = parse_region("rect:60x40").unwrap();
    for seed in 1..=3 {
        let mut settings = Settings::default();
        settings.seed = seed;
        let product = make_product(&exemplar, &region, &settings, &Control::default()).unwrap();
        let paths: Vec<_> = product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
        let out = curve_statistics(&paths);
        assert_eq!(out.junctions_per_100mm, 0.0, "seed {seed}: paths meet");
    }
}

#[test]
fn the_grids_nearest_sample_is_the_first_of_those_within_reach() {
    // The crackle's samples, looked up from points in and around it, with
    // reaches from under a cell to the whole exemplar: the ring-by-ring
    // search must find what gathering and sorting finds.
    let graph = SampleGraph::new(&builtin_curves("crackle").unwrap(), 1.5).unwrap();
    let grid = SampleGrid::new(&graph, 4.6);
    let mut state = 7u64;
    let mut unit = || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..2000 {
        let centre = DVec2::new(unit() * 60.0 - 10.0, unit() * 60.0 - 10.0);
        let reach = 0.5 + unit() * 30.0;
        assert_eq!(grid.nearest(&graph, centre, reach), grid.within(&graph, centre, reach).first().copied());
    }
}

#[test]
fn a_larger_exemplar_scale_gives_a_coarser_fill() {
    // The waves drawn twice as large repeat half as often: the fill's
    // curves, per square millimetre, are about half as long.
    let exemplar = CurveExemplar::builtin("waves").unwrap();
    let region = parse_region("rect:60x40").unwrap();
    let length = |scale: f64| {
        let mut settings = Settings::default();
        settings.exemplar_scale = scale;
        let product = make_product(&exemplar, &region, &settings, &Control::default()).unwrap();
        product.paths_mm.iter().map(|p| p.points_mm.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()).sum::<f64>()
    };
    let ratio = length(2.0) / length(1.0);
    assert!((0.35..=0.65).contains(&ratio), "twice the scale gives {ratio:.2} of the length");
}
