//! bumpwork against POV-Ray 3.7 on the same scene, in one run: sphere-on-plane-dimples with a
//! checked, dimpled plane and a sphere wearing the chelsea photograph and the gravel height map,
//! at 1920×1080, without and with antialiasing (POV-Ray `-A` / `+A0.3`, bumpwork 1 / 16 samples),
//! shadows on in both. POV-Ray renders two scenes: the one `render --format pov` writes (our
//! meshes, our baked maps), so both draw the same geometry; and the same look as a POV-Ray user
//! writes it (an analytic box and sphere, POV-Ray's checker, dents and image maps). The cost of
//! bumpwork's shadows is its frame with them against the frame without. Antialiased at equal
//! error, each renderer's adaptive frame is measured against its own full supersampling: ours
//! at 16 samples, and at 9, the 3 × 3 POV-Ray takes in a pixel it refines (`+R3`, its default).
//! The renderers of a comparison take turns, round by round (this virtual machine's speed
//! drifts by tens of per cent within minutes), and each ratio is the median of the rounds'
//! ratios, with the least and greatest; times are medians with min–max.
//! Skipped (and said so) when `povray` is not installed.
//!
//! Run: `cargo bench --bench peer_povray`.

mod bench_support;

use bench_support::{pov_peer_files, pov_peer_settings, write_native_pov_scene};
use bumpwork::export::{PreparedStill, StillFormat, StillPlace, write_pov};
use bumpwork::measure::{Timing, ratio_by_round};
use bumpwork::raster::Viewport;
use bumpwork::scene::Camera;
use bumpwork::scene::PreparedScene;
use bumpwork::still::{BandBuffers, BandJob, StillSettings, Supersampling, render_supersampled};
use std::process::Command;
use std::time::Duration;

const SIZE: (u32, u32) = (1920, 1080);

fn runs() -> usize {
    bench_support::runs_or(3)
}

/// The adaptive supersampling contrast the peer is run with.
const ADAPTIVE: f32 = 0.05;

fn main() {
    if Command::new("povray").arg("--version").output().is_err() {
        println!("povray is not installed (Debian package `povray`): peer benchmark skipped");
        return;
    }
    let temp = tempfile::tempdir().expect("a temporary directory");
    let dir = temp.path().to_path_buf();
    let (scene_path, text, scene) = pov_peer_files(&dir);
    let camera = scene.camera.clone();
    let base = pov_peer_settings(1, None);
    let prepared = base.prepare(scene, &camera).unwrap();
    let pov = dir.join("peer.pov");
    write_pov(&prepared, &camera, SIZE, 0.0, &pov).expect("pov scene");
    println!(
        "{}x{} checks+dimples plane, textured bump-mapped sphere; {} runs",
        SIZE.0,
        SIZE.1,
        runs()
    );
    write_native_pov_scene(&dir, &prepared.scene, SIZE);
    let povray = |antialias: &'static str, scene: &'static str| {
        let dir = dir.clone();
        move || run_povray(&dir, scene, &[antialias], "pov.png")
    };
    let request = pov_peer_settings;
    let source = (scene_path.display().to_string(), text);
    let unshadowed = PreparedScene {
        scene: bumpwork::scene::Scene {
            shadows: false,
            ..prepared.scene.clone()
        },
        objects: prepared.objects.iter().map(clone_object).collect(),
        notices: Vec::new(),
    };
    let unshadowed = PreparedStill::from_prepared((&source.0, &source.1), unshadowed, &camera);
    let prepared = PreparedStill::from_prepared((&source.0, &source.1), prepared, &camera);
    let ours_of = |still: &PreparedStill, settings: &StillSettings| {
        let out = dir.join("ours.png");
        let destination = (out.as_path(), StillFormat::Png);
        (still)
            .write(
                *settings,
                StillPlace::default(),
                destination,
                &mut |_| {},
                &|| None,
            )
            .expect("still");
    };
    let ours = |settings: &StillSettings| ours_of(&prepared, settings);
    let report = |label: &str, pov: &[Duration], ours: &[Duration]| {
        let (ratio, least, most) = ratio_by_round(pov, ours);
        println!(
            "  {label:<40} {}   POV-Ray {}   {ratio:.1}x faster (rounds {least:.1}–{most:.1}x)",
            Timing::from_samples(ours.to_vec()).summary_ms(),
            Timing::from_samples(pov.to_vec()).summary_ms(),
        );
    };
    // Each comparison's renderers take turns after a warm-up round, so drift slows them alike;
    // each of our stills (tenths of a second) settles with one unmeasured run first, as
    // POV-Ray's seconds-long runs do within themselves.
    let one_sample = request(1, None);
    let (mut pov_plain, mut pov_native) = (povray("-A", "peer.pov"), povray("-A", "native.pov"));
    let mut ours_plain = || ours(&one_sample);
    let mut ours_unshadowed = || ours_of(&unshadowed, &one_sample);
    let times = Timing::interleaved(
        1,
        runs(),
        &mut [
            (0, &mut pov_plain),
            (0, &mut pov_native),
            (1, &mut ours_plain),
            (1, &mut ours_unshadowed),
        ],
    );
    report("bumpwork 1 spp vs -A (our meshes)", &times[0], &times[2]);
    report("bumpwork 1 spp vs -A (native scene)", &times[1], &times[2]);
    let (with, without) = (
        Timing::from_samples(times[2].clone()),
        Timing::from_samples(times[3].clone()),
    );
    let (ratio, least, most) = ratio_by_round(&times[2], &times[3]);
    println!(
        "  shadows: {} with, {} without: {:.1}% of the frame (rounds {:.1}–{:.1}%)",
        with.summary_ms(),
        without.summary_ms(),
        100.0 * (1.0 - 1.0 / ratio),
        100.0 * (1.0 - 1.0 / least),
        100.0 * (1.0 - 1.0 / most),
    );

    let errors = adaptive_errors(prepared.prepared(), &camera, 16);
    // POV-Ray's `+A` takes 3 × 3 samples in a pixel it refines (its default `+R3`): the same
    // comparison with as many of ours.
    let errors_9 = adaptive_errors(prepared.prepared(), &camera, 9);
    for (scene, label) in [("peer.pov", "our meshes"), ("native.pov", "native scene")] {
        let pov_aa_error = povray_error(&dir, scene);
        println!(
            "  POV-Ray +A0.3 against its own +A0.0 ({label}, every pixel supersampled): {}",
            pov_aa_error.describe()
        );
        // The cheapest contrast whose error is nowhere worse than POV-Ray's own adaptive error.
        let equal_error = |errors: &[(f32, ChannelError)]| {
            errors
                .iter()
                .rev()
                .find(|(_, error)| error.no_worse_than(&pov_aa_error))
                .map(|&(contrast, _)| contrast)
        };
        let (equal_error, equal_error_9) = (equal_error(&errors), equal_error(&errors_9));
        let (full, adaptive) = (request(16, None), request(16, Some(ADAPTIVE)));
        let equal = equal_error.map(|contrast| request(16, Some(contrast)));
        let equal_9 = equal_error_9.map(|contrast| request(9, Some(contrast)));
        let (mut pov_aa, mut ours_full) = (povray("+A0.3", scene), || ours(&full));
        let (mut ours_adaptive, mut ours_equal) =
            (|| ours(&adaptive), || equal.iter().for_each(ours));
        let mut ours_equal_9 = || equal_9.iter().for_each(ours);
        let mut works: Vec<(usize, &mut dyn FnMut())> = vec![
            (0, &mut pov_aa),
            (1, &mut ours_full),
            (1, &mut ours_adaptive),
            (1, &mut ours_equal),
            (1, &mut ours_equal_9),
        ];
        let times = Timing::interleaved(1, runs(), &mut works);
        report(&format!("16 spp vs +A0.3 ({label})"), &times[0], &times[1]);
        report(
            &format!("16 spp adaptive {ADAPTIVE} vs +A0.3 ({label})"),
            &times[0],
            &times[2],
        );
        for (samples, contrast, times_ours) in
            [(16, equal_error, &times[3]), (9, equal_error_9, &times[4])]
        {
            match contrast {
                Some(contrast) => report(
                    &format!("{samples} spp adaptive {contrast}, error <= POV ({label})"),
                    &times[0],
                    times_ours,
                ),
                None => println!(
                    "  no adaptive contrast tried at {samples} spp is as accurate as POV-Ray's +A0.3"
                ),
            }
        }
    }
}

/// A prepared object again (its mesh copied), for a scene that differs only in its settings.
fn clone_object(object: &bumpwork::scene::PreparedObject) -> bumpwork::scene::PreparedObject {
    bumpwork::scene::PreparedObject {
        surface: object.surface.clone(),
        material: object.material.clone(),
        mesh: object.mesh.clone(),
    }
}

/// Contrasts of adaptive supersampling measured against full supersampling, least first.
const CONTRASTS: [f32; 11] = [
    0.02, ADAPTIVE, 0.07, 0.08, 0.09, 0.1, 0.11, 0.12, 0.15, 0.2, 0.3,
];

/// How far an antialiased frame lands from its renderer's full supersampling, in 8-bit sRGB
/// steps over every channel.
struct ChannelError {
    mean: f64,
    max: u32,
    /// Share of channels within 2 steps.
    within_2: f64,
}

impl ChannelError {
    fn between(reference: &[[u8; 3]], frame: &[[u8; 3]]) -> ChannelError {
        assert_eq!(reference.len(), frame.len(), "frames of one size");
        let errors: Vec<u32> = reference
            .iter()
            .zip(frame)
            .flat_map(|(a, b)| (0..3).map(move |c| a[c].abs_diff(b[c]) as u32))
            .collect();
        ChannelError {
            mean: errors.iter().sum::<u32>() as f64 / errors.len() as f64,
            max: errors.iter().copied().max().unwrap_or(0),
            within_2: errors.iter().filter(|&&e| e <= 2).count() as f64 / errors.len() as f64,
        }
    }

    fn no_worse_than(&self, other: &ChannelError) -> bool {
        self.mean <= other.mean && self.within_2 >= other.within_2
    }

    fn describe(&self) -> String {
        format!(
            "mean {:.3}, max {} of 255 per channel, {:.2}% of channels within 2",
            self.mean,
            self.max,
            100.0 * self.within_2
        )
    }
}

/// Renders `scene` in `dir` at `SIZE` with `options` into `out`, without a window.
fn run_povray(dir: &std::path::Path, scene: &str, options: &[&str], out: &str) {
    let status = Command::new("povray")
        .args([&format!("+W{}", SIZE.0), &format!("+H{}", SIZE.1)])
        .args(options)
        .args(["-D", "-GA", &format!("+O{out}"), scene])
        .current_dir(dir)
        .output()
        .expect("povray runs");
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
}

/// POV-Ray's `+A0.3` frame against its `+A0.0` one, which supersamples every pixel that differs
/// from a neighbour at all. Both without jitter (`-J`), so a pixel supersampled in both is
/// sampled at the same points and the difference is the adaptive choice alone.
fn povray_error(dir: &std::path::Path, scene: &str) -> ChannelError {
    let render = |antialias: &str, out: &str| {
        run_povray(dir, scene, &[antialias, "-J"], out);
        let image = image::open(dir.join(out)).expect("POV-Ray's PNG").to_rgb8();
        image.pixels().map(|p| p.0).collect::<Vec<[u8; 3]>>()
    };
    ChannelError::between(
        &render("+A0.0", "pov-full.png"),
        &render("+A0.3", "pov-aa.png"),
    )
}

/// The pixels a one-sample frame leaves more than 2 steps (of 255) from full supersampling in
/// some channel, and what refining exactly those with all `samples` would shade: a bound
/// no contrast mask beats without settling some of them on fewer samples.
fn report_needed(full: &[[u8; 3]], samples: u32, (one_sample, fragments): (Vec<[u8; 3]>, usize)) {
    let needed = full
        .iter()
        .zip(&one_sample)
        .filter(|(a, b)| (0..3).any(|c| a[c].abs_diff(b[c]) > 2))
        .count();
    let further = samples as usize - 1;
    println!(
        "  one sample against full {samples} spp: {needed} pixels ({:.1}%) more than 2 steps off; \
         refining only those, fully, shades {:.2}x the one-sample fragments",
        100.0 * needed as f64 / full.len() as f64,
        (fragments + further * needed) as f64 / fragments as f64
    );
}

/// Adaptive supersampling at each of `CONTRASTS` against full supersampling, both at `samples`.
fn adaptive_errors(
    prepared: &PreparedScene,
    camera: &Camera,
    samples: u32,
) -> Vec<(f32, ChannelError)> {
    let base = pov_peer_settings(samples, None);
    let full = Viewport {
        width: SIZE.0,
        height: SIZE.1,
    };
    let shader = base.quality.shader(prepared, camera, full);
    let render = |supersampling, adaptive| {
        let job = BandJob {
            prepared,
            camera,
            full,
            shader: &shader,
            supersampling,
            interpolation: base.quality.interpolation,
            adaptive,
        };
        let (framebuffer, stats) = render_supersampled(&job, &mut BandBuffers::default());
        (framebuffer.to_srgb8(), stats.fragments)
    };
    let frame = |adaptive| render(base.supersampling(), adaptive);
    let (full, full_fragments) = frame(None);
    let one_sample = Supersampling {
        samples: 1,
        ..base.supersampling()
    };
    report_needed(&full, base.quality.samples, render(one_sample, None));
    CONTRASTS
        .into_iter()
        .map(|contrast| {
            let (adaptive, adaptive_fragments) = frame(Some(contrast));
            let error = ChannelError::between(&full, &adaptive);
            println!(
                "  adaptive {contrast} against full {samples} spp: {}; {:.1}% of the fragments shaded",
                error.describe(),
                100.0 * adaptive_fragments as f64 / full_fragments as f64
            );
            (contrast, error)
        })
        .collect()
}
