//! Batch evaluator: runs a compiled program over chunks of fragments in structure-of-arrays form.
//! The instruction loop is outside, the fragment loop inside, so each op is a tight loop over
//! `CHUNK` lanes with no allocation, boxing or tree walking.
//!
//! Numbers are `f64`: `t` reaches 1e7 s, where an `f32` step is a whole second (so `sin(t)` would
//! be noise), and floored `mod` of large coordinates needs the extra bits to keep a 30-unit period
//! accurate to 1e-3. Inputs and outputs stay `f32` for the renderer.

use super::check::Input;
use super::compile::{Program, Source};
use super::dual::{Dual, Scalar};
use super::ops::{Op, apply};

/// Fragments evaluated together; slots are `CHUNK` lanes wide.
pub const CHUNK: usize = 64;

/// The per-fragment inputs of a batch, structure-of-arrays. `u` and `v` are always read; the
/// point `x, y, z` only if the pattern uses it (`Pattern::uses_point`), and its partials
/// `x_u … z_v` only when a height pattern's gradient is evaluated. Unused slices may be empty.
#[derive(Clone, Copy, Debug, Default)]
pub struct Inputs<'a> {
    pub u: &'a [f32],
    pub v: &'a [f32],
    pub x: &'a [f32],
    pub y: &'a [f32],
    pub z: &'a [f32],
    pub x_u: &'a [f32],
    pub x_v: &'a [f32],
    pub y_u: &'a [f32],
    pub y_v: &'a [f32],
    pub z_u: &'a [f32],
    pub z_v: &'a [f32],
    /// Seconds; the same for the whole batch; its derivative is 0. `f64` because an animation
    /// clock of 1e7 s has a step of a whole second in `f32`.
    pub t: f64,
}

impl<'a> Inputs<'a> {
    /// Inputs for patterns that read only `u`, `v` and `t`.
    pub fn uv(u: &'a [f32], v: &'a [f32], t: f64) -> Inputs<'a> {
        Inputs {
            u,
            v,
            t,
            ..Inputs::default()
        }
    }
}

/// Reusable working memory for evaluation. Grows on first use to fit the program; reuse it across
/// calls (one per thread) so evaluation never allocates.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    values: Vec<f64>,
    duals: Vec<Dual>,
}

impl Scratch {
    pub fn new() -> Scratch {
        Scratch::default()
    }

    pub(crate) fn lanes<T: Lane>(&mut self, slots: usize) -> &mut [T] {
        let storage = T::storage(self);
        if storage.len() < slots * CHUNK {
            storage.resize(slots * CHUNK, T::default());
        }
        &mut storage[..slots * CHUNK]
    }
}

/// A scalar type with its own storage in `Scratch`.
pub(crate) trait Lane: Scalar {
    fn storage(scratch: &mut Scratch) -> &mut Vec<Self>;
}

impl Lane for f64 {
    fn storage(scratch: &mut Scratch) -> &mut Vec<f64> {
        &mut scratch.values
    }
}

impl Lane for Dual {
    fn storage(scratch: &mut Scratch) -> &mut Vec<Dual> {
        &mut scratch.duals
    }
}

/// Fills the slots that hold the same value for every fragment of a call: params and constants.
pub(crate) fn load_uniforms<T: Scalar>(
    program: &Program,
    param: impl Fn(usize) -> f64,
    t: f64,
    slots: &mut [T],
) {
    for (slot, source) in program.sources.iter().enumerate() {
        let value = match *source {
            Source::Param(p) => param(p),
            Source::Constant(c) => c,
            Source::Input(Input::T) => t,
            _ => continue,
        };
        slots[slot * CHUNK..(slot + 1) * CHUNK].fill(T::constant(value));
    }
}

/// Loads the per-fragment inputs of fragments `start..start + n` into their slots.
pub(crate) fn load_inputs<T: Scalar>(
    program: &Program,
    inputs: &Inputs,
    start: usize,
    n: usize,
    slots: &mut [T],
) {
    for (slot, source) in program.sources.iter().enumerate() {
        let Source::Input(input) = *source else {
            continue;
        };
        let lanes = &mut slots[slot * CHUNK..slot * CHUNK + n];
        let range = start..start + n;
        match input {
            Input::U => seed(lanes, &inputs.u[range], None),
            Input::V => seed(lanes, &inputs.v[range], None),
            Input::X => seed(
                lanes,
                &inputs.x[range.clone()],
                partials(inputs.x_u, inputs.x_v, range, T::DUAL),
            ),
            Input::Y => seed(
                lanes,
                &inputs.y[range.clone()],
                partials(inputs.y_u, inputs.y_v, range, T::DUAL),
            ),
            Input::Z => seed(
                lanes,
                &inputs.z[range.clone()],
                partials(inputs.z_u, inputs.z_v, range, T::DUAL),
            ),
            Input::T => {}
        }
        if T::DUAL {
            seed_parameter_derivative(lanes, input);
        }
    }
}

fn partials<'a>(
    du: &'a [f32],
    dv: &'a [f32],
    range: std::ops::Range<usize>,
    wanted: bool,
) -> Option<(&'a [f32], &'a [f32])> {
    wanted.then(|| (&du[range.clone()], &dv[range]))
}

fn seed<T: Scalar>(lanes: &mut [T], values: &[f32], partials: Option<(&[f32], &[f32])>) {
    match partials {
        Some((du, dv)) => {
            for (((lane, &x), &du), &dv) in lanes.iter_mut().zip(values).zip(du).zip(dv) {
                *lane = T::input(f64::from(x), f64::from(du), f64::from(dv));
            }
        }
        None => {
            for (lane, &x) in lanes.iter_mut().zip(values) {
                *lane = T::constant(f64::from(x));
            }
        }
    }
}

/// u has ∂/∂u = 1 and v has ∂/∂v = 1.
fn seed_parameter_derivative<T: Scalar>(lanes: &mut [T], input: Input) {
    let (du, dv) = match input {
        Input::U => (1.0, 0.0),
        Input::V => (0.0, 1.0),
        _ => return,
    };
    for lane in lanes {
        *lane = T::input(lane.value(), du, dv);
    }
}

/// Runs every instruction over the first `n` lanes.
pub(crate) fn run<T: Scalar>(program: &Program, n: usize, slots: &mut [T]) {
    for instr in &program.instrs {
        let (below, rest) = slots.split_at_mut(instr.dst * CHUNK);
        let out = &mut rest[..n];
        let [a, b, c] = instr.args.map(|s| &below[s * CHUNK..s * CHUNK + n]);
        dispatch(instr.op, out, a, b, c);
    }
}

/// One monomorphised lane loop per op, so the op's `match` is resolved outside the loop.
macro_rules! lane_loops {
    ($op:expr, $out:expr, $a:expr, $b:expr, $c:expr; $($name:ident),* $(,)?) => {
        match $op {
            $(Op::$name => lanes($out, $a, $b, $c, |x, y, z| apply(Op::$name, x, y, z)),)*
        }
    };
}

fn dispatch<T: Scalar>(op: Op, out: &mut [T], a: &[T], b: &[T], c: &[T]) {
    lane_loops!(op, out, a, b, c;
        Neg, Not, Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Abs, Sign, Floor, Ceil, Fract, Exp, Log,
        Add, Sub, Mul, Div, Pow, Mod, Min, Max, Atan2, Hypot, Step, Lt, Le, Gt, Ge, Eq, Ne, And,
        Or, Noise2, Select, Clamp, Mix, Smoothstep, Hypot3, Noise3,
    );
}

#[inline(always)]
fn lanes<T: Scalar>(out: &mut [T], a: &[T], b: &[T], c: &[T], f: impl Fn(T, T, T) -> T) {
    for (((o, &x), &y), &z) in out.iter_mut().zip(a).zip(b).zip(c) {
        *o = f(x, y, z);
    }
}

#[cfg(test)]
mod tests {
    use super::super::compile::Instr;
    use super::*;

    /// slot 0 = u, slot 1 = constant 3, slot 2 = u * 3, slot 3 = sin(slot 2)
    fn program() -> Program {
        Program {
            sources: vec![
                Source::Input(Input::U),
                Source::Constant(3.0),
                Source::Computed,
                Source::Computed,
            ],
            instrs: vec![
                Instr {
                    op: Op::Mul,
                    dst: 2,
                    args: [0, 1, 0],
                },
                Instr {
                    op: Op::Sin,
                    dst: 3,
                    args: [2, 2, 2],
                },
            ],
            outputs: vec![3],
        }
    }

    #[test]
    fn runs_instructions_over_the_lanes_with_derivatives() {
        let program = program();
        let u = [0.5f32, 1.0, 2.0];
        let mut scratch = Scratch::new();
        let slots = scratch.lanes::<Dual>(4);
        load_uniforms(&program, |_| 0.0, 0.0, slots);
        load_inputs(&program, &Inputs::uv(&u, &u, 0.0), 0, 3, slots);
        run(&program, 3, slots);
        for (i, &u) in u.iter().enumerate() {
            let r = slots[3 * CHUNK + i];
            let u = f64::from(u);
            assert_eq!(r.value, (3.0 * u).sin());
            assert_eq!(r.du, 3.0 * (3.0 * u).cos());
            assert_eq!(r.dv, 0.0);
        }
    }

    #[test]
    fn value_lanes_ignore_missing_point_partials() {
        let mut program = program();
        program.sources[0] = Source::Input(Input::X);
        let x = [1.0f32; 70];
        let inputs = Inputs {
            x: &x,
            ..Inputs::default()
        };
        let mut scratch = Scratch::new();
        let slots = scratch.lanes::<f64>(4);
        load_uniforms(&program, |_| 0.0, 0.0, slots);
        load_inputs(&program, &inputs, 64, 6, slots);
        run(&program, 6, slots);
        assert_eq!(slots[3 * CHUNK + 5], 3.0f64.sin());
    }
}
