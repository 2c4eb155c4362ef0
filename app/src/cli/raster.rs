//! `tracery raster`: the raster brush. Every flag left out takes its value
//! from [`Settings::default`], the same defaults the app uses.

use std::path::Path;

use anyhow::{Context, Result, bail};
use clap::Parser;
use tracery_core::curve::{Along, Curve};
use tracery_core::geom::Region;
use tracery_core::print::{add_jump_rings, finish};
use tracery_core::raster_brush::{BUILTIN_NAMES, RasterExemplar, Settings, builtin, make_product};

use super::output::{OutputArgs, write_outputs};
use super::progress::Progress;

/// Flags of `tracery raster`.
#[derive(Parser, Debug, Clone, PartialEq)]
#[command(allow_negative_numbers = true)]
pub struct RasterArgs {
    /// A PNG file with a transparent background, or the name of a built-in raster exemplar (see `tracery list --raster`).
    #[arg(long)]
    pub exemplar: String,
    #[command(flatten)]
    pub output: OutputArgs,
    /// Close the curve into a loop.
    #[arg(long)]
    pub closed: bool,
    /// Ribbon width across the curve, mm [default: 10].
    #[arg(long)]
    pub band: Option<f64>,
    /// Piece length along the curve, mm [default: 2].
    #[arg(long)]
    pub step: Option<f64>,
    /// The pattern's height as a fraction of the band, up to 1 [default: 0.75].
    #[arg(long)]
    pub scale: Option<f64>,
    /// Leave the seams as they are (no stitching).
    #[arg(long)]
    pub no_stitching: bool,
    /// Thickness of the printed outline, mm [default: 2].
    #[arg(long)]
    pub thickness: Option<f64>,
    /// How much where the pattern jumps in the exemplar changes along the curve; 0 turns it off [default: 0.5].
    #[arg(long)]
    pub variety: Option<f64>,
    /// Which random choices variety makes [default: 0].
    #[arg(long)]
    pub seed: Option<u64>,
}

impl RasterArgs {
    /// The settings these flags ask for: the defaults, with each given flag applied.
    pub fn settings(&self) -> Settings {
        let mut s = Settings::default();
        s.band_mm = self.band.unwrap_or(s.band_mm);
        s.step_mm = self.step.unwrap_or(s.step_mm);
        s.scale = self.scale.unwrap_or(s.scale);
        s.stitching = !self.no_stitching;
        s.thickness_mm = self.thickness.unwrap_or(s.thickness_mm);
        s.variety = self.variety.unwrap_or(s.variety);
        s.seed = self.seed.unwrap_or(s.seed);
        s
    }
}

/// Loads a built-in raster exemplar by name, or a PNG file.
pub fn load_raster_exemplar(spec: &str) -> Result<RasterExemplar> {
    if let Some(exemplar) = BUILTIN_NAMES.contains(&spec).then(|| builtin(spec)).flatten() {
        return Ok(exemplar);
    }
    let path = Path::new(spec);
    if !path.exists() {
        bail!("no exemplar file '{spec}', and no built-in raster exemplar of that name (see `tracery list --raster`)");
    }
    RasterExemplar::from_png_file(path).with_context(|| format!("in {spec}"))
}

/// Runs `tracery raster`.
pub fn run(args: RasterArgs, progress: &Progress) -> Result<()> {
    let settings = args.settings();
    super::flags::check("raster", settings.validate())?;
    args.output.svg_options()?;
    let print = args.output.print.settings()?;
    let rings = args.output.print.jump_rings()?;
    let exemplar = load_raster_exemplar(&args.exemplar)?;
    let spec = args.output.along()?;
    let mut along = Along::parse(spec).context("--along")?;
    if let Along::Curve(curve) = &along
        && args.closed
        && !curve.is_closed()
    {
        along = Along::Curve(Curve::from_polyline(curve.points(), true)?);
    }
    let product = make_product(&exemplar, &along, &settings, &Region::default(), &progress.control())?;
    let product = finish(add_jump_rings(product, &rings)?, &print);
    write_outputs("raster", &exemplar.name, spec, &args.output, &product, progress)
}
