//! Where a frame goes and how it is seen: the camera, viewport, window, sample spacing, mask
//! and blend of a pass, and where its pixels are written.

use super::framebuffer::{Blend, Framebuffer};
use super::interpolation::Interpolation;
use super::setup::Viewport;
use super::window::ImageWindow;
use crate::camera::Camera;
use glam::Mat4;

/// Where a frame goes and how it is seen.
pub struct RenderTarget<'a> {
    pub camera: &'a Camera,
    /// The size of the frame rendered (the window's size when rendering part of an image).
    pub viewport: Viewport,
    pub interpolation: Interpolation,
    /// The part of the image this frame covers and where it samples in each pixel.
    pub window: ImageWindow,
    /// The spacing of samples in pixels, scaling the (u,v) derivatives that pick texture detail:
    /// 1 for one sample per pixel, ½ for 4 samples, so supersampled stills keep their detail.
    pub footprint: f32,
    /// Only these pixels (row-major over the viewport) are rendered; the rest of the
    /// framebuffer is left as it was, and tiles with none of them are skipped whole.
    pub mask: Option<&'a [bool]>,
    pub blend: Blend,
    /// Whether the framebuffer's depth is written. When not, it keeps what it held: a pass whose
    /// depth nobody reads skips the stores, and a fresh framebuffer's depth is never touched
    /// (so never mapped).
    pub writes_depth: bool,
}

/// Where a render's pixels go.
pub enum FrameOutput<'o> {
    /// Into the framebuffer (resized to the viewport).
    Framebuffer(&'o mut Framebuffer),
    /// Into the framebuffer, and each strip of `STRIP_ROWS` rows handed on as 8-bit sRGB once
    /// every pass has finished it: a still encodes its rows while the rest renders.
    FramebufferAndStrips(&'o mut Framebuffer, &'o Srgb8Strips<'o>),
    /// Only as 8-bit sRGB strips, no framebuffer at all (none is allocated, zeroed or touched):
    /// for one pass that replaces every pixel, unmasked, keeping no depth.
    Strips(&'o Srgb8Strips<'o>),
}

/// A render's strips handed on as 8-bit sRGB (3 bytes a pixel, row-major), each tile converted
/// as soon as it is finished, while its colours are still in cache.
pub struct Srgb8Strips<'a> {
    /// A buffer to fill with a strip's bytes (its contents are overwritten: pass one back).
    pub buffer: &'a (dyn Fn() -> Vec<u8> + Sync),
    /// Strip `index` (from the top) and its bytes, on the thread that rendered it, in no set
    /// order.
    pub finished: &'a (dyn Fn(usize, Vec<u8>) + Sync),
}

impl<'a> RenderTarget<'a> {
    /// The whole `viewport` seen by `camera`, one perspective-correct sample at each pixel centre.
    pub fn new(camera: &'a Camera, viewport: Viewport) -> RenderTarget<'a> {
        RenderTarget {
            camera,
            viewport,
            interpolation: Interpolation::PerspectiveCorrect,
            window: ImageWindow::whole(viewport),
            footprint: 1.0,
            mask: None,
            blend: Blend::Replace,
            writes_depth: true,
        }
    }

    pub fn with_interpolation(self, interpolation: Interpolation) -> RenderTarget<'a> {
        RenderTarget {
            interpolation,
            ..self
        }
    }

    /// Camera-relative world positions to this frame's clip space.
    pub fn view_projection(&self) -> Mat4 {
        self.window.clip_transform(self.viewport)
            * self.camera.view_projection(self.window.full.aspect())
    }
}
