//! Output stage: copies a chunk's output slots to the caller's buffer, making non-finite
//! fragments flat (height and gradient 0, colour black) and counting them.

use super::compile::Program;
use super::dual::Dual;
use super::eval::{CHUNK, Lane, slot};

/// A bump sample: height B and its gradient (Bu, Bv) = (∂B/∂u, ∂B/∂v). Slope patterns give the
/// gradient directly and report height 0.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BumpSample {
    pub height: f32,
    pub du: f32,
    pub dv: f32,
}

fn lanes(slots: &[f64], index: usize, n: usize) -> &[f64] {
    &slot::<f64>(slots, index)[..n]
}

/// `values` and true if all are finite, else zeros and false: selects, not branches, so the
/// output loops vectorise (branching, they were 6% of a frame's instructions).
#[inline(always)]
fn finite_or_zero<const N: usize>(values: [f32; N]) -> ([f32; N], bool) {
    let finite = values.iter().fold(true, |all, v| all & v.is_finite());
    (values.map(|v| if finite { v } else { 0.0 }), finite)
}

#[inline(always)]
pub fn height_gradient(program: &Program, slots: &[f64], out: &mut [BumpSample]) -> usize {
    let n = out.len().min(CHUNK);
    let lanes = slot::<Dual>(slots, program.outputs[0]);
    let mut bad = 0;
    for (i, o) in out[..n].iter_mut().enumerate() {
        let d = Dual::get(lanes, i);
        let (sample, finite) = finite_or_zero([d.value as f32, d.du as f32, d.dv as f32]);
        bad += usize::from(!finite);
        let [height, du, dv] = sample;
        *o = BumpSample { height, du, dv };
    }
    bad
}

#[inline(always)]
pub fn slope(program: &Program, slots: &[f64], out: &mut [BumpSample]) -> usize {
    let n = out.len().min(CHUNK);
    let bu = lanes(slots, program.outputs[0], n);
    let bv = lanes(slots, program.outputs[1], n);
    let mut bad = 0;
    for ((o, &bu), &bv) in out.iter_mut().zip(bu).zip(bv) {
        let ([du, dv], finite) = finite_or_zero([bu as f32, bv as f32]);
        bad += usize::from(!finite);
        *o = BumpSample {
            height: 0.0,
            du,
            dv,
        };
    }
    bad
}

#[inline(always)]
pub fn height(program: &Program, slots: &[f64], out: &mut [f32]) -> usize {
    let n = out.len().min(CHUNK);
    let mut bad = 0;
    for (o, &h) in out.iter_mut().zip(lanes(slots, program.outputs[0], n)) {
        let ([h], finite) = finite_or_zero([h as f32]);
        bad += usize::from(!finite);
        *o = h;
    }
    bad
}

#[inline(always)]
pub fn color(program: &Program, slots: &[f64], out: &mut [[f32; 3]]) -> usize {
    let n = out.len().min(CHUNK);
    let [r, g, b] = [0, 1, 2].map(|i| lanes(slots, program.outputs[i], n));
    let mut bad = 0;
    for (((o, &r), &g), &b) in out[..n].iter_mut().zip(r).zip(g).zip(b) {
        let (rgb, finite) = finite_or_zero([r as f32, g as f32, b as f32]);
        bad += usize::from(!finite);
        *o = rgb.map(|c| c.clamp(0.0, 1.0));
    }
    bad
}
