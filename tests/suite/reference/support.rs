//! Helpers shared by the reference renderer's tests: render a scene both ways, compare.
#![allow(dead_code)]

use crate::common::render_with;
use bumpwork::raster::{Framebuffer, RenderTarget, Viewport};
use bumpwork::reference::{FrameError, ShadedAndNormals, render_reference};
use bumpwork::scene::Camera;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::Scene;
use bumpwork::shade::LitShader;
use bumpwork::surface::Tessellation;

pub const SMALL: Viewport = Viewport {
    width: 64,
    height: 48,
};

/// A scene's frame both ways with the same shader: (raster, reference).
pub struct FramePair {
    pub raster: Framebuffer,
    pub reference: Framebuffer,
}

pub fn render_both(
    scene: &Scene,
    viewport: Viewport,
    density: u32,
    configure: impl Fn(&mut LitShader),
) -> FramePair {
    let prepared = PreparedScene::new(scene.clone(), Tessellation { density });
    let camera = &scene.camera;
    let mut shader = LitShader::new(scene, camera);
    configure(&mut shader);
    let target = RenderTarget::new(camera, viewport);
    FramePair {
        raster: render_with(&prepared, &target, &shader).0,
        reference: render_reference(&prepared, camera, viewport, &shader).0,
    }
}

/// Every error figure of the rasterizer against the reference, at a tessellation density.
pub fn raster_error(scene: &Scene, viewport: Viewport, density: u32) -> FrameError {
    let prepared = PreparedScene::new(scene.clone(), Tessellation { density });
    let camera = &scene.camera;
    let mut shader = LitShader::new(scene, camera);
    let target = RenderTarget::new(camera, viewport);
    let raster = ShadedAndNormals::render(&mut shader, |s| render_with(&prepared, &target, s).0);
    let reference = ShadedAndNormals::render(&mut shader, |s| {
        render_reference(&prepared, camera, viewport, s).0
    });
    raster.error_against(&reference)
}

pub fn assert_all_finite(fb: &Framebuffer, what: &str) {
    for (i, c) in fb.color().iter().enumerate() {
        assert!(c.is_finite(), "{what}: NaN or infinity at pixel {i}: {c:?}");
    }
    for (i, d) in fb.depth().iter().enumerate() {
        assert!(
            d.is_finite() || *d == f32::INFINITY,
            "{what}: bad depth {d} at pixel {i}"
        );
    }
}

pub fn covered(fb: &Framebuffer) -> usize {
    fb.depth().iter().filter(|d| d.is_finite()).count()
}

pub fn camera(eye: [f64; 3], target: [f64; 3], fov: f32) -> Camera {
    Camera {
        eye: eye.into(),
        target: target.into(),
        up: glam::Vec3::Y,
        vfov_degrees: fov,
        near: 0.01,
        far: 1e5,
    }
}

/// A small deterministic generator, so failures reproduce.
pub struct XorShift(pub u64);

impl XorShift {
    pub fn next_f64(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }

    pub fn unit_vector(&mut self) -> glam::DVec3 {
        loop {
            let v = glam::DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            let len = v.length();
            if len > 0.1 && len <= 1.0 {
                return v / len;
            }
        }
    }
}

/// The exact reference's frame of `scene` at `view`: exact surfaces, exact shadow rays.
pub fn exact_frame(scene: &Scene, view: Viewport) -> Framebuffer {
    let prepared = PreparedScene::new(scene.clone(), Tessellation { density: 4 });
    let shader: LitShader = bumpwork::reference::exact_shader(&prepared, &scene.camera, 0.0);
    render_reference(&prepared, &scene.camera, view, &shader).0
}
