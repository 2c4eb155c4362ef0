//! [`GuidanceField`]: the direction the swatch's `u` axis follows over a
//! curved base (the paper's vector field, section 3.1), one tangent per
//! base face: around the `z` axis by default, or interpolated from strokes
//! a person drew on the model.

use glam::DVec3;

use super::{Direction, QuiltError};
use crate::geom::Rect;
use crate::surface::SurfaceMesh;

/// Strokes nearer a face than this, as a fraction of the model's size,
/// count fully; farther, their weight falls off with the square of the
/// distance. Keeps a face lying on a stroke from taking that stroke alone
/// while a neighbour a hair away blends in others.
const NEAR_FRACTION: f64 = 0.02;

/// A straight cap takes in faces facing within this many degrees of the
/// axis (see [`GuidanceField::with_straight_caps`]).
pub const CAP_FACING_DEG: f64 = 30.0;

/// A straight cap grows across edges whose faces' normals differ by less
/// than this many degrees, and so stops at a crease such as a flat top's rim.
pub const CAP_SMOOTH_DEG: f64 = 15.0;

/// The most stroke points a field may have: each face weighs every segment.
pub const MAX_FIELD_POINTS: usize = 20_000;

/// A unit tangent per base face.
#[derive(Clone, Debug, PartialEq)]
pub struct GuidanceField {
    directions: Vec<DVec3>,
    /// Made round or up the `z` axis (not from strokes): singular where a
    /// face looks along the axis, see [`GuidanceField::with_straight_caps`].
    about_axis: bool,
    /// Faces on a straight cap (empty when there is none).
    caps: Vec<bool>,
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
        GuidanceField { directions, about_axis: true, caps: Vec::new() }
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
        GuidanceField { directions, about_axis: true, caps: Vec::new() }
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
        Ok(GuidanceField { directions, about_axis: false, caps: Vec::new() })
    }

    /// This field with the caps round the axis made straight. A cap grows
    /// from the faces where the circle round the `z` axis turns tighter
    /// than `turn_radius_mm` within the surface (its geodesic curvature,
    /// `|n_z| / r` for a face at distance `r` from the axis with normal `n`,
    /// is over `1 / turn_radius_mm`) to the faces joined to them across
    /// smooth edges (normals within [`CAP_SMOOTH_DEG`]) that still face
    /// along the axis (within [`CAP_FACING_DEG`]). A cap whose edge is a
    /// crease all round (a flat top's rim) and that is at least
    /// `least_across_mm` across is kept, and its faces take the `x` axis
    /// instead.
    ///
    /// Why: round a pole or across a flat top the circles shrink to a point,
    /// and the swatch's straight rows cannot follow circles much tighter than
    /// the swatch is wide; a weave there came out curled and tangled. The
    /// rows across such a cap now lie straight, as on a plane. A straight
    /// cap cannot meet rows going round without a seam (a field round a
    /// disk's edge turns once), so the cap reaches out to a crease, the rim
    /// of a flat top, and hides the seam there. Round a smooth pole (a
    /// sphere's) no crease hides it, and the field is left round.
    /// Fields drawn from strokes are left as they are: they say what the
    /// person wants.
    ///
    /// ```
    /// use tracery_core::mesh_quilt::GuidanceField;
    /// use tracery_core::surface::{SurfaceMesh, builtin_base};
    /// let cylinder = SurfaceMesh::new(builtin_base("cylinder").unwrap()).unwrap();
    /// let field = GuidanceField::around_axis(&cylinder).with_straight_caps(&cylinder, 20.0, 20.0);
    /// // On the top 10 mm from the axis, the circle (1/10 mm⁻¹) turns too
    /// // tightly: the row runs along x, not round (along y there).
    /// let middle = cylinder.closest_point([10.0, 0.0, 60.0]).face;
    /// assert!(field.direction(middle).x.abs() > 0.99);
    /// // 24 mm out the circle turns gently, but the top is one flat cap.
    /// let edge = cylinder.closest_point([24.0, 0.0, 60.0]).face;
    /// assert!(field.direction(edge).x.abs() > 0.99);
    /// // Past the rim, the side still goes round.
    /// let side = cylinder.closest_point([25.0, 0.0, 59.0]).face;
    /// assert!(field.direction(side).y.abs() > 0.99);
    /// // A sphere's pole has no crease round it: the rows still go round.
    /// let sphere = SurfaceMesh::new(builtin_base("sphere").unwrap()).unwrap();
    /// let near_pole = sphere.closest_point([3.0, 0.0, 60.0]).face;
    /// let field = GuidanceField::around_axis(&sphere).with_straight_caps(&sphere, 20.0, 20.0);
    /// assert!(!field.on_cap(near_pole) && field.direction(near_pole).y.abs() > 0.9);
    /// ```
    pub fn with_straight_caps(mut self, surface: &SurfaceMesh, turn_radius_mm: f64, least_across_mm: f64) -> Self {
        let triangles = surface.triangles();
        if !self.about_axis || self.directions.len() != triangles.len() {
            return self;
        }
        let (facing, smooth) = (CAP_FACING_DEG.to_radians().cos(), CAP_SMOOTH_DEG.to_radians().cos());
        let tight = |f: u32| {
            let centre = surface.point(f, [1.0 / 3.0; 3]);
            surface.face_normal(f).z.abs() * turn_radius_mm > centre.truncate().length()
        };
        let mut cap = vec![false; triangles.len()];
        let mut seen = vec![false; triangles.len()];
        for start in 0..triangles.len() as u32 {
            if seen[start as usize] || !tight(start) {
                continue;
            }
            // One cap: the faces joined to `start` smoothly that face along
            // the axis. It is kept only if creases bound it all round.
            seen[start as usize] = true;
            let (mut component, mut todo, mut creased) = (vec![start], vec![start], true);
            while let Some(f) = todo.pop() {
                let normal = surface.face_normal(f);
                let t = triangles[f as usize];
                for k in 0..3 {
                    for &g in surface.faces_on_edge(t[k], t[(k + 1) % 3]) {
                        let other = surface.face_normal(g);
                        if other.dot(normal) <= smooth {
                            continue;
                        }
                        if other.z.abs() <= facing {
                            creased = false;
                        } else if !seen[g as usize] {
                            seen[g as usize] = true;
                            component.push(g);
                            todo.push(g);
                        }
                    }
                }
            }
            // A cap narrower than the caller's least width (the swatch's,
            // for a swatch whose rows wrap over a rim) holds few whole
            // elements, and rows round it, wrapped over its rim, cover it
            // better.
            let across = Rect::from_points(
                component
                    .iter()
                    .flat_map(|&f| triangles[f as usize])
                    .map(|v| surface.positions()[v as usize].truncate()),
            )
            .map_or(0.0, |extent| extent.size().min_element());
            if creased && across >= least_across_mm {
                for f in component {
                    cap[f as usize] = true;
                }
            }
        }
        for (f, direction) in self.directions.iter_mut().enumerate() {
            if cap[f] {
                *direction = tangent(surface, f as u32, DVec3::X);
            }
        }
        self.caps = cap;
        self
    }

    /// The field on a surface split from this one's
    /// ([`SurfaceMesh::split_to`]): each new face, lying in the plane of
    /// the face it came from (`parents`), takes that face's direction.
    pub fn on_split_faces(&self, parents: &[u32]) -> GuidanceField {
        GuidanceField {
            directions: parents.iter().map(|&p| self.directions[p as usize]).collect(),
            about_axis: self.about_axis,
            caps: if self.caps.is_empty() {
                Vec::new()
            } else {
                parents.iter().map(|&p| self.caps[p as usize]).collect()
            },
        }
    }

    /// Whether face `f` lies on a straight cap
    /// ([`GuidanceField::with_straight_caps`]). Across a cap's edge the
    /// field jumps, so a patch keeps to the seed's side of it.
    pub fn on_cap(&self, f: u32) -> bool {
        self.caps.get(f as usize).copied().unwrap_or(false)
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
