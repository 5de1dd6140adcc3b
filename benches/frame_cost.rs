//! A fixed number of frames of a peer scene, for instruction counts under callgrind: the euc
//! peer's textured sphere, or the POV-Ray peer's scene at one sample per pixel (the still's
//! shader and quality, no file written), or that scene at 16 samples as the POV-Ray peer renders
//! it, adaptive at CONTRAST if given. Prints the fragments shaded per frame; run it with two
//! frame counts and divide the difference in instructions by the difference in fragments. It
//! prints each frame's wall time too (median and range), for comparing two builds.
//! `still` writes the POV-Ray peer's PNG still FRAMES times as `peer_povray` does (render, 8-bit
//! conversion, PNG encoding, sync; 1 sample per pixel unless SAMPLES, adaptive at CONTRAST if
//! given) and prints the wall time's median and range, for comparing two builds run one after
//! the other; with BUMPWORK_NO_SHADOWS set, the still is rendered without shadows, and with
//! BUMPWORK_PLAIN set, without shadows, bumps or textures (the limit kernel's plain objects).
//!
//! Run: `cargo bench --bench frame_cost -- euc|pov|pov16|still FRAMES [ARGS]` (pov16: CONTRAST;
//! still: SAMPLES CONTRAST), e.g. under
//! `valgrind --tool=callgrind target/release/deps/frame_cost-* euc 3`.

mod bench_support;

use bench_support::{
    PeerStill, pov_peer_files, pov_peer_settings, textured_sphere_scene, time_png_stills,
    write_pov_peer_scene,
};
use bumpwork::measure::Timing;
use bumpwork::quality::Quality;
use bumpwork::raster::{Framebuffer, RenderTarget, Viewport};
use bumpwork::render::{SceneShader, render_scene_pass};
use bumpwork::scene::Camera;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::load_scene_file;
use bumpwork::still::{BandBuffers, BandJob, ResolveFilter, Supersampling, render_supersampled};
use bumpwork::surface::Tessellation;
use glam::Vec3;

const VIEWPORT: Viewport = Viewport {
    width: 1920,
    height: 1080,
};

fn frames(prepared: &PreparedScene, camera: &Camera, shader: &impl SceneShader, n: usize) {
    let target = RenderTarget::new(camera, VIEWPORT);
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let mut fragments = 0;
    let mut times = Vec::with_capacity(n);
    for _ in 0..n {
        let start = std::time::Instant::now();
        fragments = render_scene_pass(prepared, &target, shader, &mut framebuffer).fragments;
        times.push(start.elapsed());
    }
    let per_frame = Timing::from_samples(times).summary_ms();
    println!("{n} frames of {fragments} fragments: {per_frame} a frame");
}

/// `n` 1080p PNG stills of the POV-Ray peer's scene at `samples` per pixel (adaptive at
/// `contrast` if given), after one that settles the machine; prints their wall times.
fn stills(n: usize, samples: u32, contrast: Option<f32>) {
    let temp = tempfile::tempdir().expect("a temporary directory");
    let dir = temp.path().to_path_buf();
    let (_, text, mut scene) = pov_peer_files(&dir);
    if std::env::var_os("BUMPWORK_NO_SHADOWS").is_some() {
        scene.shadows = false;
    }
    if std::env::var_os("BUMPWORK_PLAIN").is_some() {
        scene.shadows = false;
        for object in &mut scene.objects {
            object.material.bump = None;
            object.material.texture = None;
        }
    }
    let still = PeerStill::new(scene, text, pov_peer_settings(samples, contrast));
    let out = dir.join("still.png");
    let timing = time_png_stills(&still.still, still.settings, &out, n);
    println!("{n} stills: {}", timing.summary_ms());
}

/// The POV-Ray peer's scene, prepared at the interactive quality it is benchmarked at.
fn pov_peer_scene() -> (PreparedScene, Camera, Quality) {
    let temp = tempfile::tempdir().expect("a temporary directory");
    let dir = temp.path().to_path_buf();
    let scene = load_scene_file(&write_pov_peer_scene(&dir)).expect("peer scene");
    let camera = scene.camera.clone();
    let quality = Quality::interactive();
    let prepared = quality.prepare(scene, &camera, VIEWPORT, 0).unwrap();
    (prepared, camera, quality)
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let scene = args.first().map_or("euc", String::as_str);
    let n = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(1);
    match scene {
        "pov" => {
            let (prepared, camera, quality) = pov_peer_scene();
            let shader = quality.shader(&prepared, &camera, VIEWPORT);
            frames(&prepared, &camera, &shader, n);
        }
        "pov16" => {
            let (prepared, camera, quality) = pov_peer_scene();
            let shader = quality.shader(&prepared, &camera, VIEWPORT);
            let job = BandJob {
                prepared: &prepared,
                camera: &camera,
                full: VIEWPORT,
                shader: &shader,
                // As `peer_povray` renders its 16-sample stills.
                supersampling: Supersampling {
                    samples: 16,
                    filter: ResolveFilter::Box,
                },
                interpolation: quality.interpolation,
                adaptive: args.get(2).and_then(|a| a.parse().ok()),
            };
            let mut buffers = BandBuffers::default();
            let mut fragments = 0;
            for _ in 0..n {
                fragments = render_supersampled(&job, &mut buffers).1.fragments;
            }
            println!("{n} frames of {fragments} fragments");
        }
        "still" => stills(
            n,
            args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1),
            args.get(3).and_then(|a| a.parse().ok()),
        ),
        _ => {
            let (scene, _) = textured_sphere_scene();
            let camera = scene.camera.clone();
            let prepared = PreparedScene::new(scene, Tessellation { density: 64 });
            let shader = bumpwork::shade::LitShader::new(&prepared.scene, &camera);
            frames(&prepared, &camera, &shader, n);
        }
    }
}
