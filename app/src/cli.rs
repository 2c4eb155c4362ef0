//! The `tracery` command line.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result, anyhow, bail};
use clap::{Parser, Subcommand};
use serde::Serialize;

use crate::files::write_atomically;
use tracery_core::{
    BUILTIN_NAMES, Control, Curve, Exemplar, LoadOptions, PieceSet, SliceOptions, SlicingMode, Synthesis,
    SynthesisRequest, Target, Timings, builtin, extrude, region_to_svg, synthesize, synthesize_rectangle,
};

/// Tracery: synthesize printable patterns along curves. Without a command, opens the app.
#[derive(Parser, Debug)]
#[command(name = "tracery", version, about, allow_negative_numbers = true)]
pub struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

impl Cli {
    /// Whether the command line asks for the app window rather than a command.
    pub fn wants_app(&self) -> bool {
        self.command.is_none()
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Print the built-in exemplars.
    List,
    /// Synthesize a pattern along a curve and write STL, SVG and a report.
    Synth(Box<SynthArgs>),
}

#[derive(Parser, Debug)]
#[command(allow_negative_numbers = true)]
struct SynthArgs {
    /// An SVG file, or the name of a built-in exemplar (see `tracery list`).
    #[arg(long)]
    exemplar: String,
    /// The curve: line:LENGTH_MM, circle:RADIUS_MM, wave:LENGTH_MM, rect:W_MMxH_MM or svg:FILE.svg.
    #[arg(long)]
    along: String,
    /// Binary STL output (millimetres).
    #[arg(long)]
    stl: Option<PathBuf>,
    /// SVG output (millimetres).
    #[arg(long)]
    svg: Option<PathBuf>,
    /// JSON report output.
    #[arg(long)]
    report: Option<PathBuf>,
    /// Band width across the curve, mm.
    #[arg(long, default_value_t = 12.0)]
    band: f64,
    /// Connected components: a number or "any".
    #[arg(long, default_value = "1", value_parser = parse_target)]
    components: Target,
    /// Holes in the lace: a number or "any".
    #[arg(long, default_value = "any", value_parser = parse_target)]
    holes: Target,
    /// On a loop, the pattern must run all around it.
    #[arg(long)]
    closed_pattern: bool,
    /// Variety (autocorrelation penalty weight).
    #[arg(long, default_value_t = 0.0)]
    variety: f64,
    /// Slicing: "topology" or "uniform:T" (T cut lines).
    #[arg(long, default_value = "topology", value_parser = parse_slicing)]
    slicing: SlicingMode,
    /// Drop cuts through features thinner than this, mm.
    #[arg(long, default_value_t = 0.0)]
    min_portal: f64,
    /// Millimetres per exemplar unit (default: fit the exemplar's height to the band).
    #[arg(long)]
    scale: Option<f64>,
    /// Thickness of the printed pattern, mm.
    #[arg(long, default_value_t = 2.0)]
    thickness: f64,
    /// Seed for another pattern (0: the best one).
    #[arg(long, default_value_t = 0)]
    seed: u64,
}

fn parse_target(s: &str) -> Result<Target, String> {
    if s.eq_ignore_ascii_case("any") {
        return Ok(Target::Any);
    }
    s.parse::<u32>().map(Target::Exactly).map_err(|_| format!("'{s}' is neither a number nor 'any'"))
}

fn parse_slicing(s: &str) -> Result<SlicingMode, String> {
    if s == "topology" {
        return Ok(SlicingMode::Topology);
    }
    let cuts = s
        .strip_prefix("uniform:")
        .and_then(|t| t.parse::<usize>().ok())
        .ok_or_else(|| format!("'{s}' is not 'topology' or 'uniform:T'"))?;
    Ok(SlicingMode::Uniform { cuts })
}

fn positive(what: &str, text: &str) -> Result<f64> {
    let value: f64 = text.trim().parse().map_err(|_| anyhow!("{what} '{text}' is not a number"))?;
    if !(value.is_finite() && value > 0.0) {
        bail!("{what} must be a positive number of millimetres, not {text}");
    }
    Ok(value)
}

/// Where the pattern goes.
enum Along {
    Curve(Curve),
    Rectangle { width_mm: f64, height_mm: f64 },
}

fn parse_along(spec: &str) -> Result<Along> {
    let (kind, value) = spec.split_once(':').ok_or_else(|| anyhow!("curve '{spec}' must look like KIND:VALUE"))?;
    let curve = match kind {
        "line" => Curve::line(positive("the line length", value)?),
        "circle" => Curve::circle(positive("the circle radius", value)?),
        "wave" => Curve::wave(positive("the wave length", value)?),
        "rect" => {
            let (w, h) = value.split_once(['x', 'X']).ok_or_else(|| anyhow!("rectangle '{value}' must be WxH"))?;
            return Ok(Along::Rectangle {
                width_mm: positive("the rectangle width", w)?,
                height_mm: positive("the rectangle height", h)?,
            });
        }
        "svg" => return Ok(Along::Curve(curve_from_svg(Path::new(value))?)),
        _ => bail!("unknown curve kind '{kind}': use line, circle, wave, rect or svg"),
    };
    Ok(Along::Curve(curve?))
}

/// The first path of an SVG file, flattened, as a curve in millimetres.
fn curve_from_svg(path: &Path) -> Result<Curve> {
    let data = std::fs::read(path).with_context(|| format!("could not read {}", path.display()))?;
    let points = tracery_core::first_path_points(&data).with_context(|| format!("in {}", path.display()))?;
    let closed = points.len() > 2 && points[0].distance(*points.last().unwrap()) < 1e-6;
    Ok(Curve::from_polyline(&points, closed)?)
}

fn load_exemplar(spec: &str) -> Result<Exemplar> {
    if BUILTIN_NAMES.contains(&spec) {
        return Ok(builtin(spec)?);
    }
    let path = Path::new(spec);
    if !path.exists() {
        bail!("no exemplar file '{spec}', and no built-in exemplar of that name (see `tracery list`)");
    }
    Exemplar::from_svg_file(path, &LoadOptions::default()).with_context(|| format!("in {spec}"))
}

/// What `--report` writes.
#[derive(Serialize)]
struct Report {
    exemplar: String,
    curve: String,
    components: usize,
    holes: usize,
    loop_openings: usize,
    target_components: String,
    target_holes: String,
    target_length_mm: f64,
    length_mm: f64,
    synthesized_length_mm: f64,
    scale_mm_per_unit: f64,
    cost: f64,
    piece_sequence: Vec<usize>,
    pieces_in_exemplar: usize,
    dp_states: usize,
    stl_triangles: usize,
    stl_shells: usize,
    timings_ms: Timings,
    warnings: Vec<String>,
}

fn target_text(t: Target) -> String {
    match t {
        Target::Exactly(n) => n.to_string(),
        Target::Any => "any".into(),
    }
}

fn synth(args: SynthArgs) -> Result<()> {
    let exemplar = load_exemplar(&args.exemplar)?;
    let along = parse_along(&args.along)?;
    if !(args.thickness.is_finite() && args.thickness > 0.0) {
        bail!("the thickness must be a positive number of millimetres, not {}", args.thickness);
    }
    let mut request = SynthesisRequest::default();
    request.band_mm = args.band;
    request.components = args.components;
    request.holes = args.holes;
    request.closed_pattern = args.closed_pattern;
    request.variety = args.variety;
    request.slicing = args.slicing;
    request.min_portal_mm = args.min_portal;
    request.scale_mm_per_unit = args.scale;
    request.seed = args.seed;
    let control = Control::default();
    let (mut synthesis, target_length): (Synthesis, f64) = match &along {
        Along::Curve(curve) => (synthesize(&exemplar, curve, &request, &control)?, curve.length()),
        Along::Rectangle { width_mm, height_mm } => {
            (synthesize_rectangle(&exemplar, *width_mm, *height_mm, &request, &control)?, *width_mm)
        }
    };
    let start = Instant::now();
    let mesh = extrude(&synthesis.planar.region, args.thickness)?;
    let mut stl = Vec::new();
    mesh.write_stl(&mut stl)?;
    synthesis.timings.mesh = start.elapsed().as_secs_f64() * 1e3;
    let svg = region_to_svg(&synthesis.planar.region);
    let report = Report {
        exemplar: exemplar.name.clone(),
        curve: args.along.clone(),
        components: synthesis.topology.components,
        holes: synthesis.topology.holes,
        loop_openings: synthesis.topology.loop_openings,
        target_components: target_text(args.components),
        target_holes: target_text(args.holes),
        target_length_mm: target_length,
        length_mm: match along {
            Along::Curve(_) => synthesis.band.length * synthesis.scale_mm_per_unit,
            Along::Rectangle { .. } => synthesis.planar.region.bounds().map_or(0.0, |b| b.width()),
        },
        synthesized_length_mm: synthesis.solution.length * synthesis.scale_mm_per_unit,
        scale_mm_per_unit: synthesis.scale_mm_per_unit,
        cost: synthesis.solution.cost,
        piece_sequence: synthesis.solution.pieces.clone(),
        pieces_in_exemplar: synthesis.piece_count,
        dp_states: synthesis.solution.states,
        stl_triangles: mesh.triangles.len(),
        stl_shells: mesh.shell_count(),
        timings_ms: synthesis.timings,
        warnings: synthesis.warnings.clone(),
    };
    let json = serde_json::to_string_pretty(&report)?;
    if let Some(path) = &args.stl {
        write_atomically(path, &stl)?;
    }
    if let Some(path) = &args.svg {
        write_atomically(path, svg.as_bytes())?;
    }
    if let Some(path) = &args.report {
        write_atomically(path, json.as_bytes())?;
    }
    println!(
        "{}: {} component(s), {} hole(s){}, {:.1} mm, {} pieces; {:.0} ms",
        exemplar.name,
        report.components,
        report.holes,
        if report.loop_openings > 0 { format!(" (+{} loop opening)", report.loop_openings) } else { String::new() },
        report.length_mm,
        report.piece_sequence.len(),
        synthesis.timings.analysis + synthesis.timings.dp + synthesis.timings.geometry + synthesis.timings.mesh
    );
    for w in &report.warnings {
        println!("warning: {w}");
    }
    Ok(())
}

fn list() -> Result<()> {
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).with_context(|| format!("loading built-in exemplar '{name}'"))?;
        let pieces = PieceSet::new(&exemplar, &SliceOptions::default())
            .with_context(|| format!("cutting built-in exemplar '{name}'"))?;
        println!(
            "{name:10} {:3} component(s) {:3} hole(s) {:3} pieces",
            exemplar.region.component_count(),
            exemplar.region.hole_count(),
            pieces.len()
        );
    }
    Ok(())
}

/// Runs the command line.
pub fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Some(Command::List) => list(),
        Some(Command::Synth(args)) => synth(*args),
        None => Ok(()),
    }
}
