//! The camera's rays through pixel centres, built exactly as the rasterizer's frustum.

use super::setup::Viewport;
use crate::camera::Camera;
use crate::surface::normalize_or;
use glam::{DVec3, Vec3};

/// The camera's rays through pixel centres, in camera-relative world space, built exactly as
/// `Camera::view_projection` builds its frustum (the same up fallback, field-of-view clamp and
/// aspect), so the reference sees the very frame the rasterizer draws.
/// Directions are scaled to unit length along the view direction: t along them is view depth.
#[derive(Clone, Copy, Debug)]
pub struct ViewRays {
    forward: DVec3,
    /// One pixel to the right and one pixel down, as changes of the scaled direction.
    pub per_pixel_x: DVec3,
    pub per_pixel_y: DVec3,
    /// The direction through the image's top-left corner (shifted with the sample offset).
    top_left: DVec3,
    /// Scales the per-pixel steps used for texture footprints: 1 at one sample per pixel, the
    /// sample spacing when supersampling (as `RenderTarget::footprint` does for the rasterizer).
    pub footprint: f64,
}

impl ViewRays {
    pub fn new(camera: &Camera, viewport: Viewport) -> ViewRays {
        let forward = camera.forward();
        let up = normalize_or(camera.up, Vec3::Y);
        let up = if forward.cross(up).length_squared() < 1e-12 {
            forward.any_orthonormal_vector()
        } else {
            up
        };
        let right = forward.cross(up).normalize().as_dvec3();
        let up = right.cross(forward.as_dvec3());
        let half_h = (camera.vfov_degrees.clamp(1e-3, 179.0).to_radians() as f64 / 2.0).tan();
        let half_w = half_h * viewport.aspect() as f64;
        let per_pixel_x = right * (2.0 * half_w / viewport.width.max(1) as f64);
        let per_pixel_y = -up * (2.0 * half_h / viewport.height.max(1) as f64);
        ViewRays {
            forward: forward.as_dvec3(),
            per_pixel_x,
            per_pixel_y,
            top_left: forward.as_dvec3() - right * half_w + up * half_h,
            footprint: 1.0,
        }
    }

    /// The rays through each pixel's centre moved by `offset` pixels (right, down), with texture
    /// footprints scaled by `footprint`: one pass of a supersampled reference.
    pub fn at_sample(self, offset: glam::DVec2, footprint: f64) -> ViewRays {
        ViewRays {
            top_left: self.top_left + self.per_pixel_x * offset.x + self.per_pixel_y * offset.y,
            footprint,
            ..self
        }
    }

    /// The direction through pixel (x, y)'s centre.
    pub fn through_pixel(&self, x: u32, y: u32) -> DVec3 {
        self.top_left + self.per_pixel_x * (x as f64 + 0.5) + self.per_pixel_y * (y as f64 + 0.5)
    }

    pub fn forward(&self) -> DVec3 {
        self.forward
    }
}
