//! True displacement against Blinn's bump, on the sphere on the plane with the height form of
//! the seed's dimples (`patterns/dimples.pat`): the time of a 1080p one-sample frame each way
//! (prepare, program and raster, interleaved, medians of the rounds), then the error of each
//! against the exact judge of the displaced surface (the reference's ray search on P'), over
//! all pixels and the pixels whose coverage differs, as the bump's strength grows: the
//! lecture's "small if B is small", as a table.
//!
//! Run: `cargo bench --bench displacement` (`BUMPWORK_BENCH_RUNS` rounds, 5 by default).

mod bench_support;

use bench_support::runs_or;
use bumpwork::measure::{Timing, ratio_by_round};
use bumpwork::quality::Quality;
use bumpwork::raster::{Framebuffer, Viewport};
use bumpwork::reference::metrics::{psnr, silhouette_mismatch};
use bumpwork::reference::render_reference;
use bumpwork::render::{frame, render_with};
use bumpwork::scene::{Scene, parse_scene};
use bumpwork::shade::{NormalForm, Showing};

const FULL_HD: Viewport = Viewport {
    width: 1920,
    height: 1080,
};

const JUDGED: Viewport = Viewport {
    width: 320,
    height: 240,
};

/// The sphere on the plane, both dimpled by the height form at `strength`, displaced or not.
fn scene(strength: f32, displace: bool) -> Scene {
    let object = |surface: &str, color: &str| {
        format!(
            "[[object]]\nsurface = {surface}\nmaterial = {{ color = {color} }}\n\
             bump = {{ pattern = \"dimples\", strength = {strength} }}\ndisplace = {displace}\n"
        )
    };
    let text = format!(
        "name = \"dimples-height\"\nbackground = [0.02, 0.02, 0.02]\nambient = [0.08, 0.08, 0.08]\n\
         [camera]\neye = [0, 260, 620]\ntarget = [0, 70, 0]\nup = [0, 1, 0]\nfov = 40\n\
         [[light]]\npoint = {{ position = [-400, 600, 500], color = [0.9, 0.9, 0.9] }}\n{}{}",
        object(
            "{ plane = { origin = [-600, 0, 600], normal = [0, 1, 0], u-axis = [1, 0, 0], size = [1200, 1200] } }",
            "[0.55, 0.6, 0.7]"
        ),
        object(
            "{ sphere = { center = [0, 100, 0], radius = 100 } }",
            "[0.8, 0.45, 0.3]"
        ),
    );
    parse_scene(&text, "bench").expect("a valid scene")
}

fn timed(quality: &Quality) {
    let runs = runs_or(5);
    let (bumped, displaced) = (scene(1.0, false), scene(1.0, true));
    let mut bump_frame = || {
        let picture = frame(&bumped, quality, FULL_HD, Showing::default()).expect("fits");
        std::hint::black_box(picture);
    };
    let mut displaced_frame = || {
        let picture = frame(&displaced, quality, FULL_HD, Showing::default()).expect("fits");
        std::hint::black_box(picture);
    };
    let times = Timing::interleaved(
        1,
        runs,
        &mut [(0, &mut bump_frame), (0, &mut displaced_frame)],
    );
    let (ratio, low, high) = ratio_by_round(&times[1], &times[0]);
    println!(
        "1920x1080, 1 sample, {runs} rounds: Blinn's bump {}, displaced {}: {ratio:.1}x the time \
         (rounds {low:.1}-{high:.1}x)",
        Timing::from_samples(times[0].clone()).summary_ms(),
        Timing::from_samples(times[1].clone()).summary_ms(),
    );
}

/// The raster frame of `scene` with `quality`, and the reference's for the same program.
fn judged(scene: &Scene, quality: &Quality) -> (Framebuffer, Framebuffer) {
    let camera = &scene.camera;
    let prepared = quality
        .prepare(scene.clone(), camera, JUDGED, 0)
        .expect("fits");
    let shader = quality.shader(&prepared, camera, JUDGED);
    let raster = render_with(&prepared, &quality.target(camera, JUDGED), &shader).0;
    let reference = render_reference(&prepared, camera, JUDGED, &shader).0;
    (raster, reference)
}

fn trade(quality: &Quality) {
    println!(
        "{}x{}, against the exact judge of the displaced surface:",
        JUDGED.width, JUDGED.height
    );
    println!("  strength  displaced dB  Blinn dB (coverage off)  full normal dB (coverage off)");
    for strength in [0.125, 0.25, 0.5, 1.0, 2.0, 4.0] {
        let (displaced, truth) = judged(&scene(strength, true), quality);
        let bump = |form: NormalForm| {
            let quality = Quality {
                normal_form: form,
                ..*quality
            };
            let (bumped, _) = judged(&scene(strength, false), &quality);
            (psnr(&bumped, &truth), silhouette_mismatch(&bumped, &truth))
        };
        let (blinn, full) = (bump(NormalForm::Blinn), bump(NormalForm::Full));
        println!(
            "  {strength:>8}  {:>12.1}  {:>8.1} ({:>5} px)       {:>8.1} ({:>5} px)",
            psnr(&displaced, &truth),
            blinn.0,
            blinn.1,
            full.0,
            full.1
        );
    }
}

fn main() {
    let quality = Quality::interactive();
    timed(&quality);
    trade(&quality);
}
