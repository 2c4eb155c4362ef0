//! The corpus sweep: every ornament of a folder along several curves, with
//! several topology targets, through the whole pipeline (synthesis and
//! meshing), checked by measures the solver does not see.
//!
//! The curves are generated ones (`line:200`, `circle:40`, the frames) and
//! strokes drawn by hand (`drawn-loops`, `drawn-open`), which people bring
//! and which no generated curve stands for.
//!
//! ```text
//! cargo run -p tracery-core --release --example sweep -- \
//!     [--corpus DIR] [--every K] [--curves line,circle,...] [--targets 1/any,...] \
//!     [--csv OUT.csv] [--markdown OUT.md] [--variety WEIGHT] [--corner-radius MM]
//! ```
//!
//! Each run records whether it was answered, whether the topology counted on
//! the final geometry equals the plan and the target, how far the geometry
//! strays from the curve (in half bands), the near period and longest repeat
//! of the shape classes along the pattern, the seam tangent jump (and, for a short period, whether a much higher
//! variety weight avoids it), the stitching's worst stretch and shear of the pieces, how far
//! the seams' endpoints were apart before stitching closed them, and the
//! time of the whole pipeline. The summary prints one row per curve.

#[path = "common/corpus.rs"]
mod corpus;
#[path = "common/sheet.rs"]
mod sheet;

use std::path::PathBuf;
use std::time::Instant;

use tracery_core::control::Control;
use tracery_core::curve::{Along, Curve, DrawnStroke, Hand, StrokeShape, planar_topology};
use tracery_core::export::region_to_svg;
use tracery_core::geom::Region;
use tracery_core::mesh::extrude;
use tracery_core::quality::{longest_repeat, max_distance_from, near_period, seam_kinks_deg};
use tracery_core::vector_brush::{Exemplar, LoadOptions, Settings, SolveError, SynthesisError, Target, synthesize};

struct Args {
    corpus: PathBuf,
    every: usize,
    curves: Vec<String>,
    targets: Vec<(Target, Target)>,
    csv: Option<PathBuf>,
    markdown: Option<PathBuf>,
    /// Where to write each answered pattern as SVG (for contact sheets).
    svg_dir: Option<PathBuf>,
    /// Where to write contact sheets: one PNG per curve, of the first target's answers.
    sheets: Option<PathBuf>,
    /// Only ornaments whose name contains this.
    only: Option<String>,
    /// The variety weight, instead of the default setting's.
    variety: Option<f64>,
    /// The corner radius asked for, mm, instead of the default setting's.
    corner_radius_mm: Option<f64>,
}

const CURVES: [&str; 8] =
    ["line:200", "circle:40", "wave:200", "square:70", "hexagon:40", "star:45", "drawn-loops", "drawn-open"];

/// The curves a sweep runs along: one for every ornament, or one drawn by
/// hand for each (`drawn-loops`, `drawn-open`: the shapes of
/// `DrawnStroke::shapes`, each ornament along the next one, by a fast and a
/// slow hand in turn, smoothed as the app smooths a stroke).
enum Curves {
    Fixed(Curve),
    Drawn(Vec<StrokeShape>),
}

impl Curves {
    fn parse(spec: &str) -> Curves {
        let shapes = DrawnStroke::shapes();
        match spec {
            "drawn-loops" => Curves::Drawn(shapes.into_iter().filter(|s| s.is_loop()).collect()),
            "drawn-open" => Curves::Drawn(shapes.into_iter().filter(|s| !s.is_loop()).collect()),
            _ => match Along::parse(spec) {
                Ok(Along::Curve(c)) => Curves::Fixed(c),
                other => panic!("{spec} is not a curve: {other:?}"),
            },
        }
    }

    /// The curve for the `k`th ornament.
    fn for_ornament(&self, k: usize) -> Curve {
        match self {
            Curves::Fixed(c) => c.clone(),
            Curves::Drawn(shapes) => {
                let hand = if (k / shapes.len()).is_multiple_of(2) { Hand::Fast } else { Hand::Slow };
                DrawnStroke::new(shapes[k % shapes.len()], hand, k as u64).curve().expect("drawn strokes are long")
            }
        }
    }
}
const TARGETS: [&str; 4] = ["1/any", "any/any", "1/0", "2/any"];

fn target(text: &str) -> Target {
    if text == "any" { Target::Any } else { Target::Exactly(text.parse().expect("a target is a number or 'any'")) }
}

fn parse_args() -> Args {
    let mut args = Args {
        corpus: PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpus/ornaments")),
        every: 1,
        curves: CURVES.iter().map(|s| s.to_string()).collect(),
        targets: TARGETS.iter().map(|t| t.split_once('/').map(|(c, h)| (target(c), target(h))).unwrap()).collect(),
        csv: None,
        markdown: None,
        svg_dir: None,
        sheets: None,
        only: None,
        variety: None,
        corner_radius_mm: None,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let value = it.next().unwrap_or_else(|| panic!("{flag} needs a value"));
        match flag.as_str() {
            "--corpus" => args.corpus = value.into(),
            "--every" => args.every = value.parse().expect("--every K"),
            "--curves" => {
                args.curves = value
                    .split(',')
                    .map(|c| CURVES.iter().find(|k| k.starts_with(c)).map_or(c.to_string(), |k| k.to_string()))
                    .collect()
            }
            "--targets" => {
                args.targets =
                    value.split(',').map(|t| t.split_once('/').map(|(c, h)| (target(c), target(h))).unwrap()).collect()
            }
            "--csv" => args.csv = Some(value.into()),
            "--markdown" => args.markdown = Some(value.into()),
            "--svg-dir" => args.svg_dir = Some(value.into()),
            "--only" => args.only = Some(value),
            "--sheets" => args.sheets = Some(value.into()),
            "--variety" => args.variety = Some(value.parse().expect("--variety WEIGHT")),
            "--corner-radius" => args.corner_radius_mm = Some(value.parse().expect("--corner-radius MM")),
            _ => panic!("unknown flag {flag}"),
        }
    }
    args
}

#[derive(Clone, Debug)]
struct Run {
    /// The pattern, kept for contact sheets.
    region: Option<Region>,
    ornament: String,
    curve: String,
    target: String,
    /// ok, none (no solution), cap, mesh, error.
    status: &'static str,
    reason: String,
    exact: bool,
    drift: f64,
    period: f64,
    repeat: f64,
    seam_deg: f64,
    /// The stitching's worst stretch and shear (degrees) of the pieces, as reported.
    stretch: f64,
    shear_deg: f64,
    /// The largest seam gap stitching closed, in exemplar heights
    /// (`BandPattern::seam_gaps`), and the share of joined seams whose gap
    /// is past [`POOR_FIT`].
    gap: f64,
    bad: f64,
    pieces: usize,
    time_ms: f64,
    states: usize,
    /// The beam width where the exact search passed the state cap and the
    /// bounded search answered.
    bounded: Option<usize>,
    /// Whether the exact search passed the state cap and the search that
    /// drops dominated partial patterns answered.
    dominance: bool,
    /// Milliseconds in analysis, solve, geometry and meshing.
    stages: String,
    /// The solver's matching cost and autocorrelation, to compare with the
    /// independent measures above.
    matching: f64,
    auto: f64,
    /// For a run with a short period: whether the same run with the variety
    /// weight at [`PROBE_VARIETY`] found an answer without one, which shows
    /// that the period was the default weight's choice and not forced by the
    /// band and the targets.
    avoidable: bool,
}

/// The variety weight of the probe for short periods: far above the default
/// (0.8), so that variety outweighs every seam.
const PROBE_VARIETY: f64 = 30.0;

/// A seam gap, in exemplar heights, past which a seam reads as a poor fit:
/// a stroke moved by more than about its own width, a fret's bar bent into
/// an S.
const POOR_FIT: f64 = 0.15;

fn short_period(run: &Run) -> bool {
    run.status == "ok" && run.pieces >= 6 && run.period < 1.0 / 3.0
}

fn text(t: Target) -> String {
    match t {
        Target::Exactly(n) => n.to_string(),
        Target::Any => "any".into(),
    }
}

fn run_one(
    exemplar: &Exemplar,
    spec: &str,
    curve: &Curve,
    targets: (Target, Target),
    svg_dir: Option<&std::path::Path>,
    base: &Settings,
) -> Run {
    let mut settings = base.clone();
    settings.components = targets.0;
    settings.holes = targets.1;
    settings.closed_pattern = curve.is_closed();
    let mut run = Run {
        region: None,
        ornament: exemplar.name.clone(),
        curve: spec.to_string(),
        target: format!("{}/{}", text(targets.0), text(targets.1)),
        status: "ok",
        reason: String::new(),
        exact: false,
        drift: 0.0,
        period: 1.0,
        repeat: 0.0,
        seam_deg: 0.0,
        stretch: 0.0,
        shear_deg: 0.0,
        gap: 0.0,
        bad: 0.0,
        pieces: 0,
        time_ms: 0.0,
        states: 0,
        bounded: None,
        dominance: false,
        stages: String::new(),
        matching: 0.0,
        auto: 0.0,
        avoidable: false,
    };
    let start = Instant::now();
    let mut mesh_ms = 0.0;
    let result = synthesize(exemplar, curve, &settings, &Control::default()).and_then(|s| {
        let meshing = Instant::now();
        let mesh = extrude(&s.planar.region, settings.thickness_mm);
        mesh_ms = meshing.elapsed().as_secs_f64() * 1e3;
        mesh.map(|m| (s, m)).map_err(Into::into)
    });
    run.time_ms = start.elapsed().as_secs_f64() * 1e3;
    let (synthesis, mesh) = match result {
        Ok(r) => r,
        Err(e) => {
            run.status = match &e {
                SynthesisError::Solve(SolveError::TooManyStates { .. }) => "cap",
                // Refused with a reason, like a proof that there is none.
                SynthesisError::Solve(SolveError::NoSolution(_)) | SynthesisError::LoopTooSmall { .. } => "none",
                SynthesisError::Mesh(_) => "mesh",
                _ => "error",
            };
            run.reason = e.to_string();
            return run;
        }
    };
    if let Err(defect) = mesh.sanity_check() {
        run.status = "mesh";
        run.reason = format!("the mesh is not watertight and manifold: {defect:?}");
        return run;
    }
    let s = &synthesis.solution;
    if let Some(dir) = svg_dir {
        let name = format!("{}_{}_{}.svg", run.ornament, spec.replace(':', ""), run.target.replace('/', "-"));
        let _ = std::fs::write(dir.join(name), region_to_svg(&synthesis.planar.region));
    }
    run.states = s.states;
    run.bounded = s.bounded;
    run.dominance = s.dominance;
    run.matching = s.matching_cost;
    run.auto = s.autocorrelation;
    run.stages = ["analysis", "solve", "geometry"]
        .iter()
        .map(|k| synthesis.timings.stage_ms(k).unwrap_or(0.0))
        .chain([mesh_ms])
        .map(|ms| format!("{ms:.0}"))
        .collect::<Vec<_>>()
        .join("/");
    run.region = Some(synthesis.planar.region.clone());
    run.pieces = s.pieces.len();
    // Counted here again, apart from the pipeline's own count: the polygons
    // merged by a union first. The pipeline's report must agree with it.
    let topology = planar_topology(&synthesis.planar.region, &synthesis.curve);
    let counted = (topology.components as u32, topology.holes as u32);
    let bodies = mesh.shell_count() as u32;
    run.exact = topology == synthesis.topology
        && counted == (s.components, s.holes)
        && targets.0.accepts(counted.0)
        && targets.1.accepts(counted.1)
        && bodies == counted.0;
    if !run.exact {
        run.reason =
            format!("planned {}c {}h, counted {}c {}h, {} bodies", s.components, s.holes, counted.0, counted.1, bodies);
    }
    // Against the curve the pattern follows: the one asked for, sharp corners rounded.
    run.drift = max_distance_from(&synthesis.planar.region, &synthesis.curve) / (0.5 * settings.band_mm);
    // Shape classes along the pattern, from the same cut of the exemplar.
    let classes = &synthesis.shape_classes;
    let n = classes.len().max(1) as f64;
    run.period = near_period(classes) as f64 / n;
    run.repeat = longest_repeat(classes) as f64 / n;
    let band = &synthesis.band;
    let tolerance = 1e-6 * band.length;
    run.seam_deg = seam_kinks_deg(&band.region, &band.seams, tolerance).into_iter().fold(0.0, f64::max);
    run.stretch = band.distortion.stretch_max();
    run.shear_deg = band.distortion.shear_max_deg();
    run.gap = band.seam_gap_max();
    run.bad = band.seam_gaps.iter().filter(|&&g| g > POOR_FIT).count() as f64 / band.seam_gaps.len().max(1) as f64;
    run
}

/// One contact sheet per curve: the answered runs of one target, in a grid,
/// with a list of what each tile is next to it.
fn contact_sheets(runs: &[Run], curves: &[String], target: &str, dir: &std::path::Path) {
    std::fs::create_dir_all(dir).expect("create the sheet folder");
    for curve in curves {
        let shown: Vec<&Run> =
            runs.iter().filter(|r| &r.curve == curve && r.target == target && r.region.is_some()).take(48).collect();
        if shown.is_empty() {
            continue;
        }
        // Tiles shaped like the curve's patterns: a wave in a line's strip
        // came out a fifth of the tile's width.
        let aspect = shown[0].region.as_ref().and_then(|r| r.bounds()).map_or(0.0, |b| b.height() / b.width());
        let (tile_w, tile_h, columns) = if aspect > 0.6 {
            (300, 300, 6)
        } else if aspect > 0.15 {
            (600, (600.0 * aspect) as u32, 3)
        } else {
            (1000, (1000.0 * aspect).max(90.0) as u32, 2)
        };
        let mut index = String::new();
        let mut tiles = Vec::new();
        for (k, run) in shown.iter().enumerate() {
            tiles.push(sheet::render(run.region.as_ref().expect("answered"), tile_w, tile_h, 4.0, (0, 0, 0)));
            index += &format!(
                "row {} col {}: {} ({} pieces, exact {})\n",
                k / columns + 1,
                k % columns + 1,
                run.ornament,
                run.pieces,
                run.exact
            );
        }
        let sheet = sheet::sheet(&tiles, columns, 6);
        let stem = curve.replace(':', "");
        sheet.save_png(dir.join(format!("{stem}.png"))).expect("write the sheet");
        std::fs::write(dir.join(format!("{stem}.txt")), index).expect("write the sheet index");
    }
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

fn summary(runs: &[Run], curves: &[String]) -> String {
    let mut out = String::from(
        "| curve | runs | answered | exact | none | cap | past cap: dominance / bounded | mesh | error | drift max | seam max ° | stretch p95 / max | shear p95 / max ° | seam gap median / poor-fit seams | period < ⅓ | of which avoidable | p50 ms | p95 ms | max ms |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut rows: Vec<(String, Vec<&Run>)> =
        curves.iter().map(|c| (c.clone(), runs.iter().filter(|r| &r.curve == c).collect::<Vec<_>>())).collect();
    rows.push(("all".into(), runs.iter().collect()));
    for (name, rs) in rows {
        let answered: Vec<&&Run> = rs.iter().filter(|r| r.status == "ok").collect();
        let count = |s: &str| rs.iter().filter(|r| r.status == s).count();
        let mut times: Vec<f64> = rs.iter().map(|r| r.time_ms).collect();
        times.sort_by(f64::total_cmp);
        let periodic: Vec<&&&Run> = answered.iter().filter(|r| short_period(r)).collect();
        let sorted = |f: fn(&Run) -> f64| {
            let mut values: Vec<f64> = answered.iter().map(|r| f(r)).collect();
            values.sort_by(f64::total_cmp);
            values
        };
        let (stretches, shears, gaps) = (sorted(|r| r.stretch), sorted(|r| r.shear_deg), sorted(|r| r.gap));
        let poor = answered.iter().map(|r| r.bad).sum::<f64>() / answered.len().max(1) as f64;
        let past_cap = format!(
            "{} / {}",
            answered.iter().filter(|r| r.dominance).count(),
            answered.iter().filter(|r| r.bounded.is_some()).count()
        );
        out += &format!(
            "| {name} | {} | {} | {} | {} | {} | {} | {} | {} | {:.2} | {:.1} | {:.2} / {:.2} | {:.1} / {:.1} | {:.2} / {:.1} % | {} | {} | {:.1} | {:.1} | {:.1} |\n",
            rs.len(),
            answered.len(),
            answered.iter().filter(|r| r.exact).count(),
            count("none"),
            count("cap"),
            past_cap,
            count("mesh"),
            count("error"),
            answered.iter().map(|r| r.drift).fold(0.0, f64::max),
            answered.iter().map(|r| r.seam_deg).fold(0.0, f64::max),
            percentile(&stretches, 0.95),
            stretches.last().copied().unwrap_or(f64::NAN),
            percentile(&shears, 0.95),
            shears.last().copied().unwrap_or(f64::NAN),
            percentile(&gaps, 0.5),
            100.0 * poor,
            periodic.len(),
            periodic.iter().filter(|r| r.avoidable).count(),
            percentile(&times, 0.5),
            percentile(&times, 0.95),
            times.last().copied().unwrap_or(f64::NAN),
        );
    }
    out
}

fn main() {
    let args = parse_args();
    let mut files = corpus::svg_files(&args.corpus);
    files.retain(|f| {
        args.only.as_ref().is_none_or(|o| f.file_stem().is_some_and(|s| s.to_string_lossy().contains(o.as_str())))
    });
    let files: Vec<PathBuf> = files.into_iter().step_by(args.every.max(1)).collect();
    if let Some(dir) = &args.svg_dir {
        std::fs::create_dir_all(dir).expect("create the SVG folder");
    }
    let curves: Vec<(String, Curves)> = args.curves.iter().map(|spec| (spec.clone(), Curves::parse(spec))).collect();
    let mut runs = Vec::new();
    let mut csv = String::from(
        "ornament,curve,target,status,exact,drift,period,repeat,seam_deg,stretch,shear_deg,pieces,time_ms,states,bounded,dominance,stages,matching,auto,avoidable,gap,bad,reason\n",
    );
    let started = Instant::now();
    let mut base = Settings::default();
    base.variety = args.variety.unwrap_or(base.variety);
    base.corner_radius_mm = args.corner_radius_mm.unwrap_or(base.corner_radius_mm);
    let mut probe_base = base.clone();
    probe_base.variety = PROBE_VARIETY;
    for (k, file) in files.iter().enumerate() {
        let exemplar = match Exemplar::from_svg_file(file, &LoadOptions::default()) {
            Ok(e) => e,
            Err(e) => {
                eprintln!("{}: not loaded: {e}", file.display());
                continue;
            }
        };
        for (spec, curves) in &curves {
            let curve = &curves.for_ornament(k);
            for &t in &args.targets {
                let mut r = run_one(&exemplar, spec, curve, t, args.svg_dir.as_deref(), &base);
                if short_period(&r) {
                    let probe = run_one(&exemplar, spec, curve, t, None, &probe_base);
                    r.avoidable = probe.status == "ok" && !short_period(&probe);
                }
                csv += &format!(
                    "{},{},{},{},{},{:.3},{:.3},{:.3},{:.2},{:.3},{:.2},{},{:.2},{},{},{},{},{:.4},{:.2},{},{:.4},{:.4},\"{}\"\n",
                    r.ornament,
                    r.curve,
                    r.target,
                    r.status,
                    r.exact,
                    r.drift,
                    r.period,
                    r.repeat,
                    r.seam_deg,
                    r.stretch,
                    r.shear_deg,
                    r.pieces,
                    r.time_ms,
                    r.states,
                    r.bounded.map_or(String::new(), |w| w.to_string()),
                    r.dominance,
                    r.stages,
                    r.matching,
                    r.auto,
                    r.avoidable,
                    r.gap,
                    r.bad,
                    r.reason.replace('"', "'")
                );
                if r.status != "ok" && r.status != "none" || r.status == "ok" && !r.exact {
                    eprintln!("{} {} {}: {} {}", r.ornament, r.curve, r.target, r.status, r.reason);
                }
                runs.push(r);
            }
        }
    }
    let table = summary(&runs, &args.curves);
    println!("{} ornaments, {} runs in {:.0} s\n", files.len(), runs.len(), started.elapsed().as_secs_f64());
    println!("{table}");
    if let Some(path) = args.csv {
        std::fs::write(&path, csv).expect("write the CSV");
    }
    if let Some(dir) = &args.sheets {
        let first = args.targets.first().map(|&(c, h)| format!("{}/{}", text(c), text(h))).unwrap_or_default();
        contact_sheets(&runs, &args.curves, &first, dir);
    }
    if let Some(path) = args.markdown {
        std::fs::write(&path, table).expect("write the table");
    }
}
