//! [`GuidanceField`]: the direction the swatch's `u` axis follows over a
//! curved base (the paper's vector field, section 3.1), one tangent per
//! base face: around the `z` axis by default, or interpolated from strokes
//! a person drew on the model.

use glam::DVec3;

use super::{Direction, QuiltError};
use crate::surface::SurfaceMesh;

/// Strokes nearer a face than this, as a fraction of the model's size,
/// count fully; farther, their weight falls off with the square of the
/// distance. Keeps a face lying on a stroke from taking that stroke alone
/// while a neighbour a hair away blends in others.
const NEAR_FRACTION: f64 = 0.02;

/// The most stroke points a field may have: each face weighs every segment.
pub const MAX_FIELD_POINTS: usize = 20_000;

/// A unit tangent per base face.
#[derive(Clone, Debug, PartialEq)]
pub struct GuidanceField {
    directions: Vec<DVec3>,
}

/// `v` in the plane of face `f`, unit length; any tangent where that vanishes.
fn tangent(surface: &SurfaceMesh, f: u32, v: DVec3) -> DVec3 {
    let normal = surface.face_normal(f);
    (v - normal * v.dot(normal)).try_normalize().unwrap_or_else(|| normal.any_orthonormal_vector())
}

impl GuidanceField {
    /// Around the `z` axis (the axis a lathe-turned vase or cup stands on),
    /// in each face's plane.
    pub fn around_axis(surface: &SurfaceMesh) -> Self {
        let directions = (0..surface.triangles().len() as u32)
            .map(|f| tangent(surface, f, DVec3::Z.cross(surface.point(f, [1.0 / 3.0; 3]))))
            .collect();
        GuidanceField { directions }
    }

    /// Up the model (the `z` axis), in each face's plane: meridians on a
    /// vase; any tangent on faces facing straight up or down.
    ///
    /// ```
    /// use tracery_core::mesh_quilt::GuidanceField;
    /// use tracery_core::surface::{SurfaceMesh, builtin_base};
    /// let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
    /// let f = cylinder.closest_point([25.0, 0.0, 30.0]).face;
    /// assert!(GuidanceField::along_axis(&cylinder).direction(f).z > 0.99);
    /// assert!(GuidanceField::around_axis(&cylinder).direction(f).z.abs() < 0.01);
    /// ```
    pub fn along_axis(surface: &SurfaceMesh) -> Self {
        let directions = (0..surface.triangles().len() as u32).map(|f| tangent(surface, f, DVec3::Z)).collect();
        GuidanceField { directions }
    }

    /// The field `direction` names; `strokes_mm` are the strokes
    /// [`Direction::AlongCurves`] follows (the others leave them alone).
    /// Following curves where none is drawn is an error that says so.
    ///
    /// ```
    /// use tracery_core::mesh_quilt::{Direction, GuidanceField};
    /// use tracery_core::surface::{SurfaceMesh, builtin_base};
    /// let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
    /// assert!(GuidanceField::of(&cylinder, Direction::AroundAxis, &[]).is_ok());
    /// let err = GuidanceField::of(&cylinder, Direction::AlongCurves, &[]).unwrap_err();
    /// assert!(err.to_string().contains("no curve"), "{err}");
    /// ```
    pub fn of(surface: &SurfaceMesh, direction: Direction, strokes_mm: &[Vec<[f64; 3]>]) -> Result<Self, QuiltError> {
        match direction {
            Direction::AroundAxis => Ok(Self::around_axis(surface)),
            Direction::AlongAxis => Ok(Self::along_axis(surface)),
            Direction::AlongCurves if strokes_mm.is_empty() => Err(QuiltError::BadField(
                "there is no curve on the model for the texture to follow: draw one, or let it run around or up".into(),
            )),
            Direction::AlongCurves => Self::from_strokes(surface, strokes_mm),
        }
    }

    /// Interpolated from `strokes_mm` (each at least two points, drawn on
    /// or near the model, in the direction the swatch's `u` axis should
    /// run): each face takes the segments' directions weighted by
    /// 1 / (distance² + (2 % of the model's size)²), projected into its
    /// plane. Distances are straight, not along the surface.
    ///
    /// ```
    /// use tracery_core::mesh_quilt::GuidanceField;
    /// use tracery_core::surface::{SurfaceMesh, builtin_base};
    /// let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
    /// // One stroke up the side: every face of the side follows it.
    /// let up = GuidanceField::from_strokes(&cylinder, &[vec![[30.0, 0.0, 5.0], [30.0, 0.0, 40.0]]]).unwrap();
    /// let f = cylinder.closest_point([-30.0, 0.0, 20.0]).face;
    /// assert!(up.direction(f).z > 0.99);
    /// assert!(GuidanceField::from_strokes(&cylinder, &[vec![[0.0, 0.0, 0.0]]]).is_err());
    /// ```
    pub fn from_strokes(surface: &SurfaceMesh, strokes_mm: &[Vec<[f64; 3]>]) -> Result<Self, QuiltError> {
        let points: usize = strokes_mm.iter().map(Vec::len).sum();
        if points > MAX_FIELD_POINTS {
            return Err(QuiltError::BadField(format!(
                "it has {points} points, and at most {MAX_FIELD_POINTS} are allowed"
            )));
        }
        let mut segments: Vec<(DVec3, DVec3)> = Vec::new();
        for (k, stroke) in strokes_mm.iter().enumerate() {
            let before = segments.len();
            for pair in stroke.windows(2) {
                let (a, b) = (DVec3::from(pair[0]), DVec3::from(pair[1]));
                if a.is_finite() && b.is_finite() && a.distance(b) > 0.0 {
                    segments.push((a, b));
                }
            }
            if segments.len() == before {
                return Err(QuiltError::BadField(format!(
                    "stroke {} needs at least two distinct points to have a direction",
                    k + 1
                )));
            }
        }
        if segments.is_empty() {
            return Err(QuiltError::BadField("it has no strokes".into()));
        }
        let soft = (NEAR_FRACTION * surface.size_mm()).powi(2);
        let directions = (0..surface.triangles().len() as u32)
            .map(|f| {
                let centre = surface.point(f, [1.0 / 3.0; 3]);
                let blended: DVec3 = segments
                    .iter()
                    .map(|&(a, b)| {
                        let along = b - a;
                        let t = ((centre - a).dot(along) / along.length_squared()).clamp(0.0, 1.0);
                        let d2 = centre.distance_squared(a + along * t);
                        along.normalize() / (d2 + soft)
                    })
                    .sum();
                tangent(surface, f, blended)
            })
            .collect();
        Ok(GuidanceField { directions })
    }

    /// The field over face `f`: a unit tangent.
    pub fn direction(&self, f: u32) -> DVec3 {
        self.directions[f as usize]
    }

    /// Faces it covers (the base's triangles).
    pub fn len(&self) -> usize {
        self.directions.len()
    }

    /// Whether it covers no face.
    pub fn is_empty(&self) -> bool {
        self.directions.is_empty()
    }
}

/// Reads strokes from text: one stroke per line, its points as
/// `x,y,z;x,y,z;...` (mm, the format of `tracery surface --points`); blank
/// lines and lines starting with `#` are skipped.
///
/// ```
/// use tracery_core::mesh_quilt::parse_strokes;
/// let strokes = parse_strokes("# up the side\n30,0,5; 30,0,40\n\n0,30,5;0,30,40\n").unwrap();
/// assert_eq!(strokes.len(), 2);
/// assert!(parse_strokes("30,0\n").is_err());
/// ```
pub fn parse_strokes(text: &str) -> Result<Vec<Vec<[f64; 3]>>, QuiltError> {
    text.lines()
        .enumerate()
        .map(|(k, line)| (k, line.trim()))
        .filter(|(_, line)| !line.is_empty() && !line.starts_with('#'))
        .map(|(k, line)| {
            crate::surface::SurfaceSettings::parse_points(line)
                .map_err(|e| QuiltError::BadField(format!("line {}: {e}", k + 1)))
        })
        .collect()
}
