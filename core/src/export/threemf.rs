//! 3MF packages (millimetres): one named, coloured object per mesh.
//!
//! A 3MF file is a zip (the `zip` crate) of XML parts (written with
//! `quick-xml`). The `threemf` crate was not used: it writes `basematerials`
//! after the objects that refer to them and in the materials namespace,
//! which the 3MF core specification forbids (resources are declared before
//! use, and `basematerials` belongs to the core namespace).

use std::io::{Seek, Write};

use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesText, Event};
use zip::ZipWriter;
use zip::write::SimpleFileOptions;

use super::ExportError;
use crate::mesh::Mesh;

/// The 3MF core namespace.
const CORE_NAMESPACE: &str = "http://schemas.microsoft.com/3dmanufacturing/core/2015/02";

const CONTENT_TYPES: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
  <Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
  <Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
</Types>
"#;

const RELATIONSHIPS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
  <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>
"#;

/// Display colours given to objects in turn (sRGB): distinct on a slicer's
/// grey plate.
pub const OBJECT_COLOURS: [[u8; 3]; 6] =
    [[214, 96, 40], [52, 120, 200], [70, 160, 80], [190, 60, 140], [220, 170, 30], [110, 90, 200]];

/// The display colour of the `index`-th object (the palette repeats).
pub fn object_colour(index: usize) -> [u8; 3] {
    OBJECT_COLOURS[index % OBJECT_COLOURS.len()]
}

/// One object in a 3MF package.
#[derive(Clone, Debug)]
pub struct ThreeMfObject<'a> {
    /// Its name, as a slicer lists it.
    pub name: String,
    /// Its display colour, sRGB.
    pub colour_rgb: [u8; 3],
    /// Its solid, millimetres.
    pub mesh: &'a Mesh,
}

/// Writes `objects` as a 3MF package in millimetres, with a build item per
/// object, so a slicer loads each as its own object. Objects without
/// triangles are left out; a package with none is an error.
///
/// ```
/// use tracery_core::export::{ThreeMfObject, write_3mf};
/// use tracery_core::geom::{Polygon, Region};
/// use tracery_core::{DVec2, mesh::extrude};
/// let square = vec![DVec2::new(0.0, 0.0), DVec2::new(5.0, 0.0), DVec2::new(5.0, 5.0), DVec2::new(0.0, 5.0)];
/// let mesh = extrude(&Region::new(vec![Polygon { outer: square, holes: vec![] }]), 2.0).unwrap();
/// let mut bytes = std::io::Cursor::new(Vec::new());
/// let tile = ThreeMfObject { name: "Tile".into(), colour_rgb: [200, 80, 40], mesh: &mesh };
/// write_3mf(&[tile], &mut bytes).unwrap();
/// assert_eq!(&bytes.get_ref()[..2], b"PK");
/// ```
pub fn write_3mf(objects: &[ThreeMfObject<'_>], out: impl Write + Seek) -> Result<(), ExportError> {
    let objects: Vec<&ThreeMfObject<'_>> = objects.iter().filter(|o| !o.mesh.triangles.is_empty()).collect();
    if objects.is_empty() {
        return Err(ExportError::Empty);
    }
    let mut zip = ZipWriter::new(out);
    let options = SimpleFileOptions::default();
    zip.start_file("[Content_Types].xml", options)?;
    zip.write_all(CONTENT_TYPES.as_bytes())?;
    zip.start_file("_rels/.rels", options)?;
    zip.write_all(RELATIONSHIPS.as_bytes())?;
    zip.start_file("3D/3dmodel.model", options)?;
    write_model(&objects, &mut zip)?;
    zip.finish()?;
    Ok(())
}

/// The model part: materials first (declared before use), then objects, then the build.
fn write_model(objects: &[&ThreeMfObject<'_>], out: &mut impl Write) -> std::io::Result<()> {
    let mut xml = Writer::new_with_indent(out, b' ', 1);
    xml.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
    xml.create_element("model")
        .with_attributes([("unit", "millimeter"), ("xml:lang", "en-US"), ("xmlns", CORE_NAMESPACE)])
        .write_inner_content(|xml| {
            for (name, value) in [("Application", "Tracery"), ("Title", "Tracery pattern")] {
                xml.create_element("metadata")
                    .with_attribute(("name", name))
                    .write_text_content(BytesText::new(value))?;
            }
            xml.create_element("resources").write_inner_content(|xml| {
                // Material group id 1; objects are 2, 3, …
                xml.create_element("basematerials").with_attribute(("id", "1")).write_inner_content(|xml| {
                    for o in objects {
                        let [r, g, b] = o.colour_rgb;
                        let colour = format!("#{r:02X}{g:02X}{b:02X}FF");
                        xml.create_element("base")
                            .with_attributes([("name", o.name.as_str()), ("displaycolor", colour.as_str())])
                            .write_empty()?;
                    }
                    Ok(())
                })?;
                for (k, o) in objects.iter().enumerate() {
                    let id = (k + 2).to_string();
                    let pindex = k.to_string();
                    xml.create_element("object")
                        .with_attributes([
                            ("id", id.as_str()),
                            ("type", "model"),
                            ("name", o.name.as_str()),
                            ("pid", "1"),
                            ("pindex", pindex.as_str()),
                        ])
                        .write_inner_content(|xml| write_mesh(xml, o.mesh))?;
                }
                Ok(())
            })?;
            xml.create_element("build").write_inner_content(|xml| {
                for k in 0..objects.len() {
                    xml.create_element("item")
                        .with_attribute(("objectid", (k + 2).to_string().as_str()))
                        .write_empty()?;
                }
                Ok(())
            })?;
            Ok(())
        })?;
    Ok(())
}

fn write_mesh<W: Write>(xml: &mut Writer<W>, mesh: &Mesh) -> std::io::Result<()> {
    xml.create_element("mesh").write_inner_content(|xml| {
        xml.create_element("vertices").write_inner_content(|xml| {
            for v in &mesh.vertices {
                // Meshes are welded in f32: its shortest form keeps them welded.
                let [x, y, z] = v.map(|c| (c as f32).to_string());
                xml.create_element("vertex")
                    .with_attributes([("x", x.as_str()), ("y", y.as_str()), ("z", z.as_str())])
                    .write_empty()?;
            }
            Ok(())
        })?;
        xml.create_element("triangles").write_inner_content(|xml| {
            for t in &mesh.triangles {
                let [a, b, c] = t.map(|i| i.to_string());
                xml.create_element("triangle")
                    .with_attributes([("v1", a.as_str()), ("v2", b.as_str()), ("v3", c.as_str())])
                    .write_empty()?;
            }
            Ok(())
        })?;
        Ok(())
    })?;
    Ok(())
}
