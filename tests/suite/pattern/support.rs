//! Shared helpers for the pattern tests: a surface map with non-trivial point partials and
//! owned SoA batches.
#![allow(dead_code)]

use bumpwork::pattern::{BumpSample, Inputs, Pattern, builtin};

/// A curved surface over (u, v) so the chain rule through x, y, z is exercised:
/// x = u - 200, y = v - 200, z = 30 sin(u/50) cos(v/70).
pub fn point(u: f64, v: f64) -> [f64; 9] {
    let z = 30.0 * (u / 50.0).sin() * (v / 70.0).cos();
    let z_u = 30.0 / 50.0 * (u / 50.0).cos() * (v / 70.0).cos();
    let z_v = -30.0 / 70.0 * (u / 50.0).sin() * (v / 70.0).sin();
    [u - 200.0, v - 200.0, z, 1.0, 0.0, 0.0, 1.0, z_u, z_v]
}

/// Owned SoA inputs for a list of (u, v).
#[derive(Default)]
pub struct Batch {
    pub u: Vec<f32>,
    pub v: Vec<f32>,
    pub p: [Vec<f32>; 9],
    pub t: f64,
}

impl Batch {
    pub fn new(points: &[(f32, f32)]) -> Batch {
        let mut batch = Batch::default();
        for &(u, v) in points {
            batch.u.push(u);
            batch.v.push(v);
            for (lane, value) in batch.p.iter_mut().zip(point(f64::from(u), f64::from(v))) {
                lane.push(value as f32);
            }
        }
        batch
    }

    pub fn inputs(&self) -> Inputs<'_> {
        let p = &self.p;
        Inputs {
            u: &self.u,
            v: &self.v,
            x: &p[0],
            y: &p[1],
            z: &p[2],
            x_u: &p[3],
            x_v: &p[4],
            y_u: &p[5],
            y_v: &p[6],
            z_u: &p[7],
            z_v: &p[8],
            t: self.t,
            ..Inputs::default()
        }
    }
}

pub fn shipped(name: &str) -> Pattern {
    Pattern::compile(builtin(name).expect("shipped pattern"), name).unwrap()
}

pub fn bump(pattern: &Pattern, points: &[(f32, f32)]) -> (Vec<BumpSample>, usize) {
    let batch = Batch::new(points);
    let mut out = vec![BumpSample::default(); points.len()];
    let mut scratch = pattern.scratch();
    let bad = pattern.eval_bump(&batch.inputs(), &[], &mut scratch, &mut out);
    (out, bad)
}

pub fn heights(pattern: &Pattern, points: &[(f32, f32)]) -> Vec<f32> {
    let batch = Batch::new(points);
    let mut out = vec![0.0; points.len()];
    let mut scratch = pattern.scratch();
    pattern.eval_height(&batch.inputs(), &[], &mut scratch, &mut out);
    out
}

pub fn colors(pattern: &Pattern, points: &[(f32, f32)]) -> Vec<[f32; 3]> {
    let batch = Batch::new(points);
    let mut out = vec![[0.0; 3]; points.len()];
    pattern.eval_color(&batch.inputs(), &[], &mut pattern.scratch(), &mut out);
    out
}

/// Deterministic pseudo-random points in [lo, hi)².
pub fn sample_points(count: usize, lo: f32, hi: f32, seed: u64) -> Vec<(f32, f32)> {
    let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        lo + (hi - lo) * ((state >> 40) as f32 / (1u64 << 24) as f32)
    };
    (0..count).map(|_| (next(), next())).collect()
}
