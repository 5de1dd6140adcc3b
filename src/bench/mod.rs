//! `bumpwork bench`: each quality preset, and each single knob varied from `interactive`, timed
//! on the standard scenes and measured against the exact reference on the same frame.

mod chart;
mod label_placement;
mod pareto;
mod variants;

pub use chart::{ChartMetric, draw_chart};
pub use pareto::pareto_front;
pub use variants::{Variant, VariantKind, variants};

use crate::measure::Timing;
use crate::raster::ViewRays;
use crate::raster::{Framebuffer, RenderTarget, Viewport};
use crate::reference::{FrameError, ShadedAndNormals, exact_shader, render_rays_into};
use crate::render::render_scene_pass;
use crate::scene::Camera;
use crate::scene::PreparedScene;
use crate::scene::Scene;
use crate::shade::LitShader;
use crate::still::{BandBuffers, BandJob, Supersampling, render_supersampled};
use glam::Vec3;
use std::time::{Duration, Instant};

/// The scenes of the default bench (all built in).
pub const STANDARD_SCENES: [&str; 6] = [
    "sphere-on-plane-dimples",
    "big-sphere-squares",
    "cone-ripple",
    "textured-sphere",
    "plane-image-bump",
    "wave-spheres",
];

/// A variant stops being timed once its timed frames add up to this, after at least one: 64
/// samples of a 256-density mesh take seconds per frame (every pass sets up every triangle).
const TIME_BUDGET: Duration = Duration::from_secs(1);

/// One variant on one scene: its cost and its error.
#[derive(Clone, Debug)]
pub struct Measurement {
    pub scene: String,
    pub variant: Variant,
    pub triangles: usize,
    pub timing: Timing,
    pub error: FrameError,
}

/// The reference frames of one scene and view at one sample count, shaded as the `exact`
/// preset shades.
pub struct Reference {
    pub samples: u32,
    pub frames: ShadedAndNormals,
}

impl Reference {
    /// Ray cast through the very sample positions the supersampled rasterizer uses
    /// (`Supersampling::offsets`, equal weights), averaged in linear light; coverage is the last
    /// sample's, as `render_supersampled` keeps the last pass's depth. So a variant with more
    /// samples is measured against the same filtered picture, not a point-sampled one.
    pub fn render(scene: &Scene, viewport: Viewport, samples: u32) -> Reference {
        // The reference ignores the tessellation; a coarse one serves to build the scene.
        let coarse = crate::surface::Tessellation { density: 4 };
        let prepared = PreparedScene::new(scene.clone(), coarse);
        let mut shader = exact_shader(&prepared, &scene.camera, 0.0);
        let frames = ShadedAndNormals::render(&mut shader, |s| {
            supersampled_reference(&prepared, &scene.camera, viewport, s, samples)
        });
        Reference { samples, frames }
    }
}

fn supersampled_reference(
    prepared: &PreparedScene,
    camera: &Camera,
    viewport: Viewport,
    shader: &LitShader,
    samples: u32,
) -> Framebuffer {
    let sampling = supersampling(samples);
    let offsets = sampling.offsets();
    let weight = 1.0 / offsets.len() as f32;
    let rays = ViewRays::new(camera, viewport);
    let footprint = sampling.footprint() as f64;
    let mut pass = Framebuffer::new(0, 0, Vec3::ZERO);
    let mut color = vec![Vec3::ZERO; (viewport.width * viewport.height) as usize];
    for offset in offsets {
        let sample_rays = rays.at_sample(offset.as_dvec2(), footprint);
        render_rays_into(prepared, camera, viewport, sample_rays, shader, &mut pass);
        for (sum, &c) in color.iter_mut().zip(pass.color()) {
            *sum += c * weight;
        }
    }
    Framebuffer::from_parts(viewport.width, viewport.height, color, pass.take_depth())
}

/// The still renderer's supersampling for a sample count (its default resolve filter).
fn supersampling(samples: u32) -> Supersampling {
    Supersampling {
        samples: samples.max(1),
        ..Supersampling::default()
    }
}

/// References for every sample count the variants ask for.
pub fn references(scene: &Scene, viewport: Viewport, variants: &[Variant]) -> Vec<Reference> {
    let mut counts: Vec<u32> = variants.iter().map(|v| v.quality.samples.max(1)).collect();
    counts.sort_unstable();
    counts.dedup();
    counts
        .into_iter()
        .map(|samples| Reference::render(scene, viewport, samples))
        .collect()
}

/// One variant made ready to render on one scene.
struct Ready<'a> {
    variant: &'a Variant,
    prepared: PreparedScene,
    shader: LitShader,
    target: RenderTarget<'a>,
    samples: u32,
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
    references: &[Reference],
) -> Result<Vec<Measurement>, crate::memory_budget::OverBudget> {
    let camera: &Camera = &scene.camera;
    let mut ready: Vec<Ready> = variants
        .iter()
        .map(|variant| {
            let quality = &variant.quality;
            let output_bytes = Framebuffer::bytes_for(viewport);
            let prepared = quality.prepare(scene.clone(), camera, viewport, output_bytes)?;
            let shader = quality.shader(&prepared, camera, viewport);
            let target = quality.target(camera, viewport);
            Ok(Ready {
                variant,
                prepared,
                shader,
                target,
                samples: quality.samples.max(1),
            })
        })
        .collect::<Result<_, _>>()?;
    let timings = time_in_rounds(&ready, runs);
    Ok(ready
        .iter_mut()
        .zip(timings)
        .map(|(r, timing)| {
            let samples = r.samples;
            let frames = ShadedAndNormals::render(&mut r.shader, |s| {
                let mut frame = Framebuffer::new(0, 0, Vec3::ZERO);
                render_frame(&r.prepared, &r.target, s, samples, &mut frame);
                frame
            });
            let reference = references
                .iter()
                .find(|reference| reference.samples == samples)
                .expect("a reference for every sample count asked for");
            Measurement {
                scene: scene_name.to_string(),
                variant: r.variant.clone(),
                triangles: r.prepared.triangle_count(),
                timing,
                error: frames.error_against(&reference.frames),
            }
        })
        .collect())
}

/// Per variant, the timing of up to `runs` frames taken one per round after an untimed
/// warm-up frame (the first frame runs measurably slower: caches, the thread pool waking), fewer
/// for a variant past `TIME_BUDGET`.
fn time_in_rounds(ready: &[Ready], runs: usize) -> Vec<Timing> {
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let mut time_one = |r: &Ready| {
        let start = Instant::now();
        render_frame(
            &r.prepared,
            &r.target,
            &r.shader,
            r.samples,
            &mut framebuffer,
        );
        start.elapsed()
    };
    // The warm-up frame counts when it alone is over the budget: a frame that slow is not
    // made slow by cold caches, and it is one frame fewer of a variant that takes seconds.
    let mut samples: Vec<Vec<Duration>> = ready
        .iter()
        .map(|r| {
            let warm_up = time_one(r);
            if warm_up > TIME_BUDGET {
                vec![warm_up]
            } else {
                Vec::new()
            }
        })
        .collect();
    for _ in 0..runs.max(1) {
        for (r, times) in ready.iter().zip(&mut samples) {
            if times.len() < runs.max(1) && times.iter().sum::<Duration>() <= TIME_BUDGET {
                times.push(time_one(r));
            }
        }
    }
    samples.into_iter().map(Timing::from_samples).collect()
}

/// One frame as the bench times and measures it: one sample per pixel centre, or the still
/// renderer's supersampling (shifted passes resolved in linear light).
fn render_frame(
    prepared: &PreparedScene,
    target: &RenderTarget,
    shader: &LitShader,
    samples: u32,
    framebuffer: &mut Framebuffer,
) {
    if samples <= 1 {
        render_scene_pass(prepared, target, shader, framebuffer);
        return;
    }
    let job = BandJob {
        prepared,
        camera: target.camera,
        full: target.viewport,
        shader,
        supersampling: supersampling(samples),
        interpolation: target.interpolation,
        adaptive: None,
    };
    *framebuffer = render_supersampled(&job, &mut BandBuffers::default()).0;
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
