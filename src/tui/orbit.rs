//! The camera as an orbit around its target: yaw and pitch about the world up axis, a distance,
//! and a target that pans in the view plane.

use crate::scene::Camera;
use glam::{DVec3, Vec3};

/// Pitch stays short of the poles, where yaw would lose its meaning and the view would flip.
const MAX_PITCH: f64 = 89.0_f64.to_radians();

#[derive(Clone, Debug, PartialEq)]
pub struct Orbit {
    pub target: DVec3,
    pub distance: f64,
    /// Radians about +y, 0 looking along −z.
    pub yaw: f64,
    /// Radians above the horizon.
    pub pitch: f64,
    /// The lens and clip planes of the scene's camera.
    lens: Camera,
}

impl Orbit {
    pub fn from_camera(camera: &Camera) -> Orbit {
        let offset = camera.eye - camera.target;
        let distance = offset.length().max(1e-6);
        Orbit {
            target: camera.target,
            distance,
            yaw: offset.x.atan2(offset.z),
            pitch: (offset.y / distance).clamp(-1.0, 1.0).asin(),
            lens: camera.clone(),
        }
    }

    pub fn camera(&self) -> Camera {
        let (sin_yaw, cos_yaw) = self.yaw.sin_cos();
        let (sin_pitch, cos_pitch) = self.pitch.sin_cos();
        let direction = DVec3::new(sin_yaw * cos_pitch, sin_pitch, cos_yaw * cos_pitch);
        Camera {
            eye: self.target + direction * self.distance,
            target: self.target,
            up: Vec3::Y,
            ..self.lens.clone()
        }
    }

    pub fn rotate(&mut self, yaw_degrees: f64, pitch_degrees: f64) {
        self.yaw = (self.yaw + yaw_degrees.to_radians()).rem_euclid(std::f64::consts::TAU);
        self.pitch = (self.pitch + pitch_degrees.to_radians()).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// Moves eye and target together by fractions of the distance, along the view's right and up.
    pub fn pan(&mut self, right: f64, up: f64) {
        let camera = self.camera();
        let forward = (camera.target - camera.eye).normalize_or(DVec3::NEG_Z);
        let right_axis = forward.cross(DVec3::Y).normalize_or(DVec3::X);
        let up_axis = right_axis.cross(forward);
        self.target += (right_axis * right + up_axis * up) * self.distance;
    }

    /// Multiplies the distance by `factor`, keeping the eye between the near and far planes'
    /// reach of the target.
    pub fn zoom(&mut self, factor: f64) {
        let near = self.lens.near as f64 * 2.0;
        let far = (self.lens.far as f64 * 0.5).max(near);
        self.distance = (self.distance * factor).clamp(near, far);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera {
            eye: DVec3::new(0.0, 260.0, 620.0),
            target: DVec3::new(0.0, 70.0, 0.0),
            up: Vec3::Y,
            vfov_degrees: 40.0,
            near: 1.0,
            far: 10000.0,
        }
    }

    #[test]
    fn round_trips_the_scene_camera() {
        let back = Orbit::from_camera(&camera()).camera();
        assert!((back.eye - camera().eye).length() < 1e-9, "{back:?}");
    }

    #[test]
    fn rotating_keeps_the_distance_and_stops_short_of_the_pole() {
        let mut orbit = Orbit::from_camera(&camera());
        let distance = orbit.distance;
        orbit.rotate(33.0, 500.0);
        let c = orbit.camera();
        assert!(((c.eye - c.target).length() - distance).abs() < 1e-9);
        assert!(orbit.pitch <= MAX_PITCH);
    }

    #[test]
    fn zoom_and_pan_stay_finite() {
        let mut orbit = Orbit::from_camera(&camera());
        orbit.zoom(1e-9);
        assert!(orbit.distance >= 2.0);
        orbit.zoom(1e12);
        assert!(orbit.distance <= 5000.0);
        orbit.pan(0.1, -0.1);
        assert!(orbit.camera().eye.is_finite());
    }
}
