//! `tracery surface`: a vector-brush pattern along a curve drawn on a 3D
//! model, through picked points, as a printable shell on its surface.
//! Every flag left out takes its value from [`SurfaceSettings::default`]
//! and the vector brush's `Settings::default`.

use std::path::Path;

use anyhow::{Result, bail};
use clap::{Parser, ValueEnum};
use tracery_core::mesh::{Mesh, read_mesh_file};
use tracery_core::print::check_solid;
use tracery_core::surface::{BASE_NAMES, DrawnError, SurfaceMesh, SurfaceOutput, SurfaceSettings, builtin_base};
use tracery_core::vector_brush::make_object_on_surface;

use super::output::{OutputArgs, write_outputs};
use super::progress::Progress;
use super::synth::{BrushArgs, load_exemplar};

/// What `tracery surface` writes.
#[derive(ValueEnum, Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SurfaceMode {
    /// The pattern alone, a shell conforming to the surface.
    #[default]
    Pattern,
    /// The pattern united with the model into one solid.
    Emboss,
    /// The pattern cut out of the model hollowed to a shell (see --wall).
    Carve,
}

/// Flags of `tracery surface`.
#[derive(Parser, Debug, Clone, PartialEq)]
#[command(allow_negative_numbers = true)]
pub struct SurfaceArgs {
    /// An SVG file, or the name of a built-in exemplar (see `tracery list`).
    #[arg(long)]
    pub exemplar: String,
    /// The model: an STL or OBJ file (mm), or a built-in base (see `tracery list --bases`).
    #[arg(long)]
    pub mesh: String,
    /// Points of the curve, mm, as "x,y,z;x,y,z;..."; points off the surface snap onto it.
    /// Give it again for each further curve: all are made with the same
    /// flags and combined with the model once, into one object.
    #[arg(long, required = true, allow_hyphen_values = true)]
    pub points: Vec<String>,
    /// Close each curve back to its first point (a ring around a vase).
    #[arg(long)]
    pub closed: bool,
    /// Turn the band about the curve, degrees [default: 0, lying on the surface].
    #[arg(long)]
    pub twist: Option<f64>,
    /// What to make.
    #[arg(long, value_enum, default_value_t)]
    pub mode: SurfaceMode,
    /// Wall of the shell the pattern is carved out of, mm [default: 2].
    #[arg(long)]
    pub wall: Option<f64>,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub brush: BrushArgs,
}

impl SurfaceArgs {
    /// The curves these flags ask for, one for each `--points`.
    pub fn surface_settings(&self) -> Result<Vec<SurfaceSettings>> {
        self.points.iter().map(|points| self.curve(points)).collect()
    }

    fn curve(&self, points: &str) -> Result<SurfaceSettings> {
        let mut s = SurfaceSettings::default();
        s.points_mm = SurfaceSettings::parse_points(points).map_err(drawn_error)?;
        s.closed = self.closed;
        s.twist_deg = self.twist.unwrap_or(s.twist_deg);
        s.output = match self.mode {
            SurfaceMode::Pattern => SurfaceOutput::Pattern,
            SurfaceMode::Emboss => SurfaceOutput::Emboss,
            SurfaceMode::Carve => SurfaceOutput::Carve,
        };
        s.wall_mm = self.wall.unwrap_or(s.wall_mm);
        s.validate().map_err(drawn_error)?;
        Ok(s)
    }
}

/// A refused point or setting named by its flag.
fn drawn_error(e: DrawnError) -> anyhow::Error {
    match e {
        DrawnError::Setting(e) => super::flags::flagged("surface", e),
        other => other.into(),
    }
}

/// A built-in base by name, or a mesh file.
pub fn load_base(spec: &str) -> Result<Mesh> {
    if let Some(mesh) = builtin_base(spec) {
        return Ok(mesh);
    }
    if !Path::new(spec).exists() {
        bail!("no mesh file or built-in base named '{spec}' (built-ins: {})", BASE_NAMES.join(", "));
    }
    Ok(read_mesh_file(Path::new(spec))?)
}

/// Runs `tracery surface`.
pub fn run(args: SurfaceArgs, progress: &Progress) -> Result<()> {
    args.output.refuse_planar_only("surface", "curve from --points on --mesh", "surfaces")?;
    let settings = args.brush.settings();
    super::flags::check("surface", settings.validate())?;
    let curves = args.surface_settings()?;
    args.output.svg_options()?;
    let print = args.output.print.settings()?;
    let surface = SurfaceMesh::new(load_base(&args.mesh)?)?;
    let exemplar = load_exemplar(&args.exemplar)?;
    let product = make_object_on_surface(&exemplar, &surface, &curves, &settings, &progress.control())?;
    let product = check_solid(product, &print, settings.thickness_mm);
    let spec = format!("{}:{}{}", args.mesh, args.points.join(" | "), if args.closed { " closed" } else { "" });
    write_outputs("surface", &exemplar.name, &spec, &args.output, &product, progress)
}
