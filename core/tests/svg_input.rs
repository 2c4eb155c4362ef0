//! SVGs read nothing outside themselves: an `<image>` naming a file, a
//! device, a relative path or a URL is never opened by any of the loaders
//! (exemplars, curves, regions and fill exemplars), and a `data:` image is
//! dropped. The resolver in `svg_input` records each href it was asked
//! for: seeing it there shows the parser handed the href over instead of
//! opening it itself.

use std::time::{Duration, Instant};

use tracery_core::curve::{first_path_points, svg_shapes};
use tracery_core::svg_input::refused_hrefs;
use tracery_core::vector_brush::{Exemplar, LoadOptions};

const HREFS: [&str; 7] = [
    "/etc/passwd",
    "/dev/zero",
    "../../../../etc/passwd",
    "secret.png",
    "file:///etc/shadow",
    "http://198.51.100.7/x.png",
    "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mNk+M9QDwADhgGAWjR9awAAAABJRU5ErkJggg==",
];

fn svg_with_image(href: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="100mm" height="40mm" viewBox="0 0 100 40">
  <image xlink:href="{href}" x="0" y="0" width="100" height="40"/>
  <path d="M0,10 H100 V30 H0 Z M10,15 H20 V25 H10 Z" fill="black"/>
</svg>"#
    )
}

#[test]
fn no_loader_opens_what_an_svg_image_names() {
    for href in HREFS {
        let svg = svg_with_image(href);
        let started = Instant::now();
        let exemplar = Exemplar::from_svg_data("probe", svg.as_bytes(), &LoadOptions::default());
        let points = first_path_points(svg.as_bytes());
        let shapes = svg_shapes(svg.as_bytes(), 0.05);
        // `/dev/zero` read to its end would never finish.
        assert!(started.elapsed() < Duration::from_secs(10), "{href}: {:?}", started.elapsed());
        // The shapes are read as if the image were not there.
        assert!(exemplar.is_ok(), "{href}: {:?}", exemplar.err());
        assert_eq!(points.map(|p| p.len() > 2), Ok(true), "{href}");
        assert_eq!(shapes.map(|s| !s.is_empty()), Ok(true), "{href}");
        let seen = if let Some(rest) = href.strip_prefix("data:") {
            format!("data:{}", rest.split(';').next().unwrap())
        } else {
            href.to_string()
        };
        assert!(refused_hrefs().contains(&seen), "{href} was not handed to the resolver: {:?}", refused_hrefs());
    }
}
