//! A fixed number of frames of a peer scene, for instruction counts under callgrind: the euc
//! peer's textured sphere, or the POV-Ray peer's scene at one sample per pixel (the still's
//! shader and quality, no file written). Prints the fragments shaded per frame; run it with two
//! frame counts and divide the difference in instructions by the difference in fragments.
//!
//! Run: `cargo bench --bench frame_cost -- euc|pov FRAMES`, e.g. under
//! `valgrind --tool=callgrind target/release/deps/frame_cost-* euc 3`.

mod bench_support;

use bench_support::{textured_sphere_scene, write_pov_peer_scene};
use bumpwork::quality::Quality;
use bumpwork::raster::{
    Camera, FragmentShader, Framebuffer, PreparedScene, RenderTarget, Viewport, render_into,
};
use bumpwork::scene::load_scene_file;
use bumpwork::surface::Tessellation;
use glam::Vec3;

const VIEWPORT: Viewport = Viewport {
    width: 1920,
    height: 1080,
};

fn frames(prepared: &PreparedScene, camera: &Camera, shader: &impl FragmentShader, n: usize) {
    let target = RenderTarget::new(camera, VIEWPORT);
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let mut fragments = 0;
    for _ in 0..n {
        fragments = render_into(prepared, &target, shader, &mut framebuffer).fragments;
    }
    println!("{n} frames of {fragments} fragments");
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
            let dir = std::env::temp_dir().join(format!("bumpwork-cost-{}", std::process::id()));
            std::fs::create_dir_all(&dir).expect("temp dir");
            let scene = load_scene_file(&write_pov_peer_scene(&dir)).expect("peer scene");
            let _ = std::fs::remove_dir_all(&dir);
            let camera = scene.camera.clone();
            let quality = Quality::interactive();
            let prepared = quality.prepare(scene, &camera, VIEWPORT);
            let shader = quality.shader(&prepared, &camera);
            frames(&prepared, &camera, &shader, n);
        }
        _ => {
            let (scene, _) = textured_sphere_scene();
            let camera = scene.camera.clone();
            let prepared = PreparedScene::new(scene, Tessellation { density: 64 });
            let shader = bumpwork::shade::LitShader::new(&prepared.scene, &camera);
            frames(&prepared, &camera, &shader, n);
        }
    }
}
