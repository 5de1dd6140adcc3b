//! The rasterizer's error against the exact reference, per preset at the default tessellation,
//! and how it shrinks as the tessellation grows; the reference's own cost; and an 8192×8192
//! frame (a trivial scene, both renderers) checked for non-finite pixels.
//!
//! Run: `cargo bench --bench reference` (release; a few minutes on two cores).

mod bench_support;

use bumpwork::raster::{Framebuffer, RenderTarget, Viewport};
use bumpwork::reference::{FrameError, frame_error, render_reference};
use bumpwork::render::render_with;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{PRESET_NAMES, Scene, preset};
use bumpwork::shade::{LitShader, ShaderMode};
use bumpwork::surface::Tessellation;
use std::time::{Duration, Instant};

const VIEWPORT: Viewport = Viewport {
    width: 320,
    height: 240,
};
const CONVERGENCE_SCENES: &[&str] = &[
    "sphere-on-plane-dimples",
    "big-sphere-dimples",
    "parabola-dimples",
    "cone-dimples",
    "wave-spheres",
    "textured-sphere",
    "torus-dimples",
];

struct Measured {
    error: FrameError,
    raster_time: Duration,
    reference_time: Duration,
}

fn render_pair(
    scene: &Scene,
    density: u32,
    mode: ShaderMode,
) -> (Framebuffer, Framebuffer, [Duration; 2]) {
    let prepared = PreparedScene::new(scene.clone(), Tessellation { density });
    let mut shader = LitShader::new(scene, &scene.camera);
    shader.mode = mode;
    let target = RenderTarget::new(&scene.camera, VIEWPORT);
    let start = Instant::now();
    let raster = render_with(&prepared, &target, &shader).0;
    let raster_time = start.elapsed();
    let start = Instant::now();
    let reference = render_reference(&prepared, &scene.camera, VIEWPORT, &shader).0;
    (raster, reference, [raster_time, start.elapsed()])
}

fn measure(scene: &Scene, density: u32) -> Measured {
    let (raster, reference, [raster_time, reference_time]) =
        render_pair(scene, density, ShaderMode::Shaded);
    let (normals, normals_reference, _) = render_pair(scene, density, ShaderMode::Normals);
    Measured {
        error: frame_error(&raster, &reference, &normals, &normals_reference),
        raster_time,
        reference_time,
    }
}

fn print_row(label: &str, m: &Measured) {
    let e = &m.error;
    println!(
        "{label:<34} {:>7.2} {:>6.0} {:>8.3} {:>8.2} {:>6} {:>9.1} {:>9.1}",
        e.psnr_db,
        e.max_pixel_error,
        e.mean_normal_angle_degrees,
        e.max_normal_angle_degrees,
        e.silhouette_mismatch,
        m.raster_time.as_secs_f64() * 1e3,
        m.reference_time.as_secs_f64() * 1e3,
    );
}

fn print_header(first: &str) {
    println!(
        "{first:<34} {:>7} {:>6} {:>8} {:>8} {:>6} {:>9} {:>9}",
        "PSNR dB", "max", "mean °", "max °", "silh", "raster ms", "ref ms"
    );
}

fn trivial_scene_at_8k() {
    let scene = preset("big-sphere-dimples").expect("preset");
    let viewport = Viewport {
        width: 8192,
        height: 8192,
    };
    let prepared = PreparedScene::new(scene.clone(), Tessellation { density: 8 });
    let shader = LitShader::new(&scene, &scene.camera);
    let target = RenderTarget::new(&scene.camera, viewport);
    for (name, render) in [
        (
            "raster",
            &(|| render_with(&prepared, &target, &shader).0) as &dyn Fn() -> Framebuffer,
        ),
        ("reference", &|| {
            render_reference(&prepared, &scene.camera, viewport, &shader).0
        }),
    ] {
        let start = Instant::now();
        let frame = render();
        let bad = frame.color().iter().filter(|c| !c.is_finite()).count();
        println!(
            "8192x8192 {name}: {:.1} s, {bad} non-finite pixels",
            start.elapsed().as_secs_f64()
        );
        assert_eq!(bad, 0);
    }
}

fn main() {
    println!(
        "Raster vs reference at {}x{}, default tessellation ({}):",
        VIEWPORT.width,
        VIEWPORT.height,
        Tessellation::default().density
    );
    print_header("preset");
    for name in PRESET_NAMES {
        let scene = preset(name).expect("preset");
        print_row(name, &measure(&scene, Tessellation::default().density));
    }
    println!("\nConvergence with tessellation density:");
    print_header("preset @ density");
    for name in CONVERGENCE_SCENES {
        let scene = preset(name).expect("preset");
        for density in [4, 8, 16, 32, 64, 128, 256] {
            print_row(&format!("{name} @ {density}"), &measure(&scene, density));
        }
    }
    if std::env::args().any(|a| a == "--8k") {
        trivial_scene_at_8k();
    }
}
