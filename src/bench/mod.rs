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
use crate::raster::{Camera, Framebuffer, PreparedScene, RenderTarget, Viewport, render_into};
use crate::reference::{FrameError, ShadedAndNormals, render_reference};
use crate::scene::Scene;
use crate::shade::LitShader;
use glam::Vec3;
use std::time::Instant;

/// The scenes of the default bench (all built in).
pub const STANDARD_SCENES: [&str; 6] = [
    "sphere-on-plane-dimples",
    "big-sphere-squares",
    "cone-ripple",
    "textured-sphere",
    "plane-image-bump",
    "wave-spheres",
];

/// Untimed frames of each variant first: the first frames run measurably slower (caches, the
/// thread pool waking).
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

/// One variant made ready to render on one scene.
struct Ready<'a> {
    variant: &'a Variant,
    prepared: PreparedScene,
    shader: LitShader,
    target: RenderTarget<'a>,
}

/// Times `runs` frames of every variant on the scene and measures each one's error. The timed
/// frames go in rounds, one frame of each variant per round (after warm-up frames), so load
/// from other processes that comes and goes falls on all variants alike.
pub fn measure_scene(
    scene_name: &str,
    scene: &Scene,
    variants: &[Variant],
    viewport: Viewport,
    runs: usize,
    reference: &Reference,
) -> Vec<Measurement> {
    let camera: &Camera = &scene.camera;
    let mut ready: Vec<Ready> = variants
        .iter()
        .map(|variant| {
            let quality = &variant.quality;
            let prepared = quality.prepare(scene.clone(), camera, viewport);
            let shader = quality.shader(&prepared, camera);
            let target = quality.target(camera, viewport);
            Ready {
                variant,
                prepared,
                shader,
                target,
            }
        })
        .collect();
    let timings = time_in_rounds(&ready, runs);
    ready
        .iter_mut()
        .zip(timings)
        .map(|(r, timing)| {
            let frames = ShadedAndNormals::render(&mut r.shader, |s| {
                let mut frame = Framebuffer::new(0, 0, Vec3::ZERO);
                render_frame(&r.prepared, &r.target, s, &mut frame);
                frame
            });
            Measurement {
                scene: scene_name.to_string(),
                variant: r.variant.clone(),
                triangles: r.prepared.triangle_count(),
                timing,
                error: frames.error_against(&reference.frames),
            }
        })
        .collect()
}

/// Per variant, the timing of `runs` frames taken one per round.
fn time_in_rounds(ready: &[Ready], runs: usize) -> Vec<Timing> {
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let mut samples = vec![Vec::with_capacity(runs); ready.len()];
    for r in ready {
        for _ in 0..WARMUP_FRAMES {
            render_frame(&r.prepared, &r.target, &r.shader, &mut framebuffer);
        }
    }
    for _ in 0..runs.max(1) {
        for (r, times) in ready.iter().zip(&mut samples) {
            let start = Instant::now();
            render_frame(&r.prepared, &r.target, &r.shader, &mut framebuffer);
            times.push(start.elapsed());
        }
    }
    samples.into_iter().map(Timing::from_samples).collect()
}

/// Samples per pixel the bench renders. The supersampled renderer is being added on main;
/// until it is merged here every variant is rendered (timed and measured) at one sample, and
/// the reports say so next to the samples each variant asks for.
pub const SAMPLES_RENDERED: u32 = 1;

/// One frame as the bench times and measures it: the single place where samples per pixel
/// will be resolved (see `SAMPLES_RENDERED`).
fn render_frame(
    prepared: &PreparedScene,
    target: &RenderTarget,
    shader: &LitShader,
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
