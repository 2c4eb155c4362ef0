//! `tracery shade`: a lamp shade, rows of vector-brush pattern wrapped onto a
//! cylinder or a cone. Every flag left out takes its value from
//! [`ShadeSettings::default`] and the vector brush's `Settings::default`.

use anyhow::{Result, bail};
use clap::Parser;
use tracery_core::print::check_solid;
use tracery_core::surface::{Shade, ShadeSettings};
use tracery_core::vector_brush::make_shade;

use super::output::{OutputArgs, write_outputs};
use super::progress::Progress;
use super::synth::{BrushArgs, load_exemplar};

/// Flags of `tracery shade`.
#[derive(Parser, Debug, Clone, PartialEq)]
#[command(allow_negative_numbers = true)]
pub struct ShadeArgs {
    /// An SVG file, or the name of a built-in exemplar (see `tracery list`).
    #[arg(long)]
    pub exemplar: String,
    /// A cylinder: radius and height, mm, as R,H.
    #[arg(long, conflicts_with = "cone", allow_hyphen_values = true)]
    pub cylinder: Option<String>,
    /// A cone: bottom radius, top radius and height, mm, as R1,R2,H.
    #[arg(long, allow_hyphen_values = true)]
    pub cone: Option<String>,
    /// Height of the solid rims at the top and the bottom, mm; 0 for none [default: 3].
    #[arg(long)]
    pub rim: Option<f64>,
    /// How far rows overlap each other and the rims, mm [default: 1].
    #[arg(long)]
    pub row_overlap: Option<f64>,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub brush: BrushArgs,
}

impl ShadeArgs {
    /// The shade these flags ask for, and how the spec reads in the report.
    pub fn shade_settings(&self) -> Result<(ShadeSettings, String)> {
        let mut s = ShadeSettings::default();
        let spec = match (&self.cylinder, &self.cone) {
            (Some(text), None) => {
                s.shade = Shade::parse_cylinder(text)?;
                format!("cylinder:{text}")
            }
            (None, Some(text)) => {
                s.shade = Shade::parse_cone(text)?;
                format!("cone:{text}")
            }
            _ => bail!("give the shade's shape: --cylinder R,H or --cone R1,R2,H (mm)"),
        };
        s.rim_mm = self.rim.unwrap_or(s.rim_mm);
        s.row_overlap_mm = self.row_overlap.unwrap_or(s.row_overlap_mm);
        Ok((s, spec))
    }
}

/// Runs `tracery shade`.
pub fn run(args: ShadeArgs, progress: &Progress) -> Result<()> {
    args.output.refuse_planar_only("shade", "shape from --cylinder or --cone", "shades")?;
    let settings = args.brush.settings();
    super::flags::check("shade", settings.validate())?;
    let (shade, spec) = args.shade_settings()?;
    shade.validate(settings.band_mm)?;
    args.output.svg_options()?;
    let print = args.output.print.settings()?;
    let exemplar = load_exemplar(&args.exemplar)?;
    let product = make_shade(&exemplar, &shade, &settings, &progress.control())?;
    let product = check_solid(product, &print, settings.thickness_mm);
    write_outputs("shade", &exemplar.name, &spec, &args.output, &product, progress)
}
