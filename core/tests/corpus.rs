//! A short subset of the corpus sweep, run in CI: real ornaments no one here
//! drew, along a line and a loop, with N-component targets, checked on the
//! final geometry by measures the solver does not see. The whole sweep is
//! `cargo run -p tracery-core --release --example sweep` (see docs/quality.md).
//! Skipped, with a line saying so, where the corpus is not next to the checkout.

use std::path::PathBuf;

use tracery_core::control::Control;
use tracery_core::curve::{Curve, planar_topology};
use tracery_core::mesh::extrude;
use tracery_core::quality::{max_distance_from, near_period};
use tracery_core::vector_brush::{Exemplar, LoadOptions, Settings, SolveError, SynthesisError, Target, synthesize};

fn corpus() -> Vec<PathBuf> {
    let dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus/ornaments"));
    let mut files: Vec<PathBuf> = match std::fs::read_dir(&dir) {
        Ok(entries) => entries.filter_map(|e| e.ok().map(|e| e.path())).collect(),
        Err(_) => return Vec::new(),
    };
    files.retain(|p| p.extension().is_some_and(|x| x == "svg"));
    files.sort();
    files
}

/// One ornament of the corpus, or `None`, with a line saying so, where the
/// corpus is not next to this checkout.
fn corpus_file(name: &str) -> Option<PathBuf> {
    let files = corpus();
    if files.is_empty() {
        eprintln!("the corpus is not next to this checkout; nothing to run");
        return None;
    }
    Some(files.into_iter().find(|f| f.file_name().is_some_and(|n| n == name)).expect("in the corpus"))
}

#[test]
fn corpus_subset_meets_its_plan_in_the_band() {
    let files = corpus();
    if files.is_empty() {
        eprintln!("the corpus is not next to this checkout; nothing to sweep");
        return;
    }
    // Every 30th ornament: both families, decided by name order alone.
    // Plus ornaments that once came out unlike their plan (see the end).
    let regressions = ["vectorian56.svg", "vectorian111.svg", "vectorian169.svg", "vectorian174.svg"];
    let chosen: Vec<&PathBuf> = files
        .iter()
        .enumerate()
        .filter(|(i, f)| i % 30 == 0 || f.file_name().is_some_and(|n| regressions.iter().any(|r| n == *r)))
        .map(|(_, f)| f)
        .collect();
    let curves = [Curve::line(120.0).unwrap(), Curve::circle(30.0).unwrap()];
    let targets = [(Target::Exactly(1), Target::Any), (Target::Exactly(2), Target::Any), (Target::Any, Target::Any)];
    let mut answered = 0;
    let mut runs = 0;
    let mut inexact: Vec<String> = Vec::new();
    for file in chosen {
        let exemplar = Exemplar::from_svg_file(file, &LoadOptions::default()).unwrap();
        for curve in &curves {
            for &(components, holes) in &targets {
                let mut settings = Settings::default();
                settings.components = components;
                settings.holes = holes;
                let context = format!("{} {components:?}/{holes:?} closed={}", exemplar.name, curve.is_closed());
                runs += 1;
                let s = match synthesize(&exemplar, curve, &settings, &Control::default()) {
                    Ok(s) => s,
                    // "No solution" is an answer, with its reason.
                    Err(SynthesisError::Solve(SolveError::NoSolution(_))) => continue,
                    Err(e) => panic!("{context}: {e}"),
                };
                answered += 1;
                // Counted on the final geometry (apart from the pipeline's own
                // count, which must agree), equal to the plan and the target.
                let topology = planar_topology(&s.planar.region, &s.curve);
                assert_eq!(topology, s.topology, "{context}: the pipeline's own count");
                let counted = (topology.components as u32, topology.holes as u32);
                if counted != (s.solution.components, s.solution.holes) || !components.accepts(counted.0) {
                    inexact.push(format!(
                        "{context}: planned {}c {}h, counted {}c {}h",
                        s.solution.components, s.solution.holes, counted.0, counted.1
                    ));
                }
                match extrude(&s.planar.region, settings.thickness_mm) {
                    Ok(mesh) => assert_eq!(mesh.shell_count() as u32, counted.0, "{context}: bodies"),
                    Err(e) => inexact.push(format!("{context}: {e}")),
                }
                // In the band: within half of it plus 5% of the curve.
                let drift = max_distance_from(&s.planar.region, curve);
                assert!(drift <= 0.5 * settings.band_mm * 1.05, "{context}: {drift} mm from the curve");
            }
        }
    }
    assert!(answered * 3 >= runs, "only {answered} of {runs} runs were answered");
    // Every mismatch is a bug. Three such were found here: bends that folded
    // thin strokes over themselves (vectorian56), end pieces narrower than
    // the gap at a break turned inside out (vectorian174), and parts touching
    // at a point merged once mapped onto a loop (vectorian111). One more
    // comes from the exemplar itself: curls grazing a stroke through a neck
    // a thousandth of a millimetre wide, pinched off by every sequence
    // (vectorian169: its narrow gaps are closed and it is analysed again).
    println!("{answered} of {runs} answered, {} not as planned", inexact.len());
    assert!(inexact.is_empty(), "{} of {answered} differ from the plan: {inexact:#?}", inexact.len());
}

/// Runs whose mapped pattern once differed from their plan, each for a
/// reason of its own (`docs/quality.md`, *Seams that lean*): a part's tip on
/// the middle of another's edge, merged once mapped along a wave
/// (`vectorian139`), and a neck on the inside of a star's turn cut through
/// by its chords (`vectorian169`); since exemplars are flattened finer,
/// those two come out as planned when mapped once. And a pattern whose
/// planned parts include specks, the tips of stars that cuts graze
/// (`vectorian142`: 174 planned, 152 counted with the specks dropped). And
/// a tip thinner than twice the stitching tolerance, whose long side's
/// chord crossed its other side and pinched off specks the plan never had
/// (`vectorian157` with 2 parts asked: 2 planned, 7 counted). And parts
/// 10⁻⁵ mm apart, which rounding to `f32` laid edge on edge and the mesh
/// welded (`vectorian195`: 330 parts, 329 bodies).
/// Counted on the final geometry.
#[test]
fn runs_once_mapped_unlike_their_plan_come_out_as_planned() {
    let runs = [
        ("vectorian139.svg", Curve::wave(200.0).unwrap(), Target::Any, Target::Any, Settings::default().variety),
        ("vectorian169.svg", Curve::star(5, 45.0).unwrap(), Target::Exactly(1), Target::Exactly(0), 0.6),
        ("vectorian142.svg", Curve::line(200.0).unwrap(), Target::Any, Target::Any, Settings::default().variety),
        ("vectorian157.svg", Curve::line(200.0).unwrap(), Target::Exactly(2), Target::Any, Settings::default().variety),
        ("vectorian195.svg", Curve::wave(200.0).unwrap(), Target::Any, Target::Any, Settings::default().variety),
    ];
    for (name, curve, components, holes, variety) in runs {
        let Some(file) = corpus_file(name) else { return };
        let exemplar = Exemplar::from_svg_file(&file, &LoadOptions::default()).unwrap();
        let mut settings = Settings::default();
        (settings.components, settings.holes, settings.variety) = (components, holes, variety);
        settings.closed_pattern = curve.is_closed();
        let s = synthesize(&exemplar, &curve, &settings, &Control::default()).unwrap();
        let topology = planar_topology(&s.planar.region, &s.curve);
        let counted = (topology.components as u32, topology.holes as u32);
        assert_eq!(counted, (s.solution.components, s.solution.holes), "{name}: counted against the plan");
        let mesh = extrude(&s.planar.region, settings.thickness_mm).unwrap();
        assert_eq!(mesh.shell_count() as u32, counted.0, "{name}: bodies");
    }
}

/// A corner ornament whose plain rule seams exactly with itself
/// (`vectorian36`): at the default variety the cheapest pattern along a line
/// was that rule 150 times over, its flourishes at one end only, because
/// the variety term grows with the pattern just as the seams' cost does.
/// Such a pattern is searched again with variety weighing more, and the
/// result varies: its near-period, measured on shape classes apart from the
/// solver, is at least a third of the pattern (it was 0.006 of it).
#[test]
fn a_rule_that_seams_with_itself_gives_way_to_variety() {
    let Some(file) = corpus_file("vectorian36.svg") else { return };
    let exemplar = Exemplar::from_svg_file(&file, &LoadOptions::default()).unwrap();
    let settings = Settings::default();
    let s = synthesize(&exemplar, &Curve::line(200.0).unwrap(), &settings, &Control::default()).unwrap();
    let n = s.shape_classes.len();
    let period = near_period(&s.shape_classes);
    assert!(3 * period >= n, "near-period {period} of {n} pieces: {:?}", s.shape_classes);
    let topology = planar_topology(&s.planar.region, &s.curve);
    assert_eq!((topology.components as u32, topology.holes as u32), (s.solution.components, s.solution.holes));
    // With variety off, the person asked for the cheapest seams: the rule stays.
    let mut plain = settings.clone();
    plain.variety = 0.0;
    let s = synthesize(&exemplar, &Curve::line(200.0).unwrap(), &plain, &Control::default()).unwrap();
    assert!(3 * near_period(&s.shape_classes) < s.shape_classes.len());
}

/// A pattern whose outline doubles back within `f32` rounding of itself
/// (`vectorian139`'s joined strokes, with the spikes loading drops kept)
/// once meshed into an open solid without a word: the flood that fills the
/// caps put material on the wrong side of the outline. Meshing must give a
/// closed solid or an error, never an open one. Checked on the mesh.
#[test]
fn an_outline_doubling_back_within_rounding_never_meshes_open() {
    let Some(file) = corpus_file("vectorian139.svg") else { return };
    let mut options = LoadOptions::default();
    options.relative_needle_width = 0.0;
    let exemplar = Exemplar::from_svg_file(&file, &options).unwrap();
    let mut settings = Settings::default();
    (settings.components, settings.holes) = (Target::Any, Target::Any);
    let s = synthesize(&exemplar, &Curve::line(200.0).unwrap(), &settings, &Control::default()).unwrap();
    if let Ok(mesh) = extrude(&s.planar.region, settings.thickness_mm) {
        mesh.sanity_check().unwrap();
        assert_eq!(mesh.shell_count() as u32, s.solution.components);
    }
    // With the spikes dropped, as loading does by default, it meshes.
    let exemplar = Exemplar::from_svg_file(&file, &LoadOptions::default()).unwrap();
    let s = synthesize(&exemplar, &Curve::line(200.0).unwrap(), &settings, &Control::default()).unwrap();
    let mesh = extrude(&s.planar.region, settings.thickness_mm).unwrap();
    mesh.sanity_check().unwrap();
    assert_eq!(mesh.shell_count() as u32, s.solution.components);
}

/// Region fills of corpus ornaments that once crossed themselves where
/// their exemplar never does (`docs/region-fill.md`, *Crossings*): checked
/// by the quality measure, not the code that cuts crossings.
#[test]
fn fills_of_corpus_ornaments_cross_only_where_their_exemplar_does() {
    use tracery_core::geom::Rect;
    use tracery_core::quality::curve_statistics;
    use tracery_core::region_fill::{CurveExemplar, Settings as FillSettings, make_product, parse_region};
    let files = corpus();
    if files.is_empty() {
        eprintln!("the corpus is not next to this checkout; nothing to fill");
        return;
    }
    let region = parse_region("rect:60x40").unwrap();
    for name in ["vectorian92", "vectorian100", "pgfhan52"] {
        let file = files.iter().find(|f| f.file_stem().is_some_and(|s| s == name)).expect("in the corpus");
        let exemplar = CurveExemplar::load(&file.to_string_lossy()).unwrap();
        let bounds = Rect::from_points(exemplar.paths.iter().flat_map(|p| p.points_mm.iter().copied())).unwrap();
        let mut settings = FillSettings::default();
        // 40 mm across, as the sweep draws them.
        settings.exemplar_scale = 40.0 / bounds.width().max(bounds.height());
        let learned = exemplar.scaled(settings.exemplar_scale).curves(settings.delta_mm);
        let ex_paths: Vec<_> = learned.paths.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
        assert_eq!(curve_statistics(&ex_paths).crossings_per_100mm, 0.0, "{name}: the exemplar crosses itself");
        let product = make_product(&exemplar, &region, &settings, &Control::default()).unwrap();
        let paths: Vec<_> = product.paths_mm.iter().map(|p| (p.points_mm.clone(), p.closed)).collect();
        let out = curve_statistics(&paths);
        assert_eq!(out.crossings_per_100mm, 0.0, "{name}: the fill crosses itself");
        assert!(out.length_mm > 300.0, "{name}: only {:.0} mm of paths", out.length_mm);
    }
}

/// The share of a region's outline length, in band space, that runs within
/// `tolerance_deg` of along or across the band.
fn upright_share(region: &tracery_core::geom::Region, tolerance_deg: f64) -> f64 {
    let (mut upright, mut total) = (0.0, 0.0);
    for ring in region.rings() {
        for (i, &a) in ring.iter().enumerate() {
            let b = ring[(i + 1) % ring.len()];
            let d = b - a;
            let length = d.length();
            // Degrees off the nearest axis, from 0 to 45.
            let angle = d.y.atan2(d.x).to_degrees().rem_euclid(90.0);
            if angle.min(90.0 - angle) <= tolerance_deg {
                upright += length;
            }
            total += length;
        }
    }
    upright / total.max(f64::MIN_POSITIVE)
}

/// A fret (`pgfhan43`, bars and hooks at right angles) has seams that fit
/// exactly to vary it with, and others that move its bars by more than their
/// thickness. The variety term used to buy the second kind, which bent the
/// bars into S-curves; seams that do not fit now cost what they do to the
/// pattern (`docs/solver.md`, *Seams that do not fit*). Checked on the
/// stitched outline: nearly all of it still runs along or across the band,
/// and the pattern is still varied (no period under a third of it).
#[test]
fn a_fret_keeps_its_bars_straight_and_still_varies() {
    let Some(file) = corpus_file("pgfhan43.svg") else { return };
    let exemplar = Exemplar::from_svg_file(&file, &LoadOptions::default()).unwrap();
    let drawn = upright_share(&exemplar.region, 1.0);
    assert!(drawn > 0.99, "the fret as drawn: {drawn}");
    for curve in [Curve::line(200.0).unwrap(), Curve::circle(40.0).unwrap()] {
        let mut settings = Settings::default();
        settings.closed_pattern = curve.is_closed();
        let s = synthesize(&exemplar, &curve, &settings, &Control::default()).unwrap();
        let context = format!("closed={}", curve.is_closed());
        let upright = upright_share(&s.band.region, 1.0);
        assert!(upright > 0.97, "{context}: {:.1} % of the outline along or across the band", 100.0 * upright);
        let classes = &s.shape_classes;
        let period = near_period(classes);
        assert!(3 * period >= classes.len(), "{context}: repeats every {period} of {} pieces", classes.len());
    }
}
