//! The `tracery` command line: one subcommand per mode, sharing `--along`,
//! the outputs and `--report`. An error exits non-zero with one line on
//! stderr and leaves no partial file.

mod fill;
mod flags;
mod output;
pub mod progress;
mod quilt;
mod raster;
mod shade;
mod surface;
mod synth;

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use tracery_core::vector_brush::{BUILTIN_NAMES, PieceSet, SliceOptions, builtin};

pub use fill::FillArgs;
pub use output::{OutputArgs, Report};
pub use quilt::QuiltArgs;
pub use raster::RasterArgs;
pub use shade::ShadeArgs;
pub use surface::SurfaceArgs;
pub use synth::SynthArgs;

/// Tracery: synthesize printable patterns. Without a command, opens the app.
#[derive(Parser, Debug)]
#[command(
    name = "tracery",
    version,
    about,
    allow_negative_numbers = true,
    after_help = "Exit status: 0 done; 1 input refused or no pattern found (one line on stderr, no file written); 2 usage; 130 cancelled by Ctrl+C (no file written)."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Print nothing but errors: no progress bar, no summary.
    #[arg(long, short, global = true)]
    quiet: bool,
}

/// A run stopped by Ctrl+C: nothing was written. `main` exits with 130, as
/// shells do for a command ended by Ctrl+C.
#[derive(Debug, thiserror::Error)]
#[error("cancelled: no file was written")]
pub struct Interrupted;

impl Cli {
    /// Whether the command line asks for the app window rather than a command.
    pub fn wants_app(&self) -> bool {
        self.command.is_none()
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Print the built-in exemplars.
    List {
        /// The raster brush's exemplars instead of the vector brush's.
        #[arg(long)]
        raster: bool,
        /// The built-in base models for `tracery surface` instead.
        #[arg(long, conflicts_with = "raster")]
        bases: bool,
        /// The curve exemplars for `tracery fill` instead.
        #[arg(long, conflicts_with_all = ["raster", "bases"])]
        curves: bool,
        /// The mesh swatches for `tracery quilt` instead.
        #[arg(long, conflicts_with_all = ["raster", "bases", "curves"])]
        swatches: bool,
    },
    /// Vector brush: synthesize a pattern along a curve and write STL, SVG and a report.
    Synth(Box<SynthArgs>),
    /// Raster brush: synthesize a bitmap pattern along a curve and write PNG, STL, SVG and a report.
    Raster(Box<RasterArgs>),
    /// Lamp shade: rows of vector-brush pattern wrapped onto a cylinder or a cone, written as STL, 3MF, SVG (laid flat) and a report.
    Shade(Box<ShadeArgs>),
    /// Pattern on a 3D model: vector-brush pattern along a curve through points picked on a mesh, written as a shell (STL, 3MF), the flat pattern (SVG) and a report.
    Surface(Box<SurfaceArgs>),
    /// Region fill: a region filled with curves like an exemplar's, written as stroked paths (SVG), a printable solid (STL, 3MF) and a report.
    Fill(Box<FillArgs>),
    /// Mesh quilting: 3D texture grown over a plane from a mesh swatch, written as STL or 3MF (one closed body per element) and a report.
    Quilt(Box<QuiltArgs>),
}

/// Writes a line to standard output. A reader that stops reading (`| head`)
/// makes it fail with a broken pipe, which `main` takes as the end of the
/// listing, where `println!` would panic.
pub(crate) fn say(line: std::fmt::Arguments) -> std::io::Result<()> {
    use std::io::Write as _;
    writeln!(std::io::stdout().lock(), "{line}")
}

fn list_swatches() -> Result<()> {
    for name in tracery_core::mesh_quilt::SWATCH_NAMES {
        let swatch = tracery_core::mesh_quilt::builtin_swatch(name)
            .with_context(|| format!("modelling built-in swatch '{name}'"))?;
        let size = swatch.size_mm();
        say(format_args!(
            "{name:10} {:3} element(s) {:6} triangles  {:.0} x {:.0} x {:.1} mm",
            swatch.elements.len(),
            swatch.triangle_count(),
            size.x,
            size.y,
            size.z
        ))?;
    }
    Ok(())
}

fn list_raster() -> Result<()> {
    for name in tracery_core::raster_brush::BUILTIN_NAMES {
        let e = tracery_core::raster_brush::builtin(name).with_context(|| format!("painting built-in '{name}'"))?;
        say(format_args!("{name:10} {:4} x {:3} px {:3.0}% opaque", e.width(), e.height(), 100.0 * e.coverage()))?;
    }
    Ok(())
}

fn list_bases() -> Result<()> {
    for name in tracery_core::surface::BASE_NAMES {
        let mesh = tracery_core::surface::builtin_base(name).with_context(|| format!("building base '{name}'"))?;
        let (low, high) = mesh.vertices.iter().fold(([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]), |(lo, hi), v| {
            (std::array::from_fn(|k| lo[k].min(v[k])), std::array::from_fn(|k| hi[k].max(v[k])))
        });
        say(format_args!(
            "{name:10} {:6} triangles  {:.0} x {:.0} x {:.0} mm",
            mesh.triangles.len(),
            high[0] - low[0],
            high[1] - low[1],
            high[2] - low[2]
        ))?;
    }
    Ok(())
}

fn list_curves() -> Result<()> {
    for name in tracery_core::region_fill::BUILTIN_CURVES {
        let exemplar = tracery_core::region_fill::CurveExemplar::builtin(name)
            .with_context(|| format!("drawing built-in '{name}'"))?;
        // A built-in's filled shapes' outlines follow its strokes among its paths: counted as shapes.
        let strokes = &exemplar.paths[..exemplar.shapes.first().map_or(exemplar.paths.len(), |s| s.first_path)];
        let length: f64 = strokes.iter().map(|p| p.length_mm()).sum();
        let shapes = match exemplar.shapes.len() {
            0 => String::new(),
            n => format!(", {n} filled shape(s)"),
        };
        say(format_args!("{name:10} {:3} path(s) {:6.0} mm of curve{shapes}", strokes.len(), length))?;
    }
    Ok(())
}

fn list() -> Result<()> {
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).with_context(|| format!("loading built-in exemplar '{name}'"))?;
        let pieces = PieceSet::new(&exemplar, &SliceOptions::default())
            .with_context(|| format!("cutting built-in exemplar '{name}'"))?;
        say(format_args!(
            "{name:10} {:3} component(s) {:3} hole(s) {:3} pieces",
            exemplar.region.component_count(),
            exemplar.region.hole_count(),
            pieces.len()
        ))?;
    }
    Ok(())
}

/// Runs the command line.
pub fn run(cli: Cli) -> Result<()> {
    let quiet = cli.quiet;
    let (name, output) = match &cli.command {
        Some(Command::Synth(a)) => ("synth", &a.output),
        Some(Command::Raster(a)) => ("raster", &a.output),
        Some(Command::Shade(a)) => ("shade", &a.output),
        Some(Command::Surface(a)) => ("surface", &a.output),
        Some(Command::Fill(a)) => ("fill", &a.output),
        Some(Command::Quilt(a)) => ("quilt", &a.output),
        Some(Command::List { .. }) | None => return list_or_nothing(cli.command),
    };
    output.preflight()?;
    let progress = progress::Progress::start(name, quiet);
    let result = match cli.command {
        Some(Command::Synth(args)) => synth::run(*args, &progress),
        Some(Command::Raster(args)) => raster::run(*args, &progress),
        Some(Command::Shade(args)) => shade::run(*args, &progress),
        Some(Command::Surface(args)) => surface::run(*args, &progress),
        Some(Command::Fill(args)) => fill::run(*args, &progress),
        Some(Command::Quilt(args)) => quilt::run(*args, &progress),
        Some(Command::List { .. }) | None => Ok(()),
    };
    match result {
        Err(_) if progress.is_cancelled() => Err(Interrupted.into()),
        other => other,
    }
}

fn list_or_nothing(command: Option<Command>) -> Result<()> {
    match command {
        Some(Command::List { bases: true, .. }) => list_bases(),
        Some(Command::List { curves: true, .. }) => list_curves(),
        Some(Command::List { swatches: true, .. }) => list_swatches(),
        Some(Command::List { raster: false, .. }) => list(),
        Some(Command::List { raster: true, .. }) => list_raster(),
        _ => Ok(()),
    }
}
