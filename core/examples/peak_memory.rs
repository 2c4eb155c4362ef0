//! Peak memory of the solver on the benchmark workloads, one per process run.
//!
//! `cargo run -p tracery-core --release --example peak_memory -- braid closed 190`
//!
//! Prints the process's peak resident set (`VmHWM`) before and after solving.

use tracery_core::control::Control;
use tracery_core::vector_brush::{CurveKind, PieceSet, SliceOptions, SolveOptions, Target, builtin, solve};

fn peak_kib() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or(0)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
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
