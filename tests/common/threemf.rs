//! An independent 3MF reader for tests: a zip reader and an XML parser,
//! sharing nothing with the writer, and PrusaSlicer's `--info` where it is
//! installed (CI installs it and sets `TRACERY_REQUIRE_SLICER`).
#![allow(dead_code)]

use std::collections::{HashMap, HashSet};
use std::io::{Cursor, Read};
use std::path::Path;

use quick_xml::events::Event;

/// An object as read: its name, vertices and triangles.
pub type ReadObject = (String, Vec<[f64; 3]>, Vec<[usize; 3]>);

/// What a 3MF reader finds.
pub struct Read3mf {
    pub unit: String,
    pub objects: Vec<ReadObject>,
    pub build_items: usize,
    /// Material ids declared before the first object that refers to them.
    pub declared_before_use: bool,
}

fn attr(e: &quick_xml::events::BytesStart<'_>, name: &str) -> Option<String> {
    e.attributes()
        .flatten()
        .find(|a| a.key.as_ref() == name.as_bytes())
        .map(|a| a.normalized_value(quick_xml::XmlVersion::Implicit1_0).unwrap().into_owned())
}

pub fn read_3mf(bytes: &[u8]) -> Read3mf {
    let mut zip = zip::ZipArchive::new(Cursor::new(bytes)).expect("a zip archive");
    let mut text = |name: &str| {
        let mut s = String::new();
        zip.by_name(name).unwrap_or_else(|_| panic!("{name} in the package")).read_to_string(&mut s).unwrap();
        s
    };
    let types = text("[Content_Types].xml");
    assert!(types.contains("application/vnd.ms-package.3dmanufacturing-3dmodel+xml"));
    let rels = text("_rels/.rels");
    let target = rels.split("Target=\"").nth(1).and_then(|s| s.split('"').next()).expect("a relationship target");
    let model = text(target.trim_start_matches('/'));
    let mut reader = quick_xml::Reader::from_str(&model);
    let mut out = Read3mf { unit: String::new(), objects: Vec::new(), build_items: 0, declared_before_use: true };
    let mut materials = HashSet::new();
    loop {
        match reader.read_event().expect("well-formed XML") {
            Event::Eof => break,
            Event::Start(e) | Event::Empty(e) => match e.name().as_ref() {
                b"model" => out.unit = attr(&e, "unit").unwrap_or_default(),
                b"basematerials" => {
                    materials.insert(attr(&e, "id").unwrap());
                }
                b"object" => {
                    if let Some(pid) = attr(&e, "pid") {
                        out.declared_before_use &= materials.contains(&pid);
                    }
                    out.objects.push((attr(&e, "name").unwrap_or_default(), Vec::new(), Vec::new()));
                }
                b"vertex" => {
                    let c = |n| attr(&e, n).unwrap().parse::<f64>().unwrap();
                    out.objects.last_mut().unwrap().1.push([c("x"), c("y"), c("z")]);
                }
                b"triangle" => {
                    let c = |n| attr(&e, n).unwrap().parse::<usize>().unwrap();
                    out.objects.last_mut().unwrap().2.push([c("v1"), c("v2"), c("v3")]);
                }
                b"item" => out.build_items += 1,
                _ => {}
            },
            _ => {}
        }
    }
    out
}

/// Whether every directed edge appears once and its reverse once: closed and
/// consistently oriented.
pub fn is_closed(triangles: &[[usize; 3]]) -> bool {
    let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
    for t in triangles {
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    edges.iter().all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1))
}

/// What `prusa-slicer --info` says of a file: (manifold, number of
/// objects), or `None` when PrusaSlicer is not installed and not required.
pub fn prusa_info(path: &Path) -> Option<(bool, usize)> {
    let out = match std::process::Command::new("prusa-slicer").arg("--info").arg(path).output() {
        Ok(out) => out,
        Err(_) if std::env::var_os("TRACERY_REQUIRE_SLICER").is_none() => return None,
        Err(e) => panic!("prusa-slicer is required (TRACERY_REQUIRE_SLICER) but did not run: {e}"),
    };
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "prusa-slicer --info failed: {text}");
    // One "[name]" block per object, each saying whether it is manifold.
    let objects = text.lines().filter(|l| l.trim_start().starts_with("manifold =")).count();
    let manifold = text.lines().filter(|l| l.trim_start().starts_with("manifold =")).all(|l| l.ends_with("yes"));
    Some((manifold, objects))
}
