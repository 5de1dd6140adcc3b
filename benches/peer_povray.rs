//! bumpwork against POV-Ray 3.7 on the same scene, in one run: sphere-on-plane-dimples with a
//! checked, dimpled plane and a sphere wearing the chelsea photograph and the gravel height map,
//! at 1920×1080, without and with antialiasing (POV-Ray `-A` / `+A0.3`, bumpwork 1 / 16 samples).
//! POV-Ray renders the scene `render --format pov` writes (our meshes, our baked maps), so both
//! draw the same geometry. Medians with min–max over a few runs; skipped (and said so) when
//! `povray` is not installed.
//!
//! Run: `cargo bench --bench peer_povray`.

mod bench_support;

use bench_support::write_pov_peer_scene;
use bumpwork::export::{StillFormat, StillRequest, write_pov, write_still};
use bumpwork::measure::Timing;
use bumpwork::quality::Quality;
use bumpwork::scene::load_scene_file;
use bumpwork::shade::ViewMode;
use bumpwork::still::{Recipe, ResolveFilter, StillSettings};
use std::process::Command;

const SIZE: (u32, u32) = (1920, 1080);

fn runs() -> usize {
    std::env::var("BUMPWORK_BENCH_RUNS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(3)
}

fn settings(samples: u32) -> StillSettings {
    StillSettings {
        size: SIZE,
        quality: Quality {
            samples,
            ..Quality::interactive()
        },
        resolve: ResolveFilter::Box,
        time: 0.0,
        mode: ViewMode::Shaded,
    }
}

fn main() {
    if Command::new("povray").arg("--version").output().is_err() {
        println!("povray is not installed (Debian package `povray`): peer benchmark skipped");
        return;
    }
    let dir = std::env::temp_dir().join(format!("bumpwork-bench-pov-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scene_path = write_pov_peer_scene(&dir);
    let text = std::fs::read_to_string(&scene_path).expect("scene text");
    let scene = load_scene_file(&scene_path).expect("peer scene");
    let camera = scene.camera.clone();
    let base = settings(1);
    let prepared = base.prepare(scene, &camera);
    let pov = dir.join("peer.pov");
    write_pov(&prepared, &camera, SIZE, 0.0, &pov).expect("pov scene");
    println!(
        "{}x{} checks+dimples plane, textured bump-mapped sphere; {} runs",
        SIZE.0,
        SIZE.1,
        runs()
    );
    for (label, samples, antialias) in [("no AA", 1, "-A"), ("AA", 16, "+A0.3")] {
        let povray = Timing::measure(0, runs(), || {
            let status = Command::new("povray")
                .args([
                    &format!("+W{}", SIZE.0),
                    &format!("+H{}", SIZE.1),
                    antialias,
                ])
                .args(["-D", "-GA", "+Opov.png", "peer.pov"])
                .current_dir(&dir)
                .output()
                .expect("povray runs");
            assert!(
                status.status.success(),
                "{}",
                String::from_utf8_lossy(&status.stderr)
            );
        });
        let settings = settings(samples);
        let recipe = Recipe::capture(
            &scene_path.display().to_string(),
            &prepared.scene,
            &camera,
            &settings,
        );
        let request = StillRequest {
            prepared: &prepared,
            camera: &camera,
            settings,
            scene_text: &text,
            recipe: &recipe,
        };
        let out = dir.join("ours.png");
        let ours = Timing::measure(1, runs(), || {
            write_still(&request, &out, StillFormat::Png, &mut |_| {}, &|| None).expect("still");
        });
        let ratio = povray.median.as_secs_f64() / ours.median.as_secs_f64();
        println!(
            "  {label:<6} POV-Ray {antialias:<6} {}   bumpwork {samples:>2} spp {}   {ratio:.1}x faster",
            povray.summary_ms(),
            ours.summary_ms()
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
