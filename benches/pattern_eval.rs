//! Fragments per second of the pattern interpreter against the same patterns hand-written in
//! Rust, over the same SoA batches, with derivatives (height + gradient) and without (height
//! only); then the noise patterns (gradient, cellular and fractal noise) against the dimples,
//! both interpreted, in the same runs; and the dimples' gradient against the same program fused
//! by hand into one lane loop in `f32` (the renderer's precision for it), eight fragments per
//! instruction: what compiling patterns to straight-line lane code could reach at best. Prints
//! medians over several runs with their min..max spread.
//!
//! `cargo bench --bench pattern_eval`

use std::hint::black_box;
use std::time::Instant;

use bumpwork::pattern::{BumpSample, Inputs, Pattern, builtin, native};

const BATCH: usize = 4096;
const BATCHES_PER_RUN: usize = 128;
const RUNS: usize = 9;

struct Case {
    name: &'static str,
    gradient: fn(f64, f64) -> (f64, f64, f64),
    height: fn(f64, f64) -> f64,
}

const CASES: [Case; 3] = [
    Case {
        name: "dimples",
        gradient: native::dimples,
        height: native::dimples_height,
    },
    Case {
        name: "waffle",
        gradient: native::waffle,
        height: native::waffle_height,
    },
    Case {
        name: "ripples",
        gradient: native::ripples,
        height: native::ripples_height,
    },
];

/// A 64×64 tile of fragments spread over the seed's 400×400 plane.
fn tile() -> (Vec<f32>, Vec<f32>) {
    let side = (BATCH as f64).sqrt() as usize;
    let coord = |i: usize| (i as f32 + 0.37) * 400.0 / side as f32;
    (0..BATCH)
        .map(|i| (coord(i % side), coord(i / side)))
        .unzip()
}

/// Median, min and max fragments/s of `interpreted` and `native` (one call = one batch).
/// Runs alternate between the two, so load from other processes hits both alike.
fn measure(mut interpreted: impl FnMut(), mut native: impl FnMut()) -> [[f64; 3]; 2] {
    let mut rates = [Vec::new(), Vec::new()];
    for _ in 0..RUNS {
        rates[0].push(rate(&mut interpreted));
        rates[1].push(rate(&mut native));
    }
    rates.map(|mut r| {
        r.sort_by(f64::total_cmp);
        [r[RUNS / 2], r[0], r[RUNS - 1]]
    })
}

fn rate(work: &mut impl FnMut()) -> f64 {
    work(); // warm caches and scratch
    let start = Instant::now();
    for _ in 0..BATCHES_PER_RUN {
        work();
    }
    (BATCH * BATCHES_PER_RUN) as f64 / start.elapsed().as_secs_f64()
}

fn row(pattern: &str, mode: &str, interpreted: [f64; 3], native: [f64; 3]) {
    let m = |r: [f64; 3]| {
        format!(
            "{:>7.1} ({:>5.1}..{:>5.1})",
            r[0] / 1e6,
            r[1] / 1e6,
            r[2] / 1e6
        )
    };
    println!(
        "{pattern:<9} {mode:<9} {:>26} {:>26} {:>8.2}x",
        m(interpreted),
        m(native),
        native[0] / interpreted[0]
    );
}

/// The two sides must compute the same pattern, or the comparison means nothing.
fn assert_same(name: &str, interpreted: Vec<f32>, native: Vec<f32>) {
    let worst = interpreted
        .iter()
        .zip(&native)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert!(
        worst < 1e-3,
        "{name}: interpreted and native differ by {worst}"
    );
}

fn main() {
    let (u, v) = tile();
    let inputs = Inputs::uv(&u, &v, 0.0);
    let mut samples = vec![BumpSample::default(); BATCH];
    let mut native_samples = samples.clone();
    let mut heights = vec![0.0f32; BATCH];
    let mut native_heights = heights.clone();
    println!(
        "{BATCH} fragments per batch, {BATCHES_PER_RUN} batches per run, median of {RUNS} runs"
    );
    println!(
        "{:<9} {:<9} {:>26} {:>26} {:>9}",
        "pattern", "mode", "interpreted Mfrag/s", "native Mfrag/s", "ratio"
    );
    for case in CASES {
        let source = builtin(case.name).expect("shipped pattern");
        let pattern = Pattern::compile(source, case.name).expect("shipped pattern compiles");
        let mut scratch = pattern.scratch();
        let [interpreted, hand_written] = measure(
            || {
                pattern.eval_bump(&inputs, &[], &mut scratch, &mut samples);
                black_box(&samples);
            },
            || {
                native::eval_bump(case.gradient, &u, &v, &mut native_samples);
                black_box(&native_samples);
            },
        );
        row(case.name, "gradient", interpreted, hand_written);
        let flat = |s: &[BumpSample]| s.iter().flat_map(|s| [s.height, s.du, s.dv]).collect();
        assert_same(case.name, flat(&samples), flat(&native_samples));
        let [interpreted, hand_written] = measure(
            || {
                pattern.eval_height(&inputs, &[], &mut scratch, &mut heights);
                black_box(&heights);
            },
            || {
                native::eval_height(case.height, &u, &v, &mut native_heights);
                black_box(&native_heights);
            },
        );
        row(case.name, "value", interpreted, hand_written);
        assert_same(case.name, heights.clone(), native_heights.clone());
    }
    noise_patterns(&inputs);
    fused_dimples(&u, &v, &inputs);
}

/// The interpreter's dimples with gradient, in its default precision (`f32` lanes), against
/// `dimples_fused`.
fn fused_dimples(u: &[f32], v: &[f32], inputs: &Inputs) {
    let pattern =
        Pattern::compile(builtin("dimples").expect("shipped"), "dimples").expect("compiles");
    let mut scratch = pattern.scratch();
    let mut samples = vec![BumpSample::default(); BATCH];
    let mut fused = samples.clone();
    println!();
    println!(
        "{:<9} {:<9} {:>26} {:>26} {:>9}",
        "pattern", "lanes", "interpreted Mfrag/s", "fused f32 Mfrag/s", "ratio"
    );
    let fused_in: [(&str, FusedDimples); 2] = [
        ("8 (AVX2)", dimples_fused_avx2),
        ("4 (SSE4.1)", dimples_fused_sse41),
    ];
    for (lanes, fused_dimples) in fused_in {
        let [interpreted, by_hand] = measure(
            || {
                pattern.eval_bump(inputs, &[], &mut scratch, &mut samples);
                black_box(&samples);
            },
            || {
                fused_dimples(u, v, &mut fused);
                black_box(&fused);
            },
        );
        row("dimples", lanes, interpreted, by_hand);
        let flat = |s: &[BumpSample]| s.iter().flat_map(|s| [s.height, s.du, s.dv]).collect();
        assert_same("dimples fused", flat(&samples), flat(&fused));
    }
}

/// A fused dimples: fills the samples of fragments (u, v).
type FusedDimples = fn(&[f32], &[f32], &mut [BumpSample]);

/// `dimples_fused_lanes` compiled for AVX2 (eight lanes an instruction), where the CPU has it.
fn dimples_fused_avx2(u: &[f32], v: &[f32], out: &mut [BumpSample]) {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx2") {
        #[target_feature(enable = "avx2")]
        fn avx2(u: &[f32], v: &[f32], out: &mut [BumpSample]) {
            dimples_fused_lanes(u, v, out);
        }
        // SAFETY: the CPU has just been seen to support AVX2.
        return unsafe { avx2(u, v, out) };
    }
    dimples_fused_lanes(u, v, out);
}

/// `dimples_fused_lanes` compiled for SSE4.1 (four lanes an instruction: the width of a JIT
/// that emits 128-bit vectors), where the CPU has it.
fn dimples_fused_sse41(u: &[f32], v: &[f32], out: &mut [BumpSample]) {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("sse4.1") {
        #[target_feature(enable = "sse4.1")]
        fn sse41(u: &[f32], v: &[f32], out: &mut [BumpSample]) {
            dimples_fused_lanes(u, v, out);
        }
        // SAFETY: the CPU has just been seen to support SSE4.1.
        return unsafe { sse41(u, v, out) };
    }
    dimples_fused_lanes(u, v, out);
}

/// `dimples.pat` at period 30, depth 1, with its gradient, as one loop over the fragments in
/// `f32`: the program's every step in registers, its gradient in closed form (cu/s, cv/s, where
/// the interpreter carries dual numbers through each step). Eight fragments at a time in
/// arrays, so the loop vectorises (a loop over `BumpSample`s stored one by one did not).
#[inline(always)]
fn dimples_fused_lanes(u: &[f32], v: &[f32], out: &mut [BumpSample]) {
    const LANES: usize = 8;
    let (period, half, rim) = (30.0f32, 15.0f32, 10.0f32);
    let sample = |u: f32, v: f32| {
        let centred = |x: f32| x - period * (x / period).floor() - half;
        let (cu, cv) = (centred(u), centred(v));
        let cap = half * half - cu * cu - cv * cv;
        let s = cap.sqrt();
        let inside = cap > rim * rim;
        let inner = |x: f32| if inside { x } else { 0.0 };
        [inner(rim - s), inner(cu / s), inner(cv / s)]
    };
    let n = out.len() / LANES * LANES;
    let chunks = u[..n]
        .chunks_exact(LANES)
        .zip(v[..n].chunks_exact(LANES))
        .zip(out[..n].chunks_exact_mut(LANES));
    for ((u, v), out) in chunks {
        let mut lanes = [[0.0f32; LANES]; 3];
        for k in 0..LANES {
            [lanes[0][k], lanes[1][k], lanes[2][k]] = sample(u[k], v[k]);
        }
        for (k, out) in out.iter_mut().enumerate() {
            (out.height, out.du, out.dv) = (lanes[0][k], lanes[1][k], lanes[2][k]);
        }
    }
    for ((&u, &v), out) in u[n..].iter().zip(&v[n..]).zip(&mut out[n..]) {
        [out.height, out.du, out.dv] = sample(u, v);
    }
}

/// The shipped noise patterns' fragments per second with gradients, each against the dimples
/// measured in the same runs: what a natural texture costs over the lecture's pattern.
fn noise_patterns(inputs: &Inputs) {
    let compile = |name| Pattern::compile(builtin(name).expect("shipped"), name).expect("compiles");
    let dimples = compile("dimples");
    let mut samples = vec![BumpSample::default(); BATCH];
    let mut dimple_samples = samples.clone();
    println!();
    println!(
        "{:<9} {:<9} {:>26} {:>26} {:>9}",
        "pattern", "mode", "noise Mfrag/s", "dimples Mfrag/s", "ratio"
    );
    for name in ["stucco", "cobbles", "bark"] {
        let pattern = compile(name);
        let (mut scratch, mut dimple_scratch) = (pattern.scratch(), dimples.scratch());
        let [noise, dimple] = measure(
            || {
                pattern.eval_bump(inputs, &[], &mut scratch, &mut samples);
                black_box(&samples);
            },
            || {
                dimples.eval_bump(inputs, &[], &mut dimple_scratch, &mut dimple_samples);
                black_box(&dimple_samples);
            },
        );
        row(name, "gradient", noise, dimple);
    }
}
