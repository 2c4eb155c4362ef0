//! `tracery synth`: the vector brush. Every flag left out takes its value
//! from [`Settings::default`], the same defaults the app uses.

use std::path::Path;

use anyhow::{Context, Result, bail};
use clap::Parser;
use tracery_core::curve::Along;
use tracery_core::print::{add_jump_rings, finish};
use tracery_core::vector_brush::{
    BUILTIN_NAMES, Exemplar, LoadOptions, Settings, SlicingMode, Target, builtin, make_product,
};

use super::output::{OutputArgs, write_outputs};
use super::progress::Progress;

/// Flags of `tracery synth`.
#[derive(Parser, Debug, Clone, PartialEq)]
#[command(allow_negative_numbers = true)]
pub struct SynthArgs {
    /// An SVG file, or the name of a built-in exemplar (see `tracery list`).
    #[arg(long)]
    pub exemplar: String,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub brush: BrushArgs,
}

/// The vector brush's settings as flags, shared by `tracery synth` and
/// `tracery shade`.
#[derive(clap::Args, Debug, Clone, PartialEq)]
pub struct BrushArgs {
    /// Band width across the curve, mm [default: 10].
    #[arg(long)]
    pub band: Option<f64>,
    /// Connected components: a number or "any" [default: 1].
    #[arg(long, value_parser = parse_target)]
    pub components: Option<Target>,
    /// Holes in the lace: a number or "any" [default: any].
    #[arg(long, value_parser = parse_target)]
    pub holes: Option<Target>,
    /// On a loop, the pattern runs all around it: true or false; the flag alone means true [default: true].
    #[arg(long, num_args = 0..=1, default_missing_value = "true")]
    pub closed_pattern: Option<bool>,
    /// Variety (autocorrelation penalty weight) [default: 0.8].
    #[arg(long)]
    pub variety: Option<f64>,
    /// Slicing: "topology" or "uniform:T" (T cut lines) [default: topology].
    #[arg(long, value_parser = parse_slicing)]
    pub slicing: Option<SlicingMode>,
    /// Drop cuts through features thinner than this, mm [default: 0].
    #[arg(long)]
    pub min_portal: Option<f64>,
    /// Exemplar scale relative to fitting its height to the band [default: 1].
    #[arg(long)]
    pub scale: Option<f64>,
    /// Thickness of the printed pattern, mm [default: 2].
    #[arg(long)]
    pub thickness: Option<f64>,
    /// Radius of the arcs that round the curve's sharp corners, mm; never less than 1.25 half bands, which the band needs to turn without folding (0: that) [default: 0].
    #[arg(long)]
    pub corner_radius: Option<f64>,
    /// Turn the pattern over to the other side of the curve (a loop's pattern otherwise faces the same way whichever way it was drawn).
    #[arg(long)]
    pub flip: bool,
    /// Seed that perturbs the pattern at random (0: none) [default: 0].
    #[arg(long)]
    pub seed: Option<u64>,
    /// Which solution: 0 is the best, 1 to 5 each differ from all before them (the app's gallery) [default: 0].
    #[arg(long)]
    pub alternative: Option<u32>,
}

impl SynthArgs {
    /// The settings these flags ask for (see [`BrushArgs::settings`]).
    pub fn settings(&self) -> Settings {
        self.brush.settings()
    }
}

impl BrushArgs {
    /// The settings these flags ask for: the defaults, with each given flag applied.
    pub fn settings(&self) -> Settings {
        let mut s = Settings::default();
        s.band_mm = self.band.unwrap_or(s.band_mm);
        s.components = self.components.unwrap_or(s.components);
        s.holes = self.holes.unwrap_or(s.holes);
        s.closed_pattern = self.closed_pattern.unwrap_or(s.closed_pattern);
        s.variety = self.variety.unwrap_or(s.variety);
        s.slicing = self.slicing.unwrap_or(s.slicing);
        s.min_portal_mm = self.min_portal.unwrap_or(s.min_portal_mm);
        s.scale = self.scale.unwrap_or(s.scale);
        s.thickness_mm = self.thickness.unwrap_or(s.thickness_mm);
        s.corner_radius_mm = self.corner_radius.unwrap_or(s.corner_radius_mm);
        s.flip = self.flip || s.flip;
        s.seed = self.seed.unwrap_or(s.seed);
        s.alternative = self.alternative.unwrap_or(s.alternative);
        s
    }
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

/// Loads a built-in exemplar by name, or an SVG file.
pub fn load_exemplar(spec: &str) -> Result<Exemplar> {
    if BUILTIN_NAMES.contains(&spec) {
        return Ok(builtin(spec)?);
    }
    let path = Path::new(spec);
    if !path.exists() {
        bail!("no exemplar file '{spec}', and no built-in exemplar of that name (see `tracery list`)");
    }
    Exemplar::from_svg_file(path, &LoadOptions::default()).with_context(|| format!("in {spec}"))
}

/// Runs `tracery synth`.
pub fn run(args: SynthArgs, progress: &Progress) -> Result<()> {
    let settings = args.settings();
    super::flags::check("synth", settings.validate())?;
    args.output.svg_options()?;
    let print = args.output.print.settings()?;
    let rings = args.output.print.jump_rings()?;
    let exemplar = load_exemplar(&args.exemplar)?;
    let spec = args.output.along()?;
    let along = Along::parse(spec).context("--along")?;
    let product = make_product(&exemplar, &along, &settings, &progress.control())?;
    let product = finish(add_jump_rings(product, &rings)?, &print);
    write_outputs("synth", &exemplar.name, spec, &args.output, &product, progress)
}
