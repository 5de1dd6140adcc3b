//! Output stage: copies a chunk's output slots to the caller's buffer, making non-finite
//! fragments flat (height and gradient 0, colour black) and counting them.

use super::dual::Dual;
use super::eval::{CHUNK, Lane, slot};
use super::program::Program;
use super::real::Real;

/// A bump sample: height B and its gradient (Bu, Bv) = (∂B/∂u, ∂B/∂v). Slope patterns give the
/// gradient directly and report height 0.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BumpSample {
    pub height: f32,
    pub du: f32,
    pub dv: f32,
}

/// Takes a chunk's outputs out of the slots into the caller's buffer, in either precision.
pub(crate) trait Store {
    /// What the program computes for this output: plain values, or duals for a gradient.
    type Lanes<R: Real>: Lane<Real = R>;

    /// Fragments to evaluate.
    fn len(&self) -> usize;

    /// Copies the chunk holding fragments `start..` (at most `CHUNK` of them) out of `slots`;
    /// returns how many were not finite.
    fn store<R: Real>(&mut self, start: usize, slots: &[R]) -> usize;
}

/// The first `n` lanes of output slot `index`.
fn lanes<R: Real>(slots: &[R], index: usize, n: usize) -> &[R] {
    &slot::<R>(slots, index)[..n]
}

/// `values` and true if all are finite, else zeros and false: selects, not branches, so the
/// output loops vectorise.
#[inline(always)]
fn finite_or_zero<const N: usize>(values: [f32; N]) -> ([f32; N], bool) {
    let finite = values.iter().fold(true, |all, v| all & v.is_finite());
    (values.map(|v| if finite { v } else { 0.0 }), finite)
}

/// A height pattern's height and gradient.
pub(crate) struct HeightGradient<'a> {
    pub program: &'a Program,
    pub out: &'a mut [BumpSample],
}

impl Store for HeightGradient<'_> {
    type Lanes<R: Real> = Dual<R>;

    fn len(&self) -> usize {
        self.out.len()
    }

    #[inline(always)]
    fn store<R: Real>(&mut self, start: usize, slots: &[R]) -> usize {
        let out = &mut self.out[start..];
        let n = out.len().min(CHUNK);
        let lanes = slot::<Dual<R>>(slots, self.program.outputs[0]);
        let mut bad = 0;
        for (i, o) in out[..n].iter_mut().enumerate() {
            let d = Dual::get(lanes, i);
            let (sample, finite) = finite_or_zero([d.value, d.du, d.dv].map(R::narrow));
            bad += usize::from(!finite);
            let [height, du, dv] = sample;
            *o = BumpSample { height, du, dv };
        }
        bad
    }
}

/// A slope pattern's gradient, with height 0.
pub(crate) struct Slope<'a> {
    pub program: &'a Program,
    pub out: &'a mut [BumpSample],
}

impl Store for Slope<'_> {
    type Lanes<R: Real> = R;

    fn len(&self) -> usize {
        self.out.len()
    }

    #[inline(always)]
    fn store<R: Real>(&mut self, start: usize, slots: &[R]) -> usize {
        let out = &mut self.out[start..];
        let n = out.len().min(CHUNK);
        let bu = lanes(slots, self.program.outputs[0], n);
        let bv = lanes(slots, self.program.outputs[1], n);
        let mut bad = 0;
        for ((o, &bu), &bv) in out.iter_mut().zip(bu).zip(bv) {
            let ([du, dv], finite) = finite_or_zero([bu.narrow(), bv.narrow()]);
            bad += usize::from(!finite);
            *o = BumpSample {
                height: 0.0,
                du,
                dv,
            };
        }
        bad
    }
}

/// A height pattern's height alone.
pub(crate) struct Height<'a> {
    pub program: &'a Program,
    pub out: &'a mut [f32],
}

impl Store for Height<'_> {
    type Lanes<R: Real> = R;

    fn len(&self) -> usize {
        self.out.len()
    }

    #[inline(always)]
    fn store<R: Real>(&mut self, start: usize, slots: &[R]) -> usize {
        let out = &mut self.out[start..];
        let n = out.len().min(CHUNK);
        let mut bad = 0;
        for (o, &h) in out.iter_mut().zip(lanes(slots, self.program.outputs[0], n)) {
            let ([h], finite) = finite_or_zero([h.narrow()]);
            bad += usize::from(!finite);
            *o = h;
        }
        bad
    }
}

/// A colour pattern's linear RGB, clamped to 0..1.
pub(crate) struct Color<'a> {
    pub program: &'a Program,
    pub out: &'a mut [[f32; 3]],
}

impl Store for Color<'_> {
    type Lanes<R: Real> = R;

    fn len(&self) -> usize {
        self.out.len()
    }

    #[inline(always)]
    fn store<R: Real>(&mut self, start: usize, slots: &[R]) -> usize {
        let out = &mut self.out[start..];
        let n = out.len().min(CHUNK);
        let [r, g, b] = [0, 1, 2].map(|i| lanes(slots, self.program.outputs[i], n));
        let mut bad = 0;
        for (((o, &r), &g), &b) in out[..n].iter_mut().zip(r).zip(g).zip(b) {
            let (rgb, finite) = finite_or_zero([r.narrow(), g.narrow(), b.narrow()]);
            bad += usize::from(!finite);
            *o = rgb.map(|c| c.clamp(0.0, 1.0));
        }
        bad
    }
}
