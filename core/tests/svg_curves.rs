//! Curves taken from SVG files: the file's own size where it gives one, and
//! tangents along every segment of a path drawn with few points.

use tracery_core::curve::Along;

fn curve_from(svg: &str, name: &str) -> tracery_core::curve::Curve {
    let path = std::env::temp_dir().join(format!("tracery-svg-curve-{}-{name}.svg", std::process::id()));
    std::fs::write(&path, svg).unwrap();
    let curve = Along::curve_from_svg(&path).unwrap();
    let _ = std::fs::remove_file(&path);
    curve
}

#[test]
fn a_file_sized_in_millimetres_keeps_its_size() {
    for (width, expected) in [("100mm", 80.0), ("10cm", 80.0), ("", 80.0), ("200mm", 160.0)] {
        let size = if width.is_empty() { String::new() } else { format!(r#"width="{width}" height="{width}""#) };
        let svg = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" {size} viewBox="0 0 100 100"><path d="M10,50 L90,50" fill="none" stroke="black"/></svg>"#
        );
        let curve = curve_from(&svg, "size");
        assert!((curve.length() - expected).abs() < 0.01, "width {width:?}: {} mm", curve.length());
    }
}

#[test]
fn an_l_shaped_path_of_three_points_has_square_normals_along_its_legs() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path d="M10,90 L10,10 L90,10" fill="none" stroke="black"/></svg>"#;
    let curve = curve_from(svg, "l");
    assert!((curve.length() - 160.0).abs() < 0.5);
    // A quarter and three quarters of the way: the middle of each leg.
    for u in [0.25 * curve.length(), 0.75 * curve.length()] {
        let t = curve.tangent(u);
        let axis_aligned = t.x.abs() > 0.999 || t.y.abs() > 0.999;
        assert!(axis_aligned, "tangent {t} at {u} mm should run along the leg");
    }
}
