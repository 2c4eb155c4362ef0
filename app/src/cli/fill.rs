//! `tracery fill`: region fill with a curve texture. Every flag left out
//! takes its value from [`Settings::default`], the same defaults the app uses.

use anyhow::{Context, Result, bail};
use clap::Parser;
use tracery_core::print::finish;
use tracery_core::region_fill::{CurveExemplar, Settings, make_product, parse_region};

use super::output::{OutputArgs, write_outputs};
use super::progress::Progress;

/// Flags of `tracery fill`.
#[derive(Parser, Debug, Clone, PartialEq)]
#[command(allow_negative_numbers = true)]
pub struct FillArgs {
    /// An SVG of stroked paths, or the name of a built-in curve exemplar (see `tracery list --curves`).
    #[arg(long)]
    pub exemplar: String,
    /// The region to fill: rect:WIDTHxHEIGHT, circle:RADIUS (mm) or svg:FILE.svg (its closed shapes, even-odd).
    #[arg(long)]
    pub region: String,
    #[command(flatten)]
    pub output: OutputArgs,
    /// Width of the pen the curves are drawn with, mm [default: 0.8].
    #[arg(long)]
    pub stroke_width: Option<f64>,
    /// Width of a frame along the region's edge, mm; 0 for none [default: 0].
    #[arg(long)]
    pub frame: Option<f64>,
    /// Thickness of the printed solid, mm [default: 1.5].
    #[arg(long)]
    pub thickness: Option<f64>,
    /// Join every piece to the rest with short bridges, so the print is one object.
    #[arg(long)]
    pub one_piece: bool,
    /// Sample spacing at the finest level, mm: the scale of the detail the fill copies [default: 1.5].
    #[arg(long)]
    pub spacing: Option<f64>,
    /// The exemplar drawn this many times larger (below 1, smaller) before the fill learns from it [default: 1].
    #[arg(long)]
    pub exemplar_scale: Option<f64>,
    /// Which random choices the synthesis makes [default: 1].
    #[arg(long)]
    pub seed: Option<u64>,
}

impl FillArgs {
    /// The settings these flags ask for: the defaults, with each given flag applied.
    pub fn settings(&self) -> Settings {
        let mut s = Settings::default();
        s.stroke_width_mm = self.stroke_width.unwrap_or(s.stroke_width_mm);
        s.frame_mm = self.frame.unwrap_or(s.frame_mm);
        s.thickness_mm = self.thickness.unwrap_or(s.thickness_mm);
        s.one_piece = self.one_piece;
        s.delta_mm = self.spacing.unwrap_or(s.delta_mm);
        s.exemplar_scale = self.exemplar_scale.unwrap_or(s.exemplar_scale);
        s.seed = self.seed.unwrap_or(s.seed);
        s
    }
}

/// Runs `tracery fill`.
pub fn run(args: FillArgs, progress: &Progress) -> Result<()> {
    if args.output.along.is_some() {
        bail!("tracery fill takes its place from --region, not --along");
    }
    if args.output.print.thicken || !args.output.print.jump_ring.is_empty() {
        bail!("--thicken and --jump-ring are not available on fills yet");
    }
    let settings = args.settings();
    super::flags::check("fill", settings.validate())?;
    args.output.svg_options()?;
    let print = args.output.print.settings()?;
    let exemplar = CurveExemplar::load(&args.exemplar)?;
    let region = parse_region(&args.region).context("--region")?;
    let product = make_product(&exemplar, &region, &settings, &progress.control())?;
    let product = finish(product, &print);
    write_outputs("fill", &exemplar.name, &args.region, &args.output, &product, progress)
}
