//! The `tracery` command: the app window, or a command-line tool with a subcommand.

use std::process::ExitCode;

use clap::Parser;
use clap::error::ErrorKind;

use tracery::cli;

fn main() -> ExitCode {
    let cli = match cli::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) => e.exit(),
        Err(e) => {
            let text = e.to_string();
            let first = text.lines().next().unwrap_or("invalid arguments").trim_start_matches("error: ");
            eprintln!("tracery: {first} (see `tracery --help`)");
            return ExitCode::from(2);
        }
    };
    if cli.wants_app() {
        return match run_app() {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("tracery: {e}");
                ExitCode::FAILURE
            }
        };
    }
    match cli::run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        // The reader stopped reading (`tracery list | head -1`): nothing
        // more to say to it.
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) if e.is::<cli::Interrupted>() => cli::progress::exit_cancelled(),
        Err(e) => {
            let message = one_line(&e);
            eprintln!("tracery: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run_app() -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Tracery")
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size([720.0, 480.0])
            .with_drag_and_drop(true),
        persist_window: true,
        ..Default::default()
    };
    eframe::run_native("Tracery", options, Box::new(|cc| Ok(Box::new(tracery::TraceryApp::new(cc)))))
}

/// Whether `e` comes from writing to a pipe whose reader has gone.
fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| c.downcast_ref::<std::io::Error>().is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe))
}

/// The error and its causes on one line, each cause once: an error that
/// already quotes its cause (`not an SVG file (…)`) is not followed by it again.
fn one_line(e: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in e.chain() {
        let text = cause.to_string().replace('\n', " ");
        if line.contains(text.trim()) {
            continue;
        }
        if !line.is_empty() {
            line.push_str(": ");
        }
        line.push_str(text.trim());
    }
    line
}
