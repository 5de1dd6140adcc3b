//! Helpers shared by the integration tests.
#![allow(dead_code)]

use bumpwork::raster::{
    ClipVertex, Fragment, Framebuffer, Interpolation, PixelRect, RenderTarget, SampleShift,
    ScreenTriangle, ShiftSpan, TrianglePlanes, Viewport, scan_shifted,
};
use bumpwork::scene::Camera;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::Scene;
use bumpwork::shade::{FrameObject, PerFragment};
use bumpwork::surface::Tessellation;
use glam::{Vec2, Vec3, Vec4};

/// A vertex at pixel position (x, y) of the viewport, at w = 1.
pub fn at_pixel(viewport: Viewport, x: f64, y: f64) -> ClipVertex {
    let ndc_x = x / viewport.width as f64 * 2.0 - 1.0;
    let ndc_y = 1.0 - y / viewport.height as f64 * 2.0;
    ClipVertex {
        position: Vec4::new(ndc_x as f32, ndc_y as f32, 0.5, 1.0),
        uv: Vec2::ZERO,
    }
}

pub fn screen_triangle(viewport: Viewport, corners: [(f64, f64); 3]) -> Option<ScreenTriangle> {
    shifted_screen_triangle(viewport, corners, &ShiftSpan::NONE)
}

/// A screen triangle set up for passes whose sample points are shifted within `span`.
pub fn shifted_screen_triangle(
    viewport: Viewport,
    corners: [(f64, f64); 3],
    span: &ShiftSpan,
) -> Option<ScreenTriangle> {
    let vertices = corners.map(|(x, y)| at_pixel(viewport, x, y));
    let planes = TrianglePlanes::new(&vertices, viewport, Interpolation::PerspectiveCorrect)?;
    ScreenTriangle::new(vertices, viewport, &planes, 0, span)
}

/// How many of the triangles cover each pixel centre, ignoring depth.
pub fn coverage(viewport: Viewport, triangles: &[ScreenTriangle]) -> Vec<u32> {
    shifted_coverage(viewport, triangles, &SampleShift::NONE)
}

/// How many of the triangles cover each pixel's sample point moved by `shift`.
pub fn shifted_coverage(
    viewport: Viewport,
    triangles: &[ScreenTriangle],
    shift: &SampleShift,
) -> Vec<u32> {
    let mut count = vec![0u32; (viewport.width * viewport.height) as usize];
    let all = PixelRect {
        x0: 0,
        y0: 0,
        x1: viewport.width - 1,
        y1: viewport.height - 1,
    };
    for t in triangles {
        scan_shifted(t, &all, shift, |x, y| {
            count[(y * viewport.width + x) as usize] += 1
        });
    }
    count
}

/// Writes each fragment's (u, v, object) into the colour channels.
pub fn uv_shader() -> PerFragment<impl Fn(&FrameObject, &Fragment) -> Vec3 + Sync> {
    PerFragment(|_: &FrameObject, f: &Fragment| Vec3::new(f.uv.x, f.uv.y, f.object as f32))
}

pub fn render_uv(
    scene: Scene,
    viewport: Viewport,
    interpolation: Interpolation,
    density: u32,
) -> Framebuffer {
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation { density });
    let target = RenderTarget::new(&camera, viewport).with_interpolation(interpolation);
    render_with(&prepared, &target, &uv_shader()).0
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
}

pub fn camera(eye: [f64; 3], target: [f64; 3], fov: f32) -> Camera {
    Camera {
        eye: eye.into(),
        target: target.into(),
        up: Vec3::Y,
        vfov_degrees: fov,
        near: 0.01,
        far: 1e5,
    }
}

pub use bumpwork::render::render_with;
