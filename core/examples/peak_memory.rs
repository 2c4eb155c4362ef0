//! Peak memory of the solver on the benchmark workloads, one per process run.
//!
//! `cargo run -p tracery-core --release --example peak_memory -- braid closed 190`
//!
//! or, the whole pipeline on an SVG exemplar along a curve, with the
//! targets components and holes (a number or `any`):
//!
//! `cargo run -p tracery-core --release --example peak_memory -- --svg FILE.svg circle:40 2 any`
//!
//! Prints the process's peak resident set (`VmHWM`) before and after.

use tracery_core::control::Control;
use tracery_core::curve::Along;
use tracery_core::vector_brush::{
    CurveKind, Exemplar, LoadOptions, PieceSet, Settings, SliceOptions, SolveOptions, Target, builtin, solve,
    synthesize,
};

fn peak_kib() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or(0)
}

/// The whole pipeline on an SVG exemplar: `FILE CURVE COMPONENTS HOLES`.
fn svg_run(args: &[String]) {
    let [file, curve, components, holes] = args else {
        panic!("expected: --svg FILE.svg CURVE COMPONENTS HOLES");
    };
    let exemplar = Exemplar::from_svg_file(std::path::Path::new(file), &LoadOptions::default()).expect("exemplar");
    let Ok(Along::Curve(along)) = Along::parse(curve) else { panic!("{curve} is not a curve") };
    let target = |t: &str| if t == "any" { Target::Any } else { Target::Exactly(t.parse().expect("a number or any")) };
    let mut settings = Settings::default();
    settings.components = target(components);
    settings.holes = target(holes);
    settings.closed_pattern = along.is_closed();
    let before = peak_kib();
    let synthesis = synthesize(&exemplar, &along, &settings, &Control::default()).expect("synthesis");
    let after = peak_kib();
    println!(
        "{file} {curve} {components}/{holes}: {} states, bounded {:?}, peak RSS {:.1} MB before, {:.1} MB after",
        synthesis.solution.states,
        synthesis.solution.bounded,
        before as f64 / 1024.0,
        after as f64 / 1024.0
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().is_some_and(|a| a == "--svg") {
        return svg_run(&args[1..]);
    }
    let name = args.first().map_or("braid", String::as_str);
    let curve = if args.get(1).is_some_and(|c| c == "open") { CurveKind::Open } else { CurveKind::Closed };
    let pieces: f64 = args.get(2).and_then(|p| p.parse().ok()).unwrap_or(190.0);
    let set = PieceSet::new(&builtin(name).expect("built-in exemplar"), &SliceOptions::default()).expect("slicing");
    let mut options = SolveOptions::new(pieces * set.exemplar_width / set.len() as f64);
    options.curve = curve;
    options.components = Target::Exactly(1);
    options.closed_pattern = curve == CurveKind::Closed;
    options.variety = 0.5;
    let before = peak_kib();
    let solution = solve(&set, &options, &Control::default()).expect("solution");
    let after = peak_kib();
    println!(
        "{name} {curve:?} {pieces}: {} pieces, {} states, peak RSS {:.1} MB before solving, {:.1} MB after",
        solution.pieces.len(),
        solution.states,
        before as f64 / 1024.0,
        after as f64 / 1024.0
    );
}
