//! Projects: a file written before documents were versioned still opens,
//! with every curve's settings, and the current format round-trips.

use std::path::PathBuf;

use egui_kittest::Harness;
use tracery::TraceryApp;
use tracery::cli::SynthArgs;
use tracery::dialogs::{FileKind, ScriptedDialogs};
use tracery::document::{Document, DocumentError, ExemplarRef, FORMAT_VERSION, ModeSettings, VectorBrushItem};
use tracery::worker::JobState;
use tracery_core::vector_brush::{Settings, SlicingMode, Target};

#[path = "common/ui.rs"]
mod ui;
use ui::settle;

fn format_0_project() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/data/project-format-0.ron")
}

fn vector(item: &ModeSettings) -> &VectorBrushItem {
    let ModeSettings::VectorBrush(v) = item else { panic!("not a vector-brush curve") };
    v
}

#[test]
fn a_project_saved_before_versioning_opens_with_its_settings() {
    let text = std::fs::read_to_string(format_0_project()).unwrap();
    assert!(!text.contains("format_version"), "the checked-in file is from before versioning");
    let doc = Document::from_ron(&text).unwrap();
    assert_eq!(doc.format_version, FORMAT_VERSION);
    assert_eq!(doc.curves.len(), 3);
    assert_eq!(doc.next_id, 3);
    assert_eq!(doc.imported.len(), 1);

    // The first curve used every default of that version, kept as saved:
    // the variety default has since gone from 0.3 to 0.8, and an old
    // project must still give the pattern it gave.
    let first = vector(&doc.curves[0].mode);
    assert!(doc.curves[0].closed);
    assert_eq!(doc.curves[0].points.len(), 16);
    assert_eq!(first.exemplar, ExemplarRef::Builtin("lace".into()));
    let mut then = Settings::default();
    then.variety = 0.3;
    assert_eq!(first.settings, then);

    // The second set everything by hand.
    let second = vector(&doc.curves[1].mode);
    assert_eq!(second.exemplar, ExemplarRef::Imported("beads".into()));
    let s = &second.settings;
    assert_eq!((s.components, s.holes, s.closed_pattern), (Target::Exactly(1), Target::Exactly(0), false));
    assert_eq!((s.band_mm, s.variety, s.min_portal_mm, s.thickness_mm, s.seed), (8.0, 0.0, 0.2, 1.5, 7));
    assert_eq!(s.slicing, SlicingMode::Uniform { cuts: 6 });
    assert!(doc.exemplar(&second.exemplar).is_ok(), "the embedded exemplar loads");

    let third = vector(&doc.curves[2].mode);
    assert_eq!((third.exemplar.name(), third.settings.components), ("vine", Target::Any));
}

#[test]
fn the_current_format_round_trips_and_newer_ones_are_refused() {
    let doc = Document::from_ron(&std::fs::read_to_string(format_0_project()).unwrap()).unwrap();
    let text = doc.to_ron().unwrap();
    assert!(text.contains(&format!("format_version: {FORMAT_VERSION}")));
    assert_eq!(Document::from_ron(&text).unwrap(), doc);
    let newer = text.replace(&format!("format_version: {FORMAT_VERSION}"), "format_version: 99");
    assert_eq!(Document::from_ron(&newer), Err(DocumentError::TooNew { found: 99 }));
    assert!(matches!(Document::from_ron("(curves: 3)"), Err(DocumentError::NotAProject(_))));
}

#[test]
fn the_app_opens_an_old_project_and_synthesizes_every_curve() {
    let answers = vec![(FileKind::OpenProject, format_0_project())];
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_eframe(move |_| TraceryApp::with(Box::new(ScriptedDialogs { answers }), None));
    harness.step();
    harness.state_mut().queue(tracery::command::Command::Open);
    harness.step();
    settle(&mut harness);
    let app = harness.state();
    assert_eq!(app.doc.curves.len(), 3, "{:?}", app.message);
    for curve in &app.doc.curves {
        match app.job_state(curve.id) {
            Some(JobState::Done(Ok(product))) => {
                let s = &vector(&curve.mode).settings;
                if let Target::Exactly(n) = s.components {
                    assert_eq!(product.topology.components, n as usize, "curve {}", curve.id);
                }
                if let Target::Exactly(n) = s.holes {
                    assert_eq!(product.topology.holes, n as usize, "curve {}", curve.id);
                }
            }
            other => panic!("curve {}: {other:?}", curve.id),
        }
    }
}

#[test]
fn the_command_line_and_the_app_share_their_defaults() {
    use clap::Parser;
    #[derive(Parser)]
    struct Wrapper {
        #[command(flatten)]
        args: SynthArgs,
    }
    let parsed = Wrapper::parse_from(["synth", "--exemplar", "lace", "--along", "line:100"]).args;
    assert_eq!(parsed.settings(), Settings::default());
    let app = TraceryApp::with(Box::new(ScriptedDialogs::default()), None);
    assert_eq!(vector(app.settings()).settings, parsed.settings(), "new curves in the app use the same defaults");
    let flag_alone = Wrapper::parse_from(["synth", "--exemplar", "lace", "--along", "x:1", "--closed-pattern"]).args;
    assert!(flag_alone.settings().closed_pattern);
    let off = Wrapper::parse_from(["synth", "--exemplar", "l", "--along", "x:1", "--closed-pattern", "false"]).args;
    assert!(!off.settings().closed_pattern);
    // A shade's flags fall back on the same settings, and on the shade's own defaults.
    #[derive(Parser)]
    struct ShadeWrapper {
        #[command(flatten)]
        args: tracery::cli::ShadeArgs,
    }
    let shade = ShadeWrapper::parse_from(["shade", "--exemplar", "lace", "--cylinder", "40,60"]).args;
    assert_eq!(shade.brush.settings(), Settings::default());
    let (made, spec) = shade.shade_settings().unwrap();
    let defaults = tracery_core::surface::ShadeSettings::default();
    assert_eq!(
        (made.rim_mm, made.row_overlap_mm, spec.as_str()),
        (defaults.rim_mm, defaults.row_overlap_mm, "cylinder:40,60")
    );
}

#[test]
fn a_raster_project_keeps_its_pictures_and_avoided_areas() {
    use tracery::document::{AvoidStroke, RasterBrushItem};
    let mut doc = Document::default();
    let mut png = Vec::new();
    let bar = image::RgbaImage::from_fn(60, 20, |x, y| {
        image::Rgba([x as u8 * 4, 90, 40, if (5..15).contains(&y) { 255 } else { 0 }])
    });
    bar.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png).unwrap();
    let bar_ref = doc.import_png("bar.png", &png).unwrap();
    assert_eq!(bar_ref, ExemplarRef::Imported("bar".into()));
    assert!(doc.import_png("notes.png", b"not a picture").is_err());
    let item = RasterBrushItem { exemplar: bar_ref.clone(), ..RasterBrushItem::default() };
    doc.add_curve(
        vec![tracery_core::DVec2::ZERO, tracery_core::DVec2::new(50.0, 0.0)],
        false,
        ModeSettings::RasterBrush(item),
    );
    doc.avoid.push(AvoidStroke { points: vec![[10.0, -5.0], [12.0, 5.0]], width_mm: 4.0 });

    let text = doc.to_ron().unwrap();
    // The picture travels as base64 text, not as a list of numbers.
    assert!(text.len() < 2 * png.len() + 2000, "{} bytes of project for a {}-byte picture", text.len(), png.len());
    let back = Document::from_ron(&text).unwrap();
    assert_eq!(back, doc);
    assert_eq!(*back.imported_raster[0].png, *png);
    let exemplar = back.raster_exemplar(&bar_ref).unwrap();
    assert_eq!((exemplar.width(), exemplar.height()), (60, 20));
    // The avoided area is the brush's capsule: 4 mm wide around a 10.2 mm stroke.
    let area = tracery::document::avoided_region(&back.avoid).area();
    let expected = 4.0 * 104f64.sqrt() + std::f64::consts::PI * 4.0;
    assert!((area - expected).abs() < 0.1, "{area} vs {expected}");
}

#[test]
fn the_command_line_and_the_app_share_the_raster_defaults() {
    use clap::Parser;
    use tracery::cli::RasterArgs;
    #[derive(Parser)]
    struct Wrapper {
        #[command(flatten)]
        args: RasterArgs,
    }
    let parsed = Wrapper::parse_from(["raster", "--exemplar", "rope", "--along", "line:100"]).args;
    use tracery::modes::ModeUi;
    let ModeSettings::RasterBrush(item) = tracery::modes::raster_brush::RasterBrushUi.default_settings() else {
        panic!("not raster")
    };
    assert_eq!(item.settings, parsed.settings());
    assert_eq!(item.settings, tracery_core::raster_brush::Settings::default());
}

#[test]
fn an_imported_model_and_its_curves_survive_saving_and_opening() {
    use tracery::document::{BaseRef, SurfaceCurveItem};
    use tracery_core::surface::builtin_base;
    let egg = builtin_base("egg").unwrap();
    let mut doc = Document::default();
    let base = doc.model.import("my egg.stl", &egg).unwrap();
    assert_eq!(base, BaseRef::Imported("my egg".into()));
    doc.model.base = base.clone();
    let mut template = SurfaceCurveItem::default();
    template.surface.closed = true;
    let id = doc.add_surface_curve(&template);
    doc.model.curve_mut(id).unwrap().surface.points_mm = vec![[21.0, 0.0, 30.0], [0.0, 21.0, 30.0]];
    let back = Document::from_ron(&doc.to_ron().unwrap()).unwrap();
    assert_eq!(back, doc, "the model workspace round-trips");
    // The embedded model is the same mesh, to the precision of a binary STL.
    let mesh = back.model.base_mesh(&base).unwrap();
    assert_eq!(mesh.triangles.len(), egg.triangles.len());
    let worst = mesh
        .vertices
        .iter()
        .map(|v| {
            egg.vertices
                .iter()
                .map(|w| (0..3).map(|k| (v[k] - w[k]).abs()).fold(0.0, f64::max))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    assert!(worst < 1e-5, "an embedded vertex moved {worst} mm");
    // A project naming a model it does not hold says so.
    let missing = back.model.base_mesh(&BaseRef::Imported("lamp".into())).unwrap_err();
    assert!(missing.to_string().contains("'lamp' is missing"), "{missing}");
}
