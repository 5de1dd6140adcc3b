//! `bumpwork bench`: each quality preset, and each single knob varied from `interactive`, timed
//! on the standard scenes and measured against the exact reference on the same frame.

mod chart;
mod pareto;
mod variants;

pub use chart::{ChartMetric, draw_chart};
pub use pareto::pareto_front;
pub use variants::{Variant, VariantKind, variants};

use crate::measure::Timing;
use crate::quality::Quality;
use crate::raster::{Camera, Framebuffer, PreparedScene, Viewport, render_into};
use crate::reference::{FrameError, ShadedAndNormals, render_reference};
use crate::scene::Scene;
use glam::Vec3;

/// The scenes of the default bench (all built in).
pub const STANDARD_SCENES: [&str; 6] = [
    "sphere-on-plane-dimples",
    "big-sphere-squares",
    "cone-ripple",
    "textured-sphere",
    "plane-image-bump",
    "wave-spheres",
];

/// Untimed frames first: the first frames after a change of variant run measurably slower
/// (caches, the thread pool waking).
const WARMUP_FRAMES: usize = 3;

/// One variant on one scene: its cost and its error.
#[derive(Clone, Debug)]
pub struct Measurement {
    pub scene: String,
    pub variant: Variant,
    pub triangles: usize,
    pub timing: Timing,
    pub error: FrameError,
}

/// The reference frames of one scene and view, shaded as the `exact` preset shades.
pub struct Reference {
    pub frames: ShadedAndNormals,
}

impl Reference {
    pub fn render(scene: &Scene, viewport: Viewport) -> Reference {
        let quality = Quality::exact();
        // The reference ignores the tessellation; a coarse one serves to build the scene.
        let coarse = crate::surface::Tessellation { density: 4 };
        let prepared = PreparedScene::new(scene.clone(), coarse);
        let mut shader = quality.shader(&prepared, &scene.camera);
        let frames = ShadedAndNormals::render(&mut shader, |s| {
            render_reference(&prepared, &scene.camera, viewport, s).0
        });
        Reference { frames }
    }
}

/// Times `runs` frames of the variant (after warm-up frames) and measures its error.
pub fn measure(
    scene_name: &str,
    scene: &Scene,
    variant: &Variant,
    viewport: Viewport,
    runs: usize,
    reference: &Reference,
) -> Measurement {
    let camera: &Camera = &scene.camera;
    let quality = &variant.quality;
    let prepared = quality.prepare(scene.clone(), camera, viewport);
    let mut shader = quality.shader(&prepared, camera);
    let target = quality.target(camera, viewport);
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let timing = Timing::measure(WARMUP_FRAMES, runs, || {
        render_frame(&prepared, &target, &shader, &mut framebuffer);
    });
    let frames = ShadedAndNormals::render(&mut shader, |s| {
        let mut frame = Framebuffer::new(0, 0, Vec3::ZERO);
        render_frame(&prepared, &target, s, &mut frame);
        frame
    });
    Measurement {
        scene: scene_name.to_string(),
        variant: variant.clone(),
        triangles: prepared.triangle_count(),
        timing,
        error: frames.error_against(&reference.frames),
    }
}

/// Samples per pixel the bench renders. The supersampled renderer is being added on main;
/// until it is merged here every variant is rendered (timed and measured) at one sample, and
/// the reports say so next to the samples each variant asks for.
pub const SAMPLES_RENDERED: u32 = 1;

/// One frame as the bench times and measures it: the single place where samples per pixel
/// will be resolved (see `SAMPLES_RENDERED`).
fn render_frame(
    prepared: &PreparedScene,
    target: &crate::raster::RenderTarget,
    shader: &crate::shade::LitShader,
    framebuffer: &mut Framebuffer,
) {
    render_into(prepared, target, shader, framebuffer);
}

/// A variant's figures over every scene benched: summed median time, mean errors.
#[derive(Clone, Debug)]
pub struct Summary {
    pub variant: Variant,
    pub total_median_ms: f64,
    /// Mean over scenes of the PSNR (identical frames count as `PSNR_CEILING_DB`).
    pub mean_psnr_db: f64,
    pub mean_normal_degrees: f64,
}

/// Where identical frames are put on the PSNR axis: above any one-step 8-bit difference on a
/// frame of up to 10⁷ pixels (48 + 10·log10(3·10⁷) ≈ 123 dB would need 10¹⁰).
pub const PSNR_CEILING_DB: f64 = 150.0;

/// Per variant (in `variants` order), its figures over all scenes.
pub fn summarize(variants: &[Variant], measurements: &[Measurement]) -> Vec<Summary> {
    variants
        .iter()
        .map(|variant| {
            let rows: Vec<_> = measurements
                .iter()
                .filter(|m| m.variant.name == variant.name)
                .collect();
            let count = rows.len().max(1) as f64;
            Summary {
                variant: variant.clone(),
                total_median_ms: rows
                    .iter()
                    .map(|m| m.timing.median.as_secs_f64() * 1e3)
                    .sum(),
                mean_psnr_db: rows
                    .iter()
                    .map(|m| m.error.psnr_db.min(PSNR_CEILING_DB))
                    .sum::<f64>()
                    / count,
                mean_normal_degrees: rows
                    .iter()
                    .map(|m| m.error.mean_normal_angle_degrees)
                    .sum::<f64>()
                    / count,
            }
        })
        .collect()
}
