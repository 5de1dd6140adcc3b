//! Fill rate of the rendering core: a lit 128×64 sphere, 540 pixels high, at 1920×1080, on one
//! thread and on all threads, with a breakdown of where a single-threaded frame goes. Medians
//! over repeated frames with min–max spread.
//!
//! Run: `cargo bench --bench raster`.

mod bench_support;

use bench_support::sphere_scene;
use bumpwork::measure::Timing;
use bumpwork::raster::{Fragment, Framebuffer, RenderTarget, Viewport, screen_triangles};
use bumpwork::render::render_scene_pass;
use bumpwork::scene::PreparedScene;
use bumpwork::shade::LitShader;
use bumpwork::shade::{FrameObject, PerFragment, frame_objects};
use bumpwork::surface::Tessellation;
use glam::Vec3;

/// Frames per measurement; `BUMPWORK_BENCH_RUNS=1` makes a single-frame run for callgrind.
fn runs() -> usize {
    bench_support::runs_or(31)
}

fn main() {
    let scene = sphere_scene();
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation { density: 64 });
    let target = RenderTarget::new(
        &camera,
        Viewport {
            width: 1920,
            height: 1080,
        },
    );
    let lit = LitShader::new(&prepared.scene, &camera);
    let mut framebuffer = Framebuffer::new(1920, 1080, Vec3::ZERO);
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("thread pool");

    println!(
        "lit 128x64 sphere ({} triangles) at 1920x1080, {} frames each",
        prepared.triangle_count(),
        runs()
    );
    println!("\none thread, where the frame goes:");
    let objects = frame_objects(&prepared, &camera);
    let setup = one_thread.install(|| {
        Timing::measure(3.min(runs().saturating_sub(1)), runs(), || {
            std::hint::black_box(screen_triangles(&objects, &target));
        })
    });
    let flat = one_thread.install(|| {
        Timing::measure(3.min(runs().saturating_sub(1)), runs(), || {
            // Coverage and visibility only: isolates the rasterizer from the cost of lighting.
            render_scene_pass(
                &prepared,
                &target,
                &PerFragment(|_: &FrameObject, _: &Fragment| Vec3::ONE),
                &mut framebuffer,
            );
        })
    });
    println!(
        "  {:<44} {}",
        "transform, clip, set up triangles",
        setup.summary_ms()
    );
    println!(
        "  {:<44} {}",
        "+ bin, scan, depth test, write (flat colour)",
        flat.summary_ms()
    );

    println!(
        "\n{:<10} {:>28} {:>12} {:>10} {:>10}",
        "threads", "lit frame median (min-max)", "fragments", "Mpix/s", "Mtri/s"
    );
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    for threads in [1, cores] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool");
        let mut stats = Default::default();
        let timing = pool.install(|| {
            Timing::measure(3.min(runs().saturating_sub(1)), runs(), || {
                stats = render_scene_pass(&prepared, &target, &lit, &mut framebuffer)
            })
        });
        println!(
            "{:<10} {:>28} {:>12} {:>10.1} {:>10.2}",
            threads,
            timing.summary_ms(),
            stats.fragments,
            timing.rate(stats.fragments as f64) / 1e6,
            timing.rate(stats.triangles as f64) / 1e6,
        );
    }
}
