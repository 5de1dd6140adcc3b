//! A model of 100 352 triangles (a UV sphere written as an OBJ file) with the dimples on a floor:
//! a 1920×1080 one-sample PNG still of it beside the same still of `sphere-on-plane-dimples`,
//! and a workbench orbit step of it at 200×60 cells beside that scene's, each pair measured in
//! the same run (medians, with their spread), and the model's load time.
//!
//! Run: `cargo bench --bench model_frame`.

mod bench_support;

use bench_support::time_png_stills;
use bumpwork::export::PreparedStill;
use bumpwork::measure::Timing;
use bumpwork::quality::Quality;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::{Scene, load_scene_file, preset, source_text};
use bumpwork::shade::ShaderMode;
use bumpwork::still::{ResolveFilter, StillSettings};
use bumpwork::surface::Tessellation;
use bumpwork::term::{ColorChoice, ColorMode};
use bumpwork::tui::{App, Screen, WorkbenchOptions, keymap};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

const RUNS: usize = 7;
/// Cells around the sphere and rows from pole to pole: 2 · 224 · 224 triangles.
const SIDE: usize = 224;

/// A UV sphere of radius 1 with normals and texture coordinates, as OBJ text.
fn sphere_obj() -> String {
    let mut text = String::new();
    for j in 0..=SIDE {
        let theta = std::f64::consts::PI * j as f64 / SIDE as f64;
        for i in 0..=SIDE {
            let phi = std::f64::consts::TAU * i as f64 / SIDE as f64;
            let (x, y, z) = (
                theta.sin() * phi.cos(),
                theta.cos(),
                -theta.sin() * phi.sin(),
            );
            let (u, v) = (i as f64 / SIDE as f64, 1.0 - j as f64 / SIDE as f64);
            writeln!(
                text,
                "v {x:.6} {y:.6} {z:.6}\nvn {x:.6} {y:.6} {z:.6}\nvt {u:.6} {v:.6}"
            )
            .unwrap();
        }
    }
    let index = |i: usize, j: usize| j * (SIDE + 1) + i + 1;
    for j in 0..SIDE {
        for i in 0..SIDE {
            let [a, b, c, d] = [
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            ];
            writeln!(text, "f {a}/{a}/{a} {d}/{d}/{d} {c}/{c}/{c}").unwrap();
            writeln!(text, "f {a}/{a}/{a} {c}/{c}/{c} {b}/{b}/{b}").unwrap();
        }
    }
    text
}

/// The sphere-on-plane scene with the sphere a model of radius 100 in its place.
fn write_scene(dir: &Path) -> PathBuf {
    std::fs::write(dir.join("sphere.obj"), sphere_obj()).expect("model file");
    let text = "[camera]\neye = [0, 260, 620]\ntarget = [0, 70, 0]\nfov = 40\n\
        [[light]]\npoint = { position = [-400, 600, 500], color = [0.9, 0.9, 0.9] }\n\
        [[object]]\nsurface = { plane = { origin = [-600, 0, 600], normal = [0, 1, 0], \
        u-axis = [1, 0, 0], size = [1200, 1200] } }\nmaterial = { color = [0.55, 0.6, 0.7] }\n\
        bump = { pattern = \"dimples\" }\n\
        [[object]]\nsurface = { mesh = { file = \"sphere.obj\", position = [0, 100, 0], \
        scale = 100, uv-scale = 720 } }\n\
        material = { color = [0.8, 0.45, 0.3], specular = 0.3, shininess = 40 }\n\
        bump = { pattern = \"dimples\" }\n";
    let path = dir.join("model.toml");
    std::fs::write(&path, text).expect("scene file");
    path
}

fn still(scene: Scene, source: &str, text: &str, out: &Path) -> Timing {
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation::default());
    let settings = StillSettings {
        size: (1920, 1080),
        quality: Quality::interactive(),
        resolve: ResolveFilter::default(),
        time: 0.0,
        mode: ShaderMode::Shaded,
    };
    let still = PreparedStill::from_prepared((source, text), prepared, &camera);
    time_png_stills(&still, settings, out, RUNS)
}

/// Key press to finished frame, orbiting, at 200×60 cells.
fn orbit_step(scene: &str) -> Timing {
    let options = WorkbenchOptions {
        scenes: vec![scene.into()],
        colors: ColorChoice::Fixed(ColorMode::TrueColor),
        watch: false,
        ..WorkbenchOptions::default()
    };
    let mut app = App::new(&options, ColorMode::TrueColor).expect("scene");
    let mut screen = Screen::new(200, 60);
    let mut out = Vec::new();
    let key = KeyEvent::new(KeyCode::Char('l'), KeyModifiers::NONE);
    Timing::measure(2, 41, || {
        if let Some(action) = keymap::action_for(&key) {
            app.apply(action);
        }
        out.clear();
        screen.draw(&mut app, &mut out).expect("writing to memory");
    })
}

fn main() {
    let temp = tempfile::tempdir().expect("a temporary directory");
    let dir = temp.path().to_path_buf();
    let scene_path = write_scene(&dir);
    let load = Timing::measure(1, RUNS, || {
        load_scene_file(&scene_path).expect("model scene");
    });
    let model = load_scene_file(&scene_path).expect("model scene");
    let triangles: u64 = model
        .objects
        .iter()
        .map(|o| o.surface.triangle_count(Tessellation::default()))
        .sum();
    println!(
        "a model of {} triangles on a floor, {RUNS} runs",
        triangles - 2
    );
    println!("  load (parse, tangents, BVH): {}", load.summary_ms());
    let source = scene_path.display().to_string();
    let text = std::fs::read_to_string(&scene_path).expect("scene text");
    let out = dir.join("still.png");
    let ours = still(model, &source, &text, &out);
    let name = "sphere-on-plane-dimples";
    let text = source_text(name).expect("built-in scene");
    let peer = still(preset(name).expect("built-in"), name, &text, &out);
    let ratio = ours.median.as_secs_f64() / peer.median.as_secs_f64();
    println!("  1920x1080 still, 1 spp: model {}", ours.summary_ms());
    println!(
        "                          {name} {}  (model {ratio:.2}x)",
        peer.summary_ms()
    );
    let ms = |t: &Timing| {
        format!(
            "median {:.1} ms, p95 {:.1} ms",
            t.median.as_secs_f64() * 1e3,
            t.p95.as_secs_f64() * 1e3
        )
    };
    let model_orbit = orbit_step(&source);
    let peer_orbit = orbit_step(name);
    println!("  orbit step at 200x60 cells: model {}", ms(&model_orbit));
    println!("                              {name} {}", ms(&peer_orbit));
}
