//! What every subcommand shares: where the pattern goes, the output files,
//! and the JSON report, all made from the mode's [`Product`].

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use serde::Serialize;

use super::say;
use tracery_core::Product;
use tracery_core::export::{
    SvgFlavour, SvgOptions, ThreeMfObject, encode_png, object_colour, render_product, write_3mf, write_paths_svg,
    write_stl, write_svg,
};
use tracery_core::print::{JumpRings, PrintSettings, Printability, RingAt};
use tracery_core::product::Facts;
use tracery_core::report::{Timings, Warning};

use super::progress::Progress;
use crate::files::{check_writable, refuse_same_path, write_all_or_none};

/// PNG resolution when `--dpi` is left out.
const DEFAULT_DPI: f64 = 300.0;

/// Millimetres in an inch.
const MM_PER_INCH: f64 = 25.4;

/// The flags every subcommand takes.
#[derive(clap::Args, Debug, Clone, PartialEq)]
pub struct OutputArgs {
    /// Where the pattern goes: line:LENGTH_MM, circle:RADIUS_MM, wave:LENGTH_MM, rect:W_MMxH_MM or svg:FILE.svg (not for `shade`, whose shape says where).
    #[arg(long)]
    pub along: Option<String>,
    /// Binary STL output (millimetres).
    #[arg(long)]
    pub stl: Option<PathBuf>,
    /// 3MF output (millimetres): the pattern as one named, coloured object.
    #[arg(long = "3mf", value_name = "3MF")]
    pub three_mf: Option<PathBuf>,
    /// SVG output (millimetres).
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// PNG picture of the result (transparent background).
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Resolution of the PNG, dots per inch [default: 300].
    #[arg(long)]
    pub dpi: Option<f64>,
    /// What the SVG is for: "engrave" (filled shapes) or "cut" (hairline outlines for a laser, holes first) [default: engrave].
    #[arg(long, value_parser = parse_flavour)]
    pub svg_flavour: Option<SvgFlavour>,
    /// Laser kerf, mm: cut outlines move out and holes move in by half of it [default: 0].
    #[arg(long)]
    pub kerf: Option<f64>,
    /// JSON report output: topology, printability, `timings_ms`, `warnings` and the mode's figures.
    #[arg(long)]
    pub report: Option<PathBuf>,
    #[command(flatten)]
    pub print: PrintArgs,
}

/// The printer the pattern is checked against.
#[derive(clap::Args, Debug, Clone, PartialEq)]
pub struct PrintArgs {
    /// Nozzle diameter, mm: thinner features and narrower gaps are reported [default: 0.4].
    #[arg(long)]
    pub nozzle: Option<f64>,
    /// Layer height, mm [default: 0.2].
    #[arg(long)]
    pub layer_height: Option<f64>,
    /// Thicken features thinner than the nozzle to its width (the topology is counted again).
    #[arg(long)]
    pub thicken: bool,
    /// Flag bridges between pieces narrower than this many nozzle widths [default: 1.5].
    #[arg(long)]
    pub weak_bridge: Option<f64>,
    /// A jump ring for hanging the piece: start, end, top or X,Y (mm); repeat for more.
    #[arg(long = "jump-ring", value_parser = parse_ring_at, allow_hyphen_values = true)]
    pub jump_ring: Vec<RingAt>,
    /// The jump rings' hole diameter, mm [default: 2.5].
    #[arg(long)]
    pub jump_ring_hole: Option<f64>,
    /// The jump rings' wall, mm [default: 1.2].
    #[arg(long)]
    pub jump_ring_wall: Option<f64>,
}

fn parse_ring_at(s: &str) -> Result<RingAt, String> {
    match s {
        "start" => Ok(RingAt::Start),
        "end" => Ok(RingAt::End),
        "top" => Ok(RingAt::Top),
        _ => {
            let bad = || format!("'{s}' is not start, end, top or X,Y in mm");
            let (x, y) = s.split_once(',').ok_or_else(bad)?;
            let (x_mm, y_mm) =
                (x.trim().parse::<f64>().map_err(|_| bad())?, y.trim().parse::<f64>().map_err(|_| bad())?);
            if !(x_mm.is_finite() && y_mm.is_finite()) {
                return Err(bad());
            }
            Ok(RingAt::Point { x_mm, y_mm })
        }
    }
}

impl PrintArgs {
    /// The print settings these flags ask for: the defaults, with each given flag applied.
    pub fn settings(&self) -> Result<PrintSettings> {
        let mut s = PrintSettings::default();
        s.nozzle_mm = self.nozzle.unwrap_or(s.nozzle_mm);
        s.layer_height_mm = self.layer_height.unwrap_or(s.layer_height_mm);
        s.thicken = self.thicken;
        s.bridge_nozzles = self.weak_bridge.unwrap_or(s.bridge_nozzles);
        s.validate()?;
        Ok(s)
    }

    /// The jump rings these flags ask for, checked against the printer.
    pub fn jump_rings(&self) -> Result<JumpRings> {
        let mut rings = JumpRings::at(self.jump_ring.clone());
        rings.hole_mm = self.jump_ring_hole.unwrap_or(rings.hole_mm);
        rings.wall_mm = self.jump_ring_wall.unwrap_or(rings.wall_mm);
        rings.validate(&self.settings()?)?;
        Ok(rings)
    }
}

fn parse_flavour(s: &str) -> Result<SvgFlavour, String> {
    match s {
        "engrave" => Ok(SvgFlavour::Engrave),
        "cut" => Ok(SvgFlavour::Cut),
        _ => Err(format!("'{s}' is not 'engrave' or 'cut'")),
    }
}

impl OutputArgs {
    /// The `--along` curve, which synth and raster need.
    pub fn along(&self) -> Result<&str> {
        match &self.along {
            Some(spec) => Ok(spec),
            None => {
                bail!("--along is required: where the pattern goes (line:120, circle:25, rect:80x50, svg:FILE.svg, …)")
            }
        }
    }

    /// Refuses the flags a pattern laid on a surface cannot use: `--along`
    /// (`command` takes its shape from `shape_from`), and the print edits
    /// made on a flat region (`--thicken`, `--jump-ring`) not yet made on `what`.
    pub fn refuse_planar_only(&self, command: &str, shape_from: &str, what: &str) -> Result<()> {
        if self.along.is_some() {
            bail!("tracery {command} takes its {shape_from}, not --along");
        }
        if self.print.thicken || !self.print.jump_ring.is_empty() {
            bail!("--thicken and --jump-ring are not available on {what} yet");
        }
        Ok(())
    }

    /// The output files asked for, each with its flag.
    fn outputs(&self) -> Vec<(&'static str, &std::path::Path)> {
        let named = [
            ("--stl", &self.stl),
            ("--3mf", &self.three_mf),
            ("--png", &self.png),
            ("--svg", &self.svg),
            ("--report", &self.report),
        ];
        named.into_iter().filter_map(|(flag, path)| path.as_deref().map(|p| (flag, p))).collect()
    }

    /// Checks, before any work, that every output can be written and that
    /// no two share a file: a run never computes for minutes only to find
    /// it cannot write.
    pub fn preflight(&self) -> Result<()> {
        let outputs = self.outputs();
        refuse_same_path(&outputs)?;
        for (flag, path) in &outputs {
            check_writable(path).with_context(|| flag.to_string())?;
        }
        Ok(())
    }

    /// The SVG options these flags ask for.
    pub fn svg_options(&self) -> Result<SvgOptions> {
        let kerf_mm = self.kerf.unwrap_or(0.0);
        if !(0.0..=5.0).contains(&kerf_mm) {
            bail!("--kerf must be between 0 and 5 mm, not {kerf_mm}");
        }
        Ok(SvgOptions::new(self.svg_flavour.unwrap_or_default()).with_kerf_mm(kerf_mm))
    }
}

/// What `--report` writes.
#[derive(Serialize)]
pub struct Report<'a> {
    /// The subcommand.
    pub mode: &'static str,
    /// The exemplar (or swatch) used.
    pub exemplar: String,
    /// `--along` as given.
    pub curve: String,
    /// Components counted on the final geometry.
    pub components: usize,
    /// Holes counted on the final geometry (loop openings apart).
    pub holes: usize,
    /// Central openings of a loop.
    pub loop_openings: usize,
    /// Holes of jump rings.
    pub jump_rings: usize,
    /// The mode's own figures.
    #[serde(flatten)]
    pub facts: &'a Facts,
    /// Triangles in the STL.
    pub stl_triangles: usize,
    /// Shells in the STL.
    pub stl_shells: usize,
    /// What the nozzle can print: `thinnest_feature_mm`, `narrowest_gap_mm`,
    /// and every thin feature, narrow gap and weak bridge with its place.
    pub printability: Option<&'a Printability>,
    /// Milliseconds per stage.
    pub timings_ms: &'a Timings,
    /// What the person should know.
    pub warnings: &'a [Warning],
}

/// Writes the outputs asked for and prints a summary. Every file is made in
/// memory first and all are put in place together, so that an error (or
/// Ctrl+C) leaves none behind.
///
/// `placed` says where the pattern went (the `--along` curve, or a shade's shape).
pub fn write_outputs(
    mode: &'static str,
    exemplar: &str,
    placed: &str,
    args: &OutputArgs,
    product: &Product,
    progress: &Progress,
) -> Result<()> {
    let mut stl = Vec::new();
    let (mut triangles, mut shells) = (0, 0);
    if let Some(mesh) = &product.mesh_mm {
        if args.stl.is_some() {
            write_stl(mesh, &mut stl)?;
        }
        (triangles, shells) = (mesh.triangles.len(), mesh.shell_count());
    } else if args.stl.is_some() || args.three_mf.is_some() {
        bail!("this mode makes no solid to write as STL or 3MF");
    }
    let mut three_mf = std::io::Cursor::new(Vec::new());
    if let (Some(_), Some(mesh)) = (&args.three_mf, &product.mesh_mm) {
        let object = ThreeMfObject { name: format!("{exemplar} on {placed}"), colour_rgb: object_colour(0), mesh };
        write_3mf(&[object], &mut three_mf)?;
    }
    let png = match &args.png {
        Some(_) => {
            let dpi = args.dpi.unwrap_or(DEFAULT_DPI);
            if !(dpi.is_finite() && (1.0..=4800.0).contains(&dpi)) {
                bail!("--dpi must be between 1 and 4800, not {dpi}");
            }
            Some(encode_png(&render_product(product, dpi / MM_PER_INCH)?)?)
        }
        None => None,
    };
    let svg_options = args.svg_options()?;
    // A cut SVG unites and offsets the region: only when it is asked for.
    // Stroked paths (a fill) are drawn as strokes for a pen, unless cut
    // outlines are asked for.
    let svg = args.svg.as_ref().map(|_| match svg_options.flavour {
        SvgFlavour::Engrave
            if !(product.paths_mm.is_empty() && product.filled_mm.is_empty()) && svg_options.kerf_mm == 0.0 =>
        {
            write_paths_svg(&product.paths_mm, &product.filled_mm)
        }
        _ => write_svg(&product.region_mm, &svg_options),
    });
    let report = Report {
        mode,
        exemplar: exemplar.to_string(),
        curve: placed.to_string(),
        components: product.topology.components,
        holes: product.topology.holes,
        loop_openings: product.topology.loop_openings,
        jump_rings: product.topology.jump_rings,
        facts: &product.facts,
        stl_triangles: triangles,
        stl_shells: shells,
        printability: product.printability.as_ref(),
        timings_ms: &product.timings,
        warnings: &product.warnings,
    };
    let json = serde_json::to_string_pretty(&report)?;
    let mut files: Vec<(&std::path::Path, &[u8])> = Vec::new();
    if let Some(path) = &args.stl {
        files.push((path, &stl));
    }
    if let Some(path) = &args.three_mf {
        files.push((path, three_mf.get_ref()));
    }
    if let (Some(path), Some(png)) = (&args.png, &png) {
        files.push((path, png));
    }
    if let (Some(path), Some(svg)) = (&args.svg, &svg) {
        files.push((path, svg.as_bytes()));
    }
    if let Some(path) = &args.report {
        files.push((path, json.as_bytes()));
    }
    super::progress::writing(true);
    if progress.is_cancelled() {
        bail!(tracery_core::control::Cancelled);
    }
    write_all_or_none(&files)?;
    progress.finish();
    if progress.is_quiet() {
        return Ok(());
    }
    let t = &product.topology;
    let openings = if t.loop_openings > 0 { format!(" (+{} loop opening)", t.loop_openings) } else { String::new() };
    let rings = if t.jump_rings > 0 { format!(" (+{} jump ring)", t.jump_rings) } else { String::new() };
    let pieces = product.facts.count("pieces").map_or(String::new(), |n| format!(", {n} pieces"));
    say(format_args!(
        "{exemplar}: {} component(s), {} hole(s){openings}{rings}{pieces}; {:.0} ms",
        t.components,
        t.holes,
        product.timings.total_ms()
    ))?;
    for w in &product.warnings {
        say(format_args!("warning: {w}"))?;
    }
    Ok(())
}
