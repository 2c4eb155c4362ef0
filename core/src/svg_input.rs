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

/// The largest number an SVG's geometry may hold, in its own units: far
/// beyond any drawing (a billion pixels is 264 km), and far below what
/// makes usvg's arc conversion allocate without bound (an arc of radius
/// `1e123` asked for 7.5 GB).
pub const MAX_SVG_NUMBER: f64 = 1e9;

/// The attributes whose numbers are geometry.
const GEOMETRY_ATTRIBUTES: &[&str] = &[
    "d",
    "points",
    "x",
    "y",
    "x1",
    "y1",
    "x2",
    "y2",
    "cx",
    "cy",
    "r",
    "rx",
    "ry",
    "width",
    "height",
    "transform",
    "viewBox",
    "style",
    "stroke-width",
    "pathLength",
];

/// Parses an SVG as every reader in Tracery does: external resources off
/// ([`options`]), compressed SVG refused, and numbers larger than
/// [`MAX_SVG_NUMBER`] refused before usvg converts anything. The error is
/// in a person's words.
///
/// ```
/// use tracery_core::svg_input::parse;
/// let arc = br#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><path d="M0,0 A3.5,1e123 0 1 1 7,0"/></svg>"#;
/// assert!(parse(arc).unwrap_err().contains("1e123"));
/// let fine = br#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><path d="M0,0 A3.5,3.5 0 1 1 7,0"/></svg>"#;
/// assert!(parse(fine).is_ok());
/// ```
pub fn parse(data: &[u8]) -> Result<usvg::Tree, String> {
    if data.starts_with(&[0x1f, 0x8b]) {
        return Err(describe(&usvg::Error::SvgzFeatureNotEnabled));
    }
    let text = std::str::from_utf8(data).map_err(|_| describe(&usvg::Error::NotAnUtf8Str))?;
    let xml = roxmltree::ParsingOptions { allow_dtd: true, ..Default::default() };
    let doc =
        roxmltree::Document::parse_with_options(text, xml).map_err(|e| describe(&usvg::Error::ParsingFailed(e)))?;
    for node in doc.descendants() {
        let style_text = (node.tag_name().name() == "style").then(|| node.text()).flatten();
        let attributes =
            node.attributes().filter(|a| GEOMETRY_ATTRIBUTES.contains(&a.name())).map(|a| (a.name(), a.value()));
        for (name, value) in attributes.chain(style_text.map(|t| ("style", t))) {
            if let Some(x) = numbers(value).find(|x| x.abs() > MAX_SVG_NUMBER) {
                return Err(format!(
                    "its <{}> has a number too large to draw ({x:e} in '{name}'); numbers up to {MAX_SVG_NUMBER:e} are read",
                    node.tag_name().name()
                ));
            }
        }
    }
    usvg::Tree::from_xmltree(&doc, &options()).map_err(|e| describe(&e))
}

/// The numbers in `text`, read as SVG reads them: `1e123.5` is `1e123`
/// then `.5`, `1-2` is `1` then `-2`.
fn numbers(text: &str) -> impl Iterator<Item = f64> + '_ {
    let bytes = text.as_bytes();
    let mut at = 0;
    std::iter::from_fn(move || {
        let digits = |from: usize| from + bytes[from..].iter().take_while(|b| b.is_ascii_digit()).count();
        while at < bytes.len() {
            let start = at;
            let mut end = at;
            if matches!(bytes[end], b'+' | b'-') {
                end += 1;
            }
            let whole = digits(end);
            let mut fraction = whole;
            if bytes.get(whole) == Some(&b'.') {
                fraction = digits(whole + 1);
            }
            if fraction == end || (fraction == end + 1 && bytes[end] == b'.') {
                at = start + 1;
                continue;
            }
            end = fraction;
            if matches!(bytes.get(end), Some(b'e' | b'E')) {
                let sign = end + 1 + usize::from(matches!(bytes.get(end + 1), Some(b'+' | b'-')));
                let exponent = digits(sign);
                if exponent > sign {
                    end = exponent;
                }
            }
            at = end;
            if let Ok(x) = text[start..end].parse::<f64>() {
                return Some(x);
            }
        }
        None
    })
}
