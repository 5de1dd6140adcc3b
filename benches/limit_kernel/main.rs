//! bumpwork against the limit kernel (`kernel.rs`) on the POV-Ray peer's 1920×1080 frame at one
//! sample: first how close the kernel's picture is to ours (PSNR: the same frame, not a
//! cheaper one), then both timed in one run, taking turns, on the scene with all its parts and
//! with them taken off one at a time (shadows, the gravel bump, the photograph, the dimples,
//! the checks). A part's cost is the frame with it less the frame without; its ratio says
//! where our time goes beyond the floor. Ours is the PNG still as `peer_povray` times it; the
//! PNG encoding's share is that still less the same still written as a PPM.
//!
//! Run: `cargo bench --bench limit_kernel` (BUMPWORK_BENCH_RUNS rounds, 5 by default;
//! BUMPWORK_KERNEL_PNG=FILE also writes the kernel's frame there);
//! `cargo bench --bench limit_kernel -- kernel N` renders only the kernel's frame N times, for a
//! profiler.

#[path = "../bench_support/mod.rs"]
mod bench_support;
mod kernel;

use bench_support::{PeerStill, pov_peer_files, pov_peer_settings};
use bumpwork::export::StillFormat;
use bumpwork::measure::{Timing, ratio_by_round};
use bumpwork::scene::Scene;
use kernel::PeerKernel;
use std::path::Path;
use std::time::Duration;

const SIZE: (u32, u32) = (1920, 1080);

fn runs() -> usize {
    bench_support::runs_or(5)
}

/// The scene with all its parts, then with one more taken off at each step: each step's name
/// is the part it takes off.
fn variants(full: &Scene) -> Vec<(&'static str, Scene)> {
    let mut scene = full.clone();
    let mut out = vec![("everything", scene.clone())];
    type TakeOff = fn(&mut Scene);
    let steps: [(&str, TakeOff); 5] = [
        ("shadows", |s| s.shadows = false),
        ("gravel bump (sphere)", |s| {
            s.objects[1].material.bump = None
        }),
        ("photograph (sphere)", |s| {
            s.objects[1].material.texture = None
        }),
        ("dimples bump (floor)", |s| {
            s.objects[0].material.bump = None
        }),
        ("checks (floor)", |s| s.objects[0].material.texture = None),
    ];
    for (part, take_off) in steps {
        take_off(&mut scene);
        out.push((part, scene.clone()));
    }
    out
}

/// `kernel N`: only the kernel's frame, N times (for a profiler).
fn kernel_only() -> Option<usize> {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    match args.as_slice() {
        [mode, frames] if mode == "kernel" => frames.parse().ok(),
        _ => None,
    }
}

fn psnr(a: &[[u8; 3]], b: &[[u8; 3]]) -> f64 {
    let squared: f64 = a
        .iter()
        .zip(b)
        .flat_map(|(a, b)| (0..3).map(move |c| (a[c] as f64 - b[c] as f64).powi(2)))
        .sum();
    let mse = squared / (3 * a.len()) as f64;
    10.0 * (255.0f64 * 255.0 / mse).log10()
}

fn main() {
    let temp = tempfile::tempdir().expect("a temporary directory");
    let dir = temp.path().to_path_buf();
    let (_, _, full) = pov_peer_files(&dir);
    if let Some(frames) = kernel_only() {
        let kernel = PeerKernel::new(&full, SIZE);
        let mut frame = vec![[0u8; 3]; pixel_count()];
        (0..frames).for_each(|_| kernel.render(&mut frame));
    } else {
        let steps: Vec<_> = variants(&full)
            .into_iter()
            .map(|(part, scene)| {
                let ours = PeerStill::new(scene.clone(), String::new(), pov_peer_settings(1, None));
                (part, PeerKernel::new(&scene, SIZE), ours)
            })
            .collect();
        println!(
            "{}x{} POV-Ray peer frame, 1 sample; {} rounds. Kernel against our still: {:.1} dB",
            SIZE.0,
            SIZE.1,
            runs(),
            same_frame(&steps[0].1, &steps[0].2, &dir)
        );
        report(&steps, &time_parts(&steps, &dir));
    }
}

fn pixel_count() -> usize {
    (SIZE.0 * SIZE.1) as usize
}

/// The PSNR of the kernel's frame against our still (written into `dir`); the kernel's frame
/// also goes to BUMPWORK_KERNEL_PNG if that is set.
fn same_frame(kernel: &PeerKernel, ours: &PeerStill, dir: &Path) -> f64 {
    let mut frame = vec![[0u8; 3]; pixel_count()];
    kernel.render(&mut frame);
    let png = dir.join("ours.png");
    ours.write(&png, StillFormat::Png);
    let ours_frame: Vec<[u8; 3]> = image::open(&png)
        .expect("our still")
        .to_rgb8()
        .pixels()
        .map(|p| p.0)
        .collect();
    if let Some(path) = std::env::var_os("BUMPWORK_KERNEL_PNG") {
        let flat: Vec<u8> = frame.iter().flatten().copied().collect();
        image::save_buffer(&path, &flat, SIZE.0, SIZE.1, image::ColorType::Rgb8).expect("png");
    }
    psnr(&ours_frame, &frame)
}

/// Every step's kernel frame and our still, then our full still as a PPM, taking turns round
/// by round: their times, in that order.
fn time_parts(steps: &[(&str, PeerKernel, PeerStill)], dir: &Path) -> Vec<Vec<Duration>> {
    let (png, ppm) = (dir.join("ours.png"), dir.join("ours.ppm"));
    let mut works: Vec<Box<dyn FnMut()>> = Vec::new();
    for (_, kernel, ours) in steps {
        let mut frame = vec![[0u8; 3]; pixel_count()];
        works.push(Box::new(move || kernel.render(&mut frame)));
        let png = png.clone();
        works.push(Box::new(move || ours.write(&png, StillFormat::Png)));
    }
    let ours_full = &steps[0].2;
    works.push(Box::new(|| ours_full.write(&ppm, StillFormat::Ppm)));
    let mut turns: Vec<(usize, &mut dyn FnMut())> = works
        .iter_mut()
        .map(|w| (1, &mut **w as &mut dyn FnMut()))
        .collect();
    Timing::interleaved(1, runs(), &mut turns)
}

/// The whole frames, then each part's cost in both and their ratio.
fn report(steps: &[(&str, PeerKernel, PeerStill)], times: &[Vec<Duration>]) {
    let (kernel_full, ours_full, ours_ppm) = (&times[0], &times[1], &times[times.len() - 1]);
    let (ratio, least, most) = ratio_by_round(ours_full, kernel_full);
    println!(
        "  whole frame: ours {}   kernel {}   ours takes {ratio:.2}x (rounds {least:.2}–{most:.2}x)",
        Timing::from_samples(ours_full.clone()).summary_ms(),
        Timing::from_samples(kernel_full.clone()).summary_ms(),
    );
    let median = |samples: Vec<f64>| {
        let mut samples = samples;
        samples.sort_by(f64::total_cmp);
        samples[samples.len() / 2]
    };
    // A part's cost, round by round: the frame with it less the frame without.
    let cost = |with: &[Duration], without: &[Duration]| {
        median(
            with.iter()
                .zip(without)
                .map(|(a, b)| a.as_secs_f64() * 1e3 - b.as_secs_f64() * 1e3)
                .collect(),
        )
    };
    println!(
        "  {:<24} {:>10} {:>10} {:>8}",
        "part", "ours ms", "kernel ms", "ratio"
    );
    for (step, (part, _, _)) in steps.iter().enumerate().skip(1) {
        let (with, without) = (2 * (step - 1), 2 * step);
        let kernel = cost(&times[with], &times[without]);
        let ours = cost(&times[with + 1], &times[without + 1]);
        println!(
            "  {part:<24} {ours:>10.2} {kernel:>10.2} {:>7.1}x",
            ours / kernel
        );
    }
    let last = 2 * (steps.len() - 1);
    let (kernel_base, ours_base) = (&times[last], &times[last + 1]);
    let base = |t: &[Duration]| median(t.iter().map(|d| d.as_secs_f64() * 1e3).collect());
    println!(
        "  {:<24} {:>10.2} {:>10.2} {:>7.1}x",
        "the rest (plain objects)",
        base(ours_base),
        base(kernel_base),
        base(ours_base) / base(kernel_base)
    );
    println!(
        "  {:<24} {:>10.2} {:>10} (the PNG still less the PPM one)",
        "PNG encoding",
        cost(ours_full, ours_ppm),
        "-"
    );
}
