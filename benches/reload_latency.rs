//! Hot-reload latency: from the write of a pattern file to the next frame rendered from it, with
//! the debounce included. A frame is a 400×120 render with `render::render_scene`, standing in for the
//! workbench's 200×60 cells (two pixels a cell across, as the terminal encoder uses half blocks
//! it is 400×120 pixels). Median and p95 over the saves, and where the time goes.
//!
//! Run: `cargo bench --bench reload_latency`.

use bumpwork::measure::Timing;
use bumpwork::raster::{RenderTarget, Viewport};
use bumpwork::render::render_lit;
use bumpwork::scene::PreparedScene;
use bumpwork::scene::Scene;
use bumpwork::surface::Tessellation;
use bumpwork::watch::{DEBOUNCE, ReloadOutcome, Reloader, SceneFileSource};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

const SAVES: u32 = 40;
const VIEWPORT: Viewport = Viewport {
    width: 400,
    height: 120,
};

const SCENE: &str = r#"
[camera]
eye = [0, 260, 620]
target = [0, 70, 0]
fov = 40

[[light]]
point = { position = [-400, 600, 500] }

[[object]]
surface = { plane = { origin = [-200, 0, 200], normal = [0, 1, 0], u-axis = [1, 0, 0], size = [400, 400] } }
bump = { pattern = "dimples.pat" }

[[object]]
surface = { sphere = { center = [0, 100, 0], radius = 100 } }
bump = { pattern = "dimples.pat" }
"#;

fn pattern(period: u32) -> String {
    format!(
        "param period = {period} in 4..200\n\
         let cu = u % period - period / 2\n\
         let cv = v % period - period / 2\n\
         let r2 = 125 - cu^2 - cv^2\n\
         height = if r2 > 0 then 10 - sqrt(225 - cu^2 - cv^2) else 0\n"
    )
}

fn frame(scene: Scene) {
    let camera = scene.camera.clone();
    let prepared = PreparedScene::new(scene, Tessellation::default());
    let target = RenderTarget::new(&camera, VIEWPORT);
    std::hint::black_box(render_lit(&prepared, &target));
}

/// Writes the save, then waits for its reload: (write → scene available, write → frame done).
fn one_save(reloader: &Reloader, file: &Path, period: u32) -> (Duration, Duration) {
    let written = Instant::now();
    std::fs::write(file, pattern(period)).unwrap();
    loop {
        match reloader.wait(Duration::from_secs(10)) {
            Some(ReloadOutcome::Reloaded(reload)) => {
                let available = written.elapsed();
                frame(reload.scene);
                return (available, written.elapsed());
            }
            Some(ReloadOutcome::Failed(error)) => panic!("reload failed: {error}"),
            Some(ReloadOutcome::Unchanged) => continue,
            None => panic!("no reload within 10 s"),
        }
    }
}

fn temporary_dir() -> PathBuf {
    let temp = tempfile::tempdir().expect("a temporary directory");

    temp.path().to_path_buf()
}

fn main() {
    let dir = temporary_dir();
    let file = dir.join("dimples.pat");
    std::fs::write(&file, pattern(30)).unwrap();
    std::fs::write(dir.join("scene.toml"), SCENE).unwrap();
    let (reloader, first) = Reloader::start(SceneFileSource::new(dir.join("scene.toml"))).unwrap();
    frame(first.unwrap());

    let render_only = Timing::measure(2, 20, || {
        frame(bumpwork::scene::load_scene_file(&dir.join("scene.toml")).unwrap())
    });
    let (mut available, mut shown) = (Vec::new(), Vec::new());
    for save in 0..SAVES {
        let (a, s) = one_save(&reloader, &file, 20 + save % 40);
        available.push(a);
        shown.push(s);
        // Let the watcher go quiet so each save is measured alone.
        std::thread::sleep(Duration::from_millis(50));
    }
    drop(reloader);

    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let report = |what: &str, t: Timing| {
        println!(
            "{what:<32} median {:6.2} ms   p95 {:6.2} ms   (min {:.2}, max {:.2}, {} runs)",
            ms(t.median),
            ms(t.p95),
            ms(t.min),
            ms(t.max),
            t.runs
        )
    };
    println!(
        "debounce {} ms, frame {}×{}",
        DEBOUNCE.as_millis(),
        VIEWPORT.width,
        VIEWPORT.height
    );
    report("write → reloaded scene", Timing::from_samples(available));
    report("write → frame rendered", Timing::from_samples(shown));
    report("load + render alone", render_only);
}
