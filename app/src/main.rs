//! The `tracery` command.

use std::process::ExitCode;

use clap::Parser;

mod cli;

fn main() -> ExitCode {
    let cli = cli::Cli::parse();
    match cli::run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // One line: the error and its causes.
            let message = format!("{e:#}").replace('\n', " ");
            eprintln!("tracery: {message}");
            ExitCode::FAILURE
        }
    }
}
