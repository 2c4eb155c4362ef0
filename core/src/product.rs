//! [`Product`]: what every mode returns, and all that the canvas, the 3D
//! preview, export and the command-line report consume.

use glam::DVec2;
use serde::Serialize;
use serde::ser::SerializeMap;

use crate::geom::{PatternTopology, Region};
use crate::mesh::Mesh;
use crate::report::{Timings, Warning};

/// A path drawn with a pen of some width (region fill draws these), mm.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StrokedPath {
    /// The points, mm, `y` up.
    pub points_mm: Vec<DVec2>,
    /// Whether the path closes on itself.
    pub closed: bool,
    /// Pen width, mm.
    pub width_mm: f64,
}

/// An RGBA picture laid in the plane (the raster brush makes these).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RasterImage {
    /// Width, pixels.
    pub width_px: u32,
    /// Height, pixels.
    pub height_px: u32,
    /// Rows top to bottom, 4 bytes a pixel, not premultiplied.
    pub rgba: Vec<u8>,
    /// Where the picture's lower-left corner lies, mm.
    pub origin_mm: DVec2,
    /// Millimetres per pixel.
    pub mm_per_px: f64,
}

/// A picture used as a texture, shared without copying (an exemplar).
///
/// ```
/// use tracery_core::product::Texture;
/// let t = Texture::new(1, 1, vec![255, 0, 0, 255]).unwrap();
/// assert_eq!(t.pixel(0, 0), [255, 0, 0, 255]);
/// assert_eq!(t.pixel(5, -1), [0, 0, 0, 0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Width, pixels.
    pub width_px: u32,
    /// Height, pixels.
    pub height_px: u32,
    /// Rows top to bottom, 4 bytes a pixel, not premultiplied.
    pub rgba: std::sync::Arc<[u8]>,
}

impl Texture {
    /// A texture of `width_px × height_px` pixels, or `None` when `rgba` has
    /// not 4 bytes for each of them.
    pub fn new(width_px: u32, height_px: u32, rgba: Vec<u8>) -> Option<Texture> {
        (rgba.len() == 4 * width_px as usize * height_px as usize).then(|| Texture {
            width_px,
            height_px,
            rgba: rgba.into(),
        })
    }

    /// The pixel at column `x`, row `y`; transparent outside the picture.
    pub fn pixel(&self, x: i64, y: i64) -> [u8; 4] {
        if x < 0 || y < 0 || x >= self.width_px as i64 || y >= self.height_px as i64 {
            return [0; 4];
        }
        let i = 4 * (y as usize * self.width_px as usize + x as usize);
        [self.rgba[i], self.rgba[i + 1], self.rgba[i + 2], self.rgba[i + 3]]
    }
}

/// Triangles in the plane that show parts of a [`Texture`] (the raster
/// brush's pieces): drawn as they are by the canvas, rendered to PNG by
/// [`crate::export::render_textured`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TexturedMesh {
    /// The picture the triangles show.
    pub texture: Option<Texture>,
    /// Vertex positions, mm, `y` up.
    pub positions_mm: Vec<DVec2>,
    /// Vertex texture coordinates, texture pixels (`x` right, `y` down).
    pub uvs_px: Vec<DVec2>,
    /// Triangles, as indices into the vertices.
    pub triangles: Vec<[u32; 3]>,
}

/// Drawn over the result to explain it; never exported.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overlays {
    /// The band's edges along the curve, mm.
    pub band_edges_mm: Vec<Vec<DVec2>>,
    /// Seams between pieces, as short segments across the band, mm.
    pub seams_mm: Vec<[DVec2; 2]>,
    /// Areas the pattern had to leave empty (fold-overs of the band, avoided
    /// areas), mm.
    pub avoided_mm: Region,
}

/// A figure about a result, for reports (named in [`Facts`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Fact {
    /// A count.
    Count(usize),
    /// A measure (its name says the unit).
    Number(f64),
    /// Words.
    Text(String),
    /// A list of indices (a piece sequence, say).
    Indices(Vec<usize>),
}

/// Mode-specific figures, in the order the mode gave them. Serialized as a map.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Facts(pub Vec<(&'static str, Fact)>);

impl Facts {
    /// Adds a figure.
    pub fn push(&mut self, name: &'static str, fact: Fact) {
        self.0.push((name, fact));
    }

    /// The figure called `name`.
    pub fn get(&self, name: &str) -> Option<&Fact> {
        self.0.iter().find(|(n, _)| *n == name).map(|(_, f)| f)
    }

    /// A count called `name`.
    pub fn count(&self, name: &str) -> Option<usize> {
        match self.get(name) {
            Some(Fact::Count(n)) => Some(*n),
            _ => None,
        }
    }
}

impl Serialize for Facts {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (name, fact) in &self.0 {
            match fact {
                Fact::Count(n) => map.serialize_entry(name, n)?,
                Fact::Number(x) => map.serialize_entry(name, x)?,
                Fact::Text(t) => map.serialize_entry(name, t)?,
                Fact::Indices(v) => map.serialize_entry(name, v)?,
            }
        }
        map.end()
    }
}

/// What a mode makes: geometry in millimetres, and what is known about it.
///
/// A mode fills what it makes and leaves the rest empty: the vector brush
/// fills `region_mm`, `fill_mm` and `mesh_mm`; a raster brush fills `image`.
#[derive(Clone, Debug, Default)]
pub struct Product {
    /// The pattern as planar regions (polygons with holes), mm, `y` up.
    pub region_mm: Region,
    /// `region_mm` as triangles, for drawing it filled.
    pub fill_mm: Vec<[DVec2; 3]>,
    /// Stroked paths, mm.
    pub paths_mm: Vec<StrokedPath>,
    /// Shapes drawn filled beside the stroked paths (a fill's discrete
    /// elements), mm; also in `region_mm` when it is filled.
    pub filled_mm: Region,
    /// A printable solid, mm, `z` up.
    pub mesh_mm: Option<Mesh>,
    /// A picture laid in the plane.
    pub image: Option<RasterImage>,
    /// Textured triangles in the plane (the raster brush's result as drawn).
    pub textured_mm: Option<TexturedMesh>,
    /// Where an open pattern starts and ends: each end's point and the
    /// direction pointing away from the pattern, mm (empty on loops).
    pub path_ends_mm: Vec<[DVec2; 2]>,
    /// Drawn over the result on the canvas.
    pub overlays: Overlays,
    /// Topology counted on the final geometry, independently of the planner.
    pub topology: PatternTopology,
    /// What the person should know.
    pub warnings: Vec<Warning>,
    /// Time per stage.
    pub timings: Timings,
    /// Mode-specific figures for reports.
    pub facts: Facts,
    /// What a nozzle can print of it, once checked ([`crate::print::finish`]).
    pub printability: Option<crate::print::Printability>,
}
