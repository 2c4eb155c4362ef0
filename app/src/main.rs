//! The `tracery` command.

use std::process::ExitCode;

use anyhow::{Context, Result};
use tracery_core::{BUILTIN_NAMES, PieceSet, SliceOptions, builtin};

const USAGE: &str = "\
usage: tracery <command>

commands:
  list        print the built-in exemplars
  help        print this message";

fn list() -> Result<()> {
    for name in BUILTIN_NAMES {
        let exemplar = builtin(name).with_context(|| format!("loading built-in exemplar '{name}'"))?;
        let pieces = PieceSet::new(&exemplar, &SliceOptions::default())
            .with_context(|| format!("cutting built-in exemplar '{name}'"))?;
        println!(
            "{name:10} {:3} component(s) {:3} hole(s) {:3} pieces",
            exemplar.region.component_count(),
            exemplar.region.hole_count(),
            pieces.len()
        );
    }
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("list") => list(),
        Some("help" | "--help" | "-h") | None => {
            println!("{USAGE}");
            Ok(())
        }
        Some("--version" | "-V") => {
            println!("tracery {}", env!("CARGO_PKG_VERSION"));
            Ok(())
        }
        Some(other) => Err(anyhow::anyhow!("unknown command '{other}'\n{USAGE}")),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("tracery: {e:#}");
            ExitCode::FAILURE
        }
    }
}
