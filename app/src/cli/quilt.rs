//! `tracery quilt`: mesh quilting, 3D texture grown from a mesh swatch.
//! Every flag left out takes its value from [`Settings::default`].

use std::path::Path;

use anyhow::{Context, Result, bail};
use clap::Parser;
use tracery_core::mesh::read_mesh_file;
use tracery_core::mesh_quilt::{
    Direction, GuidanceField, SWATCH_NAMES, Settings, Swatch, builtin_swatch, make_product, make_surface_product,
    parse_base, parse_strokes, unite_with_base,
};
use tracery_core::surface::SurfaceMesh;

use super::output::{OutputArgs, write_outputs};
use super::progress::Progress;

/// `--direction`'s values.
#[derive(clap::ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub enum DirectionArg {
    /// Around the model's z axis, as rings round a vase.
    Around,
    /// Up the model, from its foot towards its top.
    Up,
    /// Along the strokes in --field.
    Curves,
}

/// Flags of `tracery quilt`.
#[derive(Parser, Debug, Clone, PartialEq)]
#[command(allow_negative_numbers = true)]
pub struct QuiltArgs {
    /// An STL or OBJ swatch (mm; each connected part one element), or a built-in's name (see `tracery list --swatches`).
    #[arg(long)]
    pub swatch: String,
    /// What to cover: plane:WIDTHxDEPTH (mm), a built-in base's name (see `tracery list --bases`), or an STL or OBJ model (mm).
    #[arg(long)]
    pub base: String,
    /// The swatch made this many times larger [default: 1].
    #[arg(long)]
    pub scale: Option<f64>,
    /// Grid cells across the swatch's shorter side [default: 12].
    #[arg(long)]
    pub cells_across: Option<usize>,
    /// Which random choices the synthesis makes [default: 1].
    #[arg(long)]
    pub seed: Option<u64>,
    /// How deep the texture sits in a model, mm, so that it unites with it [default: 0.3].
    #[arg(long)]
    pub sink_mm: Option<f64>,
    /// Which way the swatch runs over a model [default: around, or curves when --field is given].
    #[arg(long, value_enum)]
    pub direction: Option<DirectionArg>,
    /// Strokes the swatch's direction follows on a model: a text file, one stroke per line as "x,y,z;x,y,z;..." (mm) [default: around the z axis].
    #[arg(long)]
    pub field: Option<std::path::PathBuf>,
    /// Write the model and the texture united into one solid, not the texture alone.
    #[arg(long)]
    pub with_base: bool,
    #[command(flatten)]
    pub output: OutputArgs,
}

impl QuiltArgs {
    /// The settings these flags ask for: the defaults, with each given flag applied.
    pub fn settings(&self) -> Settings {
        let mut s = Settings::default();
        s.scale = self.scale.unwrap_or(s.scale);
        s.cells_across = self.cells_across.unwrap_or(s.cells_across);
        s.seed = self.seed.unwrap_or(s.seed);
        s.sink_mm = self.sink_mm.unwrap_or(s.sink_mm);
        s.direction = match self.direction {
            Some(DirectionArg::Around) => Direction::AroundAxis,
            Some(DirectionArg::Up) => Direction::AlongAxis,
            Some(DirectionArg::Curves) => Direction::AlongCurves,
            None if self.field.is_some() => Direction::AlongCurves,
            None => s.direction,
        };
        s
    }
}

/// A built-in swatch by name, or a mesh file.
pub fn load_swatch(spec: &str) -> Result<Swatch> {
    if let Some(swatch) = builtin_swatch(spec) {
        return Ok(swatch);
    }
    let path = Path::new(spec);
    if !path.exists() {
        bail!("no mesh file or built-in swatch named '{spec}' (built-ins: {})", SWATCH_NAMES.join(", "));
    }
    let name = path.file_stem().map_or(spec.to_string(), |s| s.to_string_lossy().into_owned());
    Ok(Swatch::from_mesh(&name, &read_mesh_file(path)?)?)
}

/// Runs `tracery quilt`.
pub fn run(args: QuiltArgs, progress: &Progress) -> Result<()> {
    args.output.refuse_planar_only("quilt", "area from --base", "quilts")?;
    if args.output.svg.is_some() || args.output.png.is_some() {
        bail!("tracery quilt makes a 3D solid: write it with --stl or --3mf, not --svg or --png");
    }
    let settings = args.settings();
    super::flags::check("quilt", settings.validate())?;
    let swatch = load_swatch(&args.swatch)?;
    let product = if args.base.starts_with("plane:") {
        if args.with_base {
            bail!("a plane has no model to unite the texture with: leave out --with-base, or quilt a model");
        }
        if args.field.is_some() || args.direction.is_some() {
            bail!("a plane's texture follows the plane's axes: --field and --direction are for models");
        }
        make_product(&swatch, parse_base(&args.base).context("--base")?, &settings, &progress.control())?
    } else {
        let surface = SurfaceMesh::new(super::surface::load_base(&args.base)?)?;
        let strokes = match &args.field {
            Some(path) => {
                if settings.direction != Direction::AlongCurves {
                    bail!(
                        "--field gives strokes for the texture to follow: leave out --direction, or use --direction curves"
                    );
                }
                let text = std::fs::read_to_string(path)
                    .with_context(|| format!("could not read the field file {}", path.display()))?;
                parse_strokes(&text)?
            }
            None if settings.direction == Direction::AlongCurves => {
                bail!("--direction curves follows the strokes of --field: give a field file")
            }
            None => Vec::new(),
        };
        let field = GuidanceField::of(&surface, settings.direction, &strokes)?;
        let texture = make_surface_product(&swatch, &surface, &field, &settings, &progress.control())?;
        if args.with_base { unite_with_base(texture, &surface)? } else { texture }
    };
    write_outputs("quilt", &swatch.name, &args.base, &args.output, &product, progress)
}
