//! Still export: `sphere-on-plane-dimples` with the chelsea photograph wrapped on the sphere,
//! written as a 1920×1080 PNG at 1 and 16 samples per pixel (render, resolve, sRGB, encode,
//! atomic write), against the whole-frame path (one render in memory, then `write_png`) measured
//! in the same run; and the peak memory of a 7680×4320 export at 16 samples, read from
//! `/usr/bin/time -v` around the real binary.
//!
//! Run: `cargo bench --bench export`.

mod bench_support;

use bench_support::time_png_stills;
use bumpwork::export::{PreparedStill, write_png};
use bumpwork::measure::Timing;
use bumpwork::quality::Quality;
use bumpwork::raster::{RenderTarget, Viewport};
use bumpwork::render::render_lit;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{BindingFile, MappingKind, load_scene_file, preset_file};
use bumpwork::shade::ShaderMode;
use bumpwork::still::{ResolveFilter, StillSettings};
use bumpwork::surface::Tessellation;
use std::path::{Path, PathBuf};
use std::process::Command;

fn runs() -> usize {
    bench_support::runs_or(7)
}

/// The bench scene as a file (the binary reads it for the memory measurement).
fn write_scene(dir: &Path) -> PathBuf {
    let mut file = preset_file("sphere-on-plane-dimples").expect("preset");
    file.objects[1].texture = Some(BindingFile {
        image: Some("chelsea".into()),
        mapping: Some(MappingKind::Spherical),
        ..BindingFile::default()
    });
    let path = dir.join("textured-dimples.toml");
    std::fs::write(&path, file.to_toml()).expect("scene file");
    path
}

fn settings(samples: u32) -> StillSettings {
    StillSettings {
        size: (1920, 1080),
        quality: Quality {
            samples,
            ..Quality::interactive()
        },
        resolve: ResolveFilter::default(),
        time: 0.0,
        mode: ShaderMode::Shaded,
    }
}

fn main() {
    let temp = tempfile::tempdir().expect("a temporary directory");
    let dir = temp.path().to_path_buf();
    let scene_path = write_scene(&dir);
    let source = scene_path.display().to_string();
    let scene = load_scene_file(&scene_path).expect("bench scene");
    let text = std::fs::read_to_string(&scene_path).expect("scene text");
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation::default());
    let out = dir.join("still.png");
    println!(
        "export 1920x1080 sphere-on-plane-dimples + chelsea texture, {} runs",
        runs()
    );
    let whole = Timing::measure(1, runs(), || {
        let viewport = Viewport {
            width: 1920,
            height: 1080,
        };
        let (framebuffer, _) = render_lit(&prepared, &RenderTarget::new(&camera, viewport));
        write_png(&framebuffer, &out).expect("png");
    });
    println!("  whole frame + write_png (peer): {}", whole.summary_ms());
    let still = PreparedStill::from_prepared((&source, &text), prepared, &camera);
    for samples in [1, 16] {
        let settings = settings(samples);
        let timing = time_png_stills(&still, settings, &out, runs());
        let ratio = timing.median.as_secs_f64() / whole.median.as_secs_f64();
        println!(
            "  still, {samples:>2} spp: {}  ({ratio:.2}x the whole-frame path)",
            timing.summary_ms()
        );
    }
    peak_memory(&scene_path, &dir);
}

/// Peak resident memory of the binary exporting 7680×4320 at 16 samples.
fn peak_memory(scene: &Path, dir: &Path) {
    let out = dir.join("8k.png");
    let result = Command::new("/usr/bin/time")
        .arg("-v")
        .arg(env!("CARGO_BIN_EXE_bumpwork"))
        .args([
            "render",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .args(["--size", "7680x4320", "--samples", "16"])
        .output();
    let Ok(output) = result else {
        println!("  peak memory: skipped, /usr/bin/time is not installed");
        return;
    };
    let report = String::from_utf8_lossy(&output.stderr);
    let field = |name: &str| {
        report
            .lines()
            .find_map(|l| l.trim().strip_prefix(name))
            .map(|v| v.trim().to_string())
            .unwrap_or_else(|| "?".into())
    };
    let kib: f64 = field("Maximum resident set size (kbytes):")
        .parse()
        .unwrap_or(f64::NAN);
    println!(
        "  7680x4320 at 16 spp: peak RSS {:.0} MiB, wall {}, file {} bytes (limit 512 MiB)",
        kib / 1024.0,
        field("Elapsed (wall clock) time (h:mm:ss or m:ss):"),
        std::fs::metadata(&out).map_or(0, |m| m.len())
    );
}
