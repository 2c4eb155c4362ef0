//! How every SVG Tracery reads is parsed: exemplars, curves and regions,
//! from a file or from a project that carries them. Nothing outside the
//! document is read: an `<image>` whose `href` names a file, a device or a
//! URL is dropped without opening it (usvg's default options open any local
//! path, relative ones from the current folder, so an SVG could read
//! `/etc/shadow` or grow without bound on `/dev/zero`), and embedded `data:`
//! images are dropped too: Tracery takes only shapes from an SVG.
//!
//! ```
//! let svg = br#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">
//!   <image href="/etc/passwd" width="10" height="10"/><path d="M1,1 L9,9"/></svg>"#;
//! let tree = usvg::Tree::from_data(svg, &tracery_core::svg_input::options()).unwrap();
//! assert_eq!(tree.root().children().len(), 1, "the image is dropped, the path kept");
//! assert!(tracery_core::svg_input::refused_hrefs().iter().any(|h| h == "/etc/passwd"));
//! ```

use std::sync::Mutex;

/// The last hrefs usvg asked to resolve and were refused, newest last: a
/// seam for tests to see that an external reference reached this module
/// (and so was not opened by the parser).
static REFUSED: Mutex<Vec<String>> = Mutex::new(Vec::new());

/// How many refused hrefs are remembered.
const REMEMBERED: usize = 64;

/// usvg options that read nothing outside the document.
pub fn options() -> usvg::Options<'static> {
    usvg::Options {
        resources_dir: None,
        image_href_resolver: usvg::ImageHrefResolver {
            resolve_data: Box::new(|mime, _, _| {
                remember(format!("data:{mime}"));
                None
            }),
            resolve_string: Box::new(|href, _| {
                remember(href.to_string());
                None
            }),
        },
        ..usvg::Options::default()
    }
}

fn remember(href: String) {
    let mut refused = REFUSED.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if refused.len() >= REMEMBERED {
        refused.remove(0);
    }
    refused.push(href);
}

/// The hrefs refused lately (see [`options`]).
pub fn refused_hrefs() -> Vec<String> {
    REFUSED.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).clone()
}

/// Why an SVG could not be read, in words for the person who made it
/// (usvg's own words are for developers: "enable svgz cargo feature").
///
/// ```
/// use tracery_core::svg_input::describe;
/// assert_eq!(
///     describe(&usvg::Error::SvgzFeatureNotEnabled),
///     "it is a compressed SVG (.svgz): save it as plain SVG and try again"
/// );
/// ```
pub fn describe(e: &usvg::Error) -> String {
    match e {
        usvg::Error::NotAnUtf8Str => "it is not text (SVG is UTF-8 text)".into(),
        usvg::Error::SvgzFeatureNotEnabled | usvg::Error::MalformedGZip => {
            "it is a compressed SVG (.svgz): save it as plain SVG and try again".into()
        }
        usvg::Error::ElementsLimitReached => "it has more than a million elements".into(),
        usvg::Error::InvalidSize => "it has no width and height (nor a viewBox) of more than zero".into(),
        usvg::Error::ParsingFailed(xml) => format!("it is not well-formed XML ({xml})"),
    }
}
