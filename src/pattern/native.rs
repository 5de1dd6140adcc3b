//! Hand-written Rust versions of some shipped patterns (at their default parameters), for the
//! tests to compare against and the benchmark to measure the interpreter by. Same `f64`
//! arithmetic, same SoA batches as the evaluator.

use std::f64::consts::PI;

use super::output::BumpSample;

/// The seed lecture's dimples code, with `(int)uu % 30` made a floored modulo.
/// Returns (Bu, Bv).
pub fn dimples_seed(uu: f64, vv: f64) -> (f64, f64) {
    let iu = (uu.floor() as i64).rem_euclid(30) - 15;
    let iv = (vv.floor() as i64).rem_euclid(30) - 15;
    let r2 = 225.0 - (iu * iu) as f64 - (iv * iv) as f64;
    if r2 <= 100.0 {
        return (0.0, 0.0);
    }
    let bu = if iu == 0 { 0.0 } else { iu as f64 / r2.sqrt() };
    let bv = if iv == 0 { 0.0 } else { iv as f64 / r2.sqrt() };
    (bu, bv)
}

fn floored_mod(a: f64, b: f64) -> f64 {
    a - b * (a / b).floor()
}

/// `dimples.pat`, period 30, depth 1: (height, ∂/∂u, ∂/∂v).
pub fn dimples(u: f64, v: f64) -> (f64, f64, f64) {
    let (half, rim) = (15.0, 10.0);
    let cu = floored_mod(u, 30.0) - half;
    let cv = floored_mod(v, 30.0) - half;
    let cap = half * half - cu * cu - cv * cv;
    if cap > rim * rim {
        let s = cap.sqrt();
        (rim - s, cu / s, cv / s)
    } else {
        (0.0, 0.0, 0.0)
    }
}

/// `waffle.pat`, period 40, depth 4.
pub fn waffle(u: f64, v: f64) -> (f64, f64, f64) {
    let (period, depth) = (40.0, 4.0);
    let k = PI / period;
    let (au, av) = (k * floored_mod(u, period), k * floored_mod(v, period));
    let (su, cu) = au.sin_cos();
    let (sv, cv) = av.sin_cos();
    (-depth * su * sv, -depth * k * cu * sv, -depth * k * su * cv)
}

const RIPPLE_CENTRES: [(f64, f64); 3] = [(120.0, 140.0), (280.0, 120.0), (200.0, 290.0)];

/// `ripples.pat` at t = 0, wavelength 20, amplitude 3, decay 120.
pub fn ripples(u: f64, v: f64) -> (f64, f64, f64) {
    let (amplitude, decay, k) = (3.0, 120.0, 2.0 * PI / 20.0);
    let mut sum = (0.0, 0.0, 0.0);
    for (cu, cv) in RIPPLE_CENTRES {
        let (du, dv) = (u - cu, v - cv);
        let r = du.hypot(dv);
        let (s, c) = (k * r).sin_cos();
        let fade = (-r / decay).exp();
        let slope = amplitude * fade * (-k * s - c / decay);
        let (ru, rv) = if r > 0.0 {
            (du / r, dv / r)
        } else {
            (0.0, 0.0)
        };
        sum.0 += amplitude * c * fade;
        sum.1 += slope * ru;
        sum.2 += slope * rv;
    }
    sum
}

/// Evaluates `pattern` with its gradient over a batch.
pub fn eval_bump(
    pattern: fn(f64, f64) -> (f64, f64, f64),
    u: &[f32],
    v: &[f32],
    out: &mut [BumpSample],
) {
    for ((o, &u), &v) in out.iter_mut().zip(u).zip(v) {
        let (h, du, dv) = pattern(f64::from(u), f64::from(v));
        *o = BumpSample {
            height: h as f32,
            du: du as f32,
            dv: dv as f32,
        };
    }
}

/// `dimples.pat` height only.
pub fn dimples_height(u: f64, v: f64) -> f64 {
    let cu = floored_mod(u, 30.0) - 15.0;
    let cv = floored_mod(v, 30.0) - 15.0;
    let cap = 225.0 - cu * cu - cv * cv;
    if cap > 100.0 { 10.0 - cap.sqrt() } else { 0.0 }
}

/// `waffle.pat` height only.
pub fn waffle_height(u: f64, v: f64) -> f64 {
    let k = PI / 40.0;
    -4.0 * (k * floored_mod(u, 40.0)).sin() * (k * floored_mod(v, 40.0)).sin()
}

/// `ripples.pat` height only.
pub fn ripples_height(u: f64, v: f64) -> f64 {
    let k = 2.0 * PI / 20.0;
    RIPPLE_CENTRES
        .iter()
        .map(|&(cu, cv)| {
            let r = (u - cu).hypot(v - cv);
            3.0 * (k * r).cos() * (-r / 120.0).exp()
        })
        .sum()
}

/// Evaluates a height-only `pattern` over a batch.
pub fn eval_height(pattern: fn(f64, f64) -> f64, u: &[f32], v: &[f32], out: &mut [f32]) {
    for ((o, &u), &v) in out.iter_mut().zip(u).zip(v) {
        *o = pattern(f64::from(u), f64::from(v)) as f32;
    }
}
