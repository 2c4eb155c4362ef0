//! Fuzzing what the app and the command line read from a person: project
//! files (RON), mutated from a real one, and the command line's flags. Each
//! must load or be refused: never panic. `TRACERY_FUZZ_CASES` sets the
//! cases (see `docs/robustness.md` for the long run).

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use tracery::document::{Document, ModeSettings, RasterBrushItem, VectorBrushItem};
use tracery_core::DVec2;

fn config() -> Config {
    let cases = std::env::var("TRACERY_FUZZ_CASES").ok().and_then(|c| c.parse().ok()).unwrap_or(48);
    Config { cases, failure_persistence: None, ..Config::default() }
}

/// A project with a curve of each kind, as the app saves it.
fn project() -> String {
    let mut doc = Document::default();
    let stroke = vec![DVec2::ZERO, DVec2::new(30.0, 5.0), DVec2::new(60.0, 0.0)];
    doc.add_curve(stroke.clone(), false, ModeSettings::VectorBrush(VectorBrushItem::default()));
    doc.add_curve(stroke, false, ModeSettings::RasterBrush(RasterBrushItem::default()));
    let id = doc.add_surface_curve(&tracery::document::SurfaceCurveItem::default());
    doc.model.curve_mut(id).unwrap().surface.points_mm = vec![[30.0, 0.0, 25.0], [0.0, 30.0, 25.0]];
    doc.to_ron().unwrap()
}

/// Text that breaks parsers and programs.
const NASTY: &[&str] = &[
    "1e308",
    "-1e308",
    "NaN",
    "inf",
    "-0",
    "18446744073709551615",
    "99999999999",
    "(",
    ")",
    "[",
    "]",
    ",",
    "\"",
    "Some(",
    "None",
    "",
];

#[test]
fn any_project_file_loads_or_is_refused() {
    let seed = project();
    let edit = (any::<usize>(), any::<usize>(), proptest::sample::select(NASTY));
    let mut runner = TestRunner::new(config());
    runner
        .run(&proptest::collection::vec(edit, 1..8), |edits| {
            let mut text = seed.clone();
            for (at, cut, insert) in edits {
                // Cut and insert at character boundaries, where a text editor would.
                let at = text.char_indices().map(|(i, _)| i).nth(at % text.chars().count().max(1)).unwrap_or(0);
                let end = text[at..].char_indices().map(|(i, _)| at + i).nth(cut % 12).unwrap_or(text.len());
                text.replace_range(at..end, insert);
            }
            if let Ok(doc) = Document::from_ron(&text) {
                // What loads can be saved again.
                doc.to_ron().unwrap();
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn any_flag_value_is_parsed_or_refused() {
    use clap::Parser as _;
    let value = prop_oneof![
        proptest::sample::select(NASTY).prop_map(str::to_string),
        any::<f64>().prop_map(|x| x.to_string()),
        "[-0-9.e,;x:a-z]{0,24}",
    ];
    let flag = proptest::sample::select(&["--jump-ring", "--along", "--band", "--kerf", "--dpi", "--components"][..]);
    let mut runner = TestRunner::new(config());
    runner
        .run(&(flag, value), |(flag, value)| {
            let args = ["tracery", "synth", "--exemplar", "lace", flag, &value];
            if let Ok(cli) = tracery::cli::Cli::try_parse_from(args) {
                let _ = cli.wants_app();
            }
            Ok(())
        })
        .unwrap();
}
