//! The 3D view's camera: an orbit about a target, with pan and zoom, and
//! the ray under a screen point for picking.

use glam::{Mat4, Vec2, Vec3, Vec4Swizzles};
use serde::{Deserialize, Serialize};

use super::view_mesh::Bounds;

/// Vertical field of view, radians.
const FOV_Y: f32 = 0.6;
/// Pitch stays short of straight up or down, where `look_at` with z up has no sideways direction.
const MAX_PITCH: f32 = 1.55;
/// Radians turned per point dragged.
const TURN_PER_POINT: f32 = 0.01;

/// Where the 3D view looks from. `z` is up, as in the models.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Orbit {
    /// Rotation about the vertical axis, radians.
    pub yaw: f32,
    /// Elevation above the horizontal, radians.
    pub pitch: f32,
    /// Zoom factor: 1 frames the whole scene.
    pub zoom: f32,
    /// The target's offset from the scene's centre, mm.
    pub pan_mm: [f32; 3],
}

impl Default for Orbit {
    fn default() -> Self {
        Orbit { yaw: 0.6, pitch: 0.45, zoom: 1.0, pan_mm: [0.0; 3] }
    }
}

/// The camera of one frame: the matrices for a scene's bounds and a view's shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// World (mm) to clip space, depth 0 to 1 as wgpu has it.
    pub clip_from_world: Mat4,
    /// The eye, mm.
    pub eye_mm: Vec3,
    /// The point looked at, mm.
    pub target_mm: Vec3,
    /// Distance from eye to target, mm.
    pub distance_mm: f32,
}

impl Orbit {
    /// The camera framing `bounds` in a view `aspect` wide per unit high.
    pub fn camera(&self, bounds: &Bounds, aspect: f32) -> Camera {
        let radius = bounds.radius().max(1e-3);
        let target = bounds.centre() + Vec3::from(self.pan_mm);
        // The distance at which a sphere of `radius` fills the narrower side.
        let fit = radius / (FOV_Y / 2.0).tan().min((FOV_Y / 2.0).tan() * aspect.max(1e-3));
        let distance = fit * 1.1 / self.zoom.max(1e-3);
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.clamp(-MAX_PITCH, MAX_PITCH).sin_cos();
        let eye = target + distance * Vec3::new(sy * cp, -cy * cp, sp);
        // Near and far hug the scene so that depth keeps its precision.
        let reach = radius + Vec3::from(self.pan_mm).length();
        let near = (distance - reach).max(distance * 0.01);
        let far = distance + reach * 1.01 + 1e-3;
        let view = glam::camera::rh::view::look_at_mat4(eye, target, Vec3::Z);
        // wgpu's clip space is Direct3D's: depth 0 to 1, y up.
        let projection = glam::camera::rh::proj::directx::perspective(FOV_Y, aspect.max(1e-3), near, far);
        Camera { clip_from_world: projection * view, eye_mm: eye, target_mm: target, distance_mm: distance }
    }

    /// Turns the camera by a drag of `delta` points.
    pub fn turn(&mut self, delta: Vec2) {
        self.yaw -= delta.x * TURN_PER_POINT;
        self.pitch = (self.pitch + delta.y * TURN_PER_POINT).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// Moves the target so the scene follows a drag of `delta` points in a
    /// view `height` points high.
    pub fn pan(&mut self, camera: &Camera, delta: Vec2, height: f32) {
        let mm_per_point = 2.0 * camera.distance_mm * (FOV_Y / 2.0).tan() / height.max(1.0);
        let forward = (camera.target_mm - camera.eye_mm).normalize_or_zero();
        let right = forward.cross(Vec3::Z).normalize_or_zero();
        let up = right.cross(forward);
        let moved = (-delta.x * right + delta.y * up) * mm_per_point;
        self.pan_mm = (Vec3::from(self.pan_mm) + moved).into();
    }

    /// Zooms by `factor` (above 1: closer).
    pub fn zoom_by(&mut self, factor: f32) {
        self.zoom = (self.zoom * factor).clamp(0.1, 50.0);
    }
}

impl Camera {
    /// The ray under a point of the view, with `ndc` in -1..1 (y up):
    /// its origin on the near plane, and its unit direction.
    pub fn ray(&self, ndc: Vec2) -> (Vec3, Vec3) {
        let world_from_clip = self.clip_from_world.inverse();
        let near = world_from_clip * ndc.extend(0.0).extend(1.0);
        let far = world_from_clip * ndc.extend(1.0).extend(1.0);
        let near = near.xyz() / near.w;
        let far = far.xyz() / far.w;
        (near, (far - near).normalize_or_zero())
    }

    /// Where a world point lands in normalized device coordinates (y up),
    /// with its depth 0 (near) to 1 (far).
    pub fn project(&self, p_mm: Vec3) -> Vec3 {
        self.clip_from_world.project_point3(p_mm)
    }

    /// The direction the key light comes from: above and to the left of the eye.
    pub fn light_dir(&self) -> Vec3 {
        let forward = (self.target_mm - self.eye_mm).normalize_or_zero();
        let right = forward.cross(Vec3::Z).normalize_or_zero();
        let up = right.cross(forward);
        (-0.45 * right + 0.65 * up - 0.6 * forward).normalize_or_zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box() -> Bounds {
        Bounds { min: Vec3::splat(-10.0), max: Vec3::splat(10.0) }
    }

    #[test]
    fn the_ray_through_the_centre_hits_the_target() {
        let camera = Orbit::default().camera(&unit_box(), 1.5);
        let (origin, dir) = camera.ray(Vec2::ZERO);
        // The closest approach of the ray to the target.
        let to_target = camera.target_mm - origin;
        let miss = (to_target - dir * to_target.dot(dir)).length();
        assert!(miss < 1e-3, "the centre ray misses the target by {miss} mm");
    }

    #[test]
    fn a_projected_point_is_picked_back() {
        let orbit = Orbit { yaw: -1.1, pitch: 0.3, zoom: 2.0, pan_mm: [3.0, -2.0, 1.0] };
        let camera = orbit.camera(&unit_box(), 0.8);
        let p = Vec3::new(4.0, -3.0, 7.0);
        let ndc = camera.project(p);
        let (origin, dir) = camera.ray(ndc.truncate());
        let miss = ((p - origin) - dir * (p - origin).dot(dir)).length();
        assert!(miss < 1e-3, "a point projected and cast back is missed by {miss} mm");
        assert!((0.0..1.0).contains(&ndc.z), "the point lies outside the depth range: {}", ndc.z);
    }

    #[test]
    fn the_whole_scene_is_in_view_and_depth() {
        let camera = Orbit::default().camera(&unit_box(), 2.0);
        for corner in 0..8 {
            let p = Vec3::new(
                if corner & 1 == 0 { -10.0 } else { 10.0 },
                if corner & 2 == 0 { -10.0 } else { 10.0 },
                if corner & 4 == 0 { -10.0 } else { 10.0 },
            );
            let ndc = camera.project(p);
            assert!(ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0, "corner {p} is off screen at {ndc}");
            assert!((0.0..=1.0).contains(&ndc.z), "corner {p} is clipped by depth: {}", ndc.z);
        }
    }

    #[test]
    fn panning_moves_the_scene_with_the_pointer() {
        let mut orbit = Orbit::default();
        let camera = orbit.camera(&unit_box(), 1.0);
        let before = camera.project(Vec3::ZERO);
        orbit.pan(&camera, Vec2::new(50.0, 0.0), 500.0);
        let after = orbit.camera(&unit_box(), 1.0).project(Vec3::ZERO);
        // Dragged right by a tenth of the height: the centre moves right by a fifth of the half-width.
        assert!((after.x - before.x - 0.2).abs() < 0.02, "moved {} in x", after.x - before.x);
        assert!((after.y - before.y).abs() < 0.02, "moved {} in y", after.y - before.y);
    }
}
