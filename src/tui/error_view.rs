//! The error view: the per-pixel difference of the frame to the exact reference as a heat map,
//! and the frame's PSNR. The reference is ray cast at the terminal's render size on every frame
//! of this view (slow, so only this view pays for it), shaded as the `exact` preset shades, the
//! same reference `bumpwork bench` measures against.

use crate::quality::Quality;
use crate::raster::{FrameStats, Framebuffer, RenderTarget};
use crate::reference::{error_heat_map, exact_shader, metrics::psnr, render_reference};
use crate::render::render_scene_pass;
use crate::scene::PreparedScene;
use crate::shade::Showing;
use crate::shadow::ShadowMaps;
use std::sync::Arc;

/// 8-bit sRGB steps of error drawn as white; smaller errors are red to yellow, none black.
const FULL_SCALE_STEPS: f32 = 32.0;

/// Renders the frame at `quality` and the reference, and leaves the heat map of their
/// difference in `framebuffer`; returns the frame's stats and its PSNR in dB.
pub fn render_error_view(
    time: f64,
    quality: &Quality,
    (prepared, maps): (&PreparedScene, Option<Arc<ShadowMaps>>),
    target: &RenderTarget,
    framebuffer: &mut Framebuffer,
) -> (FrameStats, f64) {
    let shader = quality.shader_with_maps(prepared, target.camera, maps, Showing::at(time));
    let stats = render_scene_pass(prepared, target, &shader, framebuffer);
    let exact = exact_shader(prepared, target.camera, time);
    let (reference, _) = render_reference(prepared, target.camera, target.viewport, &exact);
    let psnr_db = psnr(framebuffer, &reference);
    *framebuffer = error_heat_map(framebuffer, &reference, FULL_SCALE_STEPS);
    (stats, psnr_db)
}
