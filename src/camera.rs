//! The camera: a look-at pinhole with its eye in f64, and its view-projection matrix.

use glam::{DVec3, Mat4, Vec3};

/// A look-at pinhole camera with a vertical field of view. The eye is kept in f64; everything
/// the rasterizer sees is relative to it, so a scene far from the origin keeps its precision.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub eye: DVec3,
    pub target: DVec3,
    pub up: Vec3,
    pub vfov_degrees: f32,
    /// Near and far clip distances along the view direction, 0 < near < far.
    pub near: f32,
    pub far: f32,
}

impl Camera {
    /// The unit view direction, guarded against eye == target.
    pub fn forward(&self) -> Vec3 {
        let d = (self.target - self.eye).as_vec3();
        crate::surface::normalize_or(d, -Vec3::Z)
    }

    /// Maps camera-relative world positions (eye at the origin, world axes) to clip space with
    /// depth in [0, w] (z = 0 at the near plane) and w = distance along the view direction.
    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        let forward = self.forward();
        let up = crate::surface::normalize_or(self.up, Vec3::Y);
        let up = if forward.cross(up).length_squared() < 1e-12 {
            forward.any_orthonormal_vector()
        } else {
            up
        };
        let view = glam::camera::rh::view::look_to_mat4(Vec3::ZERO, forward, up);
        let fov = self.vfov_degrees.clamp(1e-3, 179.0).to_radians();
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        glam::camera::rh::proj::directx::perspective(fov, aspect, self.near, self.far) * view
    }

    /// The camera-relative direction of the ray through a point of the image, in pixels from the
    /// top-left corner of a `width` × `height` image. For reference ray casting in tests.
    pub fn ray_direction(&self, width: u32, height: u32, x: f64, y: f64) -> DVec3 {
        let forward = self.forward().as_dvec3();
        let right = forward.cross(self.up.as_dvec3()).normalize();
        let up = right.cross(forward);
        let half_h = (self.vfov_degrees.to_radians() as f64 / 2.0).tan();
        let half_w = half_h * width as f64 / height as f64;
        let sx = (2.0 * x / width as f64 - 1.0) * half_w;
        let sy = (1.0 - 2.0 * y / height as f64) * half_h;
        (forward + right * sx + up * sy).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec4;

    #[test]
    fn projects_the_target_to_the_centre_and_near_to_depth_zero() {
        let cam = Camera {
            eye: DVec3::new(1e6, 5.0, 1e6),
            target: DVec3::new(1e6, 5.0, 1e6 - 10.0),
            up: Vec3::Y,
            vfov_degrees: 60.0,
            near: 0.5,
            far: 100.0,
        };
        let vp = cam.view_projection(2.0);
        let c = vp * Vec4::new(0.0, 0.0, -10.0, 1.0);
        assert!(c.x.abs() < 1e-5 && c.y.abs() < 1e-5 && (c.w - 10.0).abs() < 1e-4);
        let n = vp * Vec4::new(0.0, 0.0, -0.5, 1.0);
        assert!(n.z.abs() < 1e-5, "{n:?}");
    }

    #[test]
    fn looking_straight_up_still_gives_a_finite_matrix() {
        let cam = Camera {
            eye: DVec3::ZERO,
            target: DVec3::Y,
            up: Vec3::Y,
            vfov_degrees: 40.0,
            near: 0.1,
            far: 10.0,
        };
        assert!(cam.view_projection(1.0).is_finite());
    }
}
