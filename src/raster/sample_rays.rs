//! The view ray through each sample point of a pass, handed to shading with its fragments.

use super::view_rays::ViewRays;
use crate::camera::Camera;
use glam::{DVec2, DVec3, Vec3};

/// The direction through each sample point of one pass, camera-relative and scaled to unit
/// length along the view direction, in the pass's pixel coordinates (a band's own rows): a
/// fragment's point on its triangle is `fragment.depth · through(x, y)`, and the true surface
/// lies along the same ray. f32 for shading: directions stay within a few units, so steps of a
/// pixel across 2^13 pixels keep about 1e-7 relative accuracy. f64 (`exact_through`) for the
/// true hits, where 1e-7 of the distance to the eye moves a (u,v) by a few f32 steps, enough to
/// cross the rim of a bump whose slope is unbounded there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleRays {
    /// The direction through pixel (0, 0)'s sample point.
    first: Vec3,
    /// The same and the per-pixel steps, in f64.
    exact_first: DVec3,
    exact_per_pixel: [DVec3; 2],
    /// One pixel to the right and one pixel down, as changes of the direction.
    pub per_pixel_x: Vec3,
    pub per_pixel_y: Vec3,
    /// The camera's unit view direction: a point's depth is its dot product with this.
    pub forward: Vec3,
    /// The sample spacing in pixels, which scales texture footprints (`RenderTarget::footprint`).
    pub footprint: f32,
    /// The camera's near and far clip depths: where along the rays surfaces are seen.
    pub near: f32,
    pub far: f32,
}

impl SampleRays {
    /// The rays of a pass whose pixel (0, 0) is pixel (`x0`, `y0`) of the image `rays` sees
    /// through `camera`, each sampled `offset` pixels from its centre.
    pub fn new(
        rays: &ViewRays,
        camera: &Camera,
        (x0, y0): (u32, u32),
        offset: DVec2,
        footprint: f32,
    ) -> SampleRays {
        let shifted = rays.at_sample(offset, footprint as f64);
        let first = shifted.through_pixel(x0, y0);
        SampleRays {
            first: first.as_vec3(),
            exact_first: first,
            exact_per_pixel: [rays.per_pixel_x, rays.per_pixel_y],
            per_pixel_x: rays.per_pixel_x.as_vec3(),
            per_pixel_y: rays.per_pixel_y.as_vec3(),
            forward: rays.forward().as_vec3(),
            footprint,
            near: camera.near,
            far: camera.far,
        }
    }

    #[inline(always)]
    pub fn through(&self, x: u32, y: u32) -> Vec3 {
        self.first + self.per_pixel_x * x as f32 + self.per_pixel_y * y as f32
    }

    /// `through` in f64, as the reference casts its rays.
    #[inline(always)]
    pub fn exact_through(&self, x: u32, y: u32) -> DVec3 {
        let [per_x, per_y] = self.exact_per_pixel;
        self.exact_first + per_x * x as f64 + per_y * y as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::Viewport;
    use glam::DVec3;

    #[test]
    fn a_band_pixel_sees_the_full_image_ray() {
        let camera = Camera {
            eye: DVec3::new(3.0, 2.0, 9.0),
            target: DVec3::new(-1.0, 0.5, 0.0),
            up: Vec3::Y,
            vfov_degrees: 50.0,
            near: 0.1,
            far: 100.0,
        };
        let full = Viewport {
            width: 640,
            height: 360,
        };
        let rays = ViewRays::new(&camera, full);
        let offset = DVec2::new(0.25, -0.125);
        let band = SampleRays::new(&rays, &camera, (100, 64), offset, 1.0);
        let expected = rays.at_sample(offset, 1.0).through_pixel(100 + 37, 64 + 5);
        let seen = band.through(37, 5).as_dvec3();
        assert!((seen - expected).length() < 1e-6, "{seen} vs {expected}");
        let exact = band.exact_through(37, 5);
        assert!((exact - expected).length() < 1e-14, "{exact} vs {expected}");
        assert!((seen.dot(rays.forward()) - 1.0).abs() < 1e-6);
    }
}
