//! Batch evaluator: runs a compiled program over chunks of fragments in structure-of-arrays form.
//! The instruction loop is outside, the fragment loop inside, so each op is a tight loop over
//! `CHUNK` lanes with no allocation, boxing or tree walking.
//!
//! Lanes are `f32` or `f64` (`Real`, which says when each serves). Inputs and outputs are `f32`
//! for the renderer either way.

use super::check::Input;
use super::dual::{Dual, Scalar};
use super::ops::{Op, apply, arithmetic};
use super::program::DualForm;
use super::program::{Instr, Program, Source};
use super::real::{LaneStorage, Precision, Real};
use num_traits::Zero;

/// Fragments evaluated together; slots are `CHUNK` lanes wide.
pub const CHUNK: usize = 64;

/// The per-fragment inputs of a batch, structure-of-arrays. `u` and `v` are read only if the
/// pattern uses them (`Pattern::uses_uv`), the point `x, y, z` only if it uses that
/// (`Pattern::uses_point`), and its partials
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
    pub precision: Precision,
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
    lanes: LaneStorage,
}

impl Scratch {
    pub fn new() -> Scratch {
        Scratch::default()
    }

    /// Storage for `slots` slots of `T`.
    pub(crate) fn slots<T: Lane>(&mut self, slots: usize) -> &mut [T::Real] {
        let len = slots * T::SLOT;
        let lanes = T::Real::lanes(&mut self.lanes);
        if lanes.len() < len {
            lanes.resize(len, T::Real::zero());
        }
        &mut lanes[..len]
    }
}

/// How a scalar type is laid out in a slot: structure-of-arrays, `CHUNK` values, then (for
/// duals) `CHUNK` u-partials and `CHUNK` v-partials, so every lane loop reads and writes
/// contiguous floats and vectorises.
pub(crate) trait Lane: Scalar {
    /// Floats per slot.
    const SLOT: usize;
    fn get(slot: &[Self::Real], i: usize) -> Self;
    fn set(slot: &mut [Self::Real], i: usize, value: Self);
    /// Sets the first `values.len()` lanes of `slot` to the inputs `values` with `partials`
    /// (as long, when per fragment).
    fn load(slot: &mut [Self::Real], values: &[f32], partials: Seed);
    /// Runs `instr` over the lanes: `out` is its result's slot, `operands` its operands'.
    fn run(instr: &Instr, out: &mut [Self::Real], operands: [&[Self::Real]; 4]);
    /// What `run` relies on before the per-fragment `instrs` run over `slots`: for duals, zero
    /// partials in the slots of the instructions that compute a value alone.
    fn prepare(instrs: &[Instr], slots: &mut [Self::Real]);
}

impl<R: Real> Lane for R {
    const SLOT: usize = CHUNK;

    #[inline(always)]
    fn get(slot: &[R], i: usize) -> R {
        slot[i]
    }

    #[inline(always)]
    fn set(slot: &mut [R], i: usize, value: R) {
        slot[i] = value;
    }

    #[inline(always)]
    fn load(slot: &mut [R], values: &[f32], _: Seed) {
        copy_lanes(slot, values);
    }

    #[inline(always)]
    fn run(instr: &Instr, out: &mut [R], operands: [&[R]; 4]) {
        dispatch::<R>(instr.op, out, operands);
    }

    fn prepare(_: &[Instr], _: &mut [R]) {}
}

impl<R: Real> Lane for Dual<R> {
    const SLOT: usize = 3 * CHUNK;

    #[inline(always)]
    fn get(slot: &[R], i: usize) -> Dual<R> {
        Dual::input(slot[i], slot[CHUNK + i], slot[2 * CHUNK + i])
    }

    #[inline(always)]
    fn set(slot: &mut [R], i: usize, value: Dual<R>) {
        slot[i] = value.value;
        slot[CHUNK + i] = value.du;
        slot[2 * CHUNK + i] = value.dv;
    }

    #[inline(always)]
    fn load(slot: &mut [R], values: &[f32], partials: Seed) {
        let n = values.len();
        let (value, partial) = slot.split_at_mut(CHUNK);
        let (du, dv) = partial.split_at_mut(CHUNK);
        copy_lanes(value, values);
        match partials {
            Seed::Constant(u, v) => {
                du[..n].fill(R::of_f32(u));
                dv[..n].fill(R::of_f32(v));
            }
            Seed::PerFragment(u, v) => {
                copy_lanes(du, &u[..n]);
                copy_lanes(dv, &v[..n]);
            }
        }
    }

    #[inline(always)]
    fn run(instr: &Instr, out: &mut [R], operands: [&[R]; 4]) {
        let [a, b, ..] = operands;
        match instr.form {
            DualForm::Full => dispatch::<Dual<R>>(instr.op, out, operands),
            DualForm::ValueOnly => {
                dispatch::<R>(instr.op, &mut out[..CHUNK], operands.map(|o| &o[..CHUNK]))
            }
            DualForm::FirstVaries => arithmetic_lanes::<R, true>(instr.op, out, a, b),
            DualForm::SecondVaries => arithmetic_lanes::<R, false>(instr.op, out, a, b),
            DualForm::Square => square_lanes(out, a),
        }
    }

    fn prepare(instrs: &[Instr], slots: &mut [R]) {
        for instr in instrs.iter().filter(|i| i.form == DualForm::ValueOnly) {
            slot_mut::<Self>(slots, instr.dst)[CHUNK..].fill(R::zero());
        }
    }
}

/// The storage of slot `index`.
pub(crate) fn slot<T: Lane>(slots: &[T::Real], index: usize) -> &[T::Real] {
    &slots[index * T::SLOT..(index + 1) * T::SLOT]
}

fn slot_mut<T: Lane>(slots: &mut [T::Real], index: usize) -> &mut [T::Real] {
    &mut slots[index * T::SLOT..(index + 1) * T::SLOT]
}

/// Fills the slots that hold the same value for every fragment of a call: params, constants, t.
pub(crate) fn load_uniforms<T: Lane>(
    program: &Program,
    param: impl Fn(usize) -> f64,
    t: f64,
    slots: &mut [T::Real],
) {
    for (index, source) in program.sources.iter().enumerate() {
        let value = match *source {
            Source::Param(p) => param(p),
            Source::Constant(c) => c,
            Source::Input(Input::T) => t,
            _ => continue,
        };
        let lanes = slot_mut::<T>(slots, index);
        for i in 0..CHUNK {
            T::set(lanes, i, T::constant(T::Real::of(value)));
        }
    }
}

/// Loads the per-fragment inputs of fragments `start..start + n` into their slots.
#[inline(always)]
pub(crate) fn load_inputs<T: Lane>(
    program: &Program,
    inputs: &Inputs,
    start: usize,
    n: usize,
    slots: &mut [T::Real],
) {
    let fragments = start..start + n;
    for (index, source) in program.sources.iter().enumerate() {
        let Source::Input(input) = *source else {
            continue;
        };
        let (values, partials) = match input {
            Input::U => (inputs.u, Seed::Constant(1.0, 0.0)),
            Input::V => (inputs.v, Seed::Constant(0.0, 1.0)),
            Input::X => (inputs.x, point::<T>(inputs.x_u, inputs.x_v)),
            Input::Y => (inputs.y, point::<T>(inputs.y_u, inputs.y_v)),
            Input::Z => (inputs.z, point::<T>(inputs.z_u, inputs.z_v)),
            Input::T => continue, // uniform
        };
        let partials = match partials {
            Seed::PerFragment(du, dv) => {
                Seed::PerFragment(&du[fragments.clone()], &dv[fragments.clone()])
            }
            constant => constant,
        };
        T::load(
            slot_mut::<T>(slots, index),
            &values[fragments.clone()],
            partials,
        );
    }
}

/// Partials (∂/∂u, ∂/∂v) of an input.
#[derive(Clone, Copy)]
pub(crate) enum Seed<'a> {
    Constant(f32, f32),
    PerFragment(&'a [f32], &'a [f32]),
}

/// The point's partials, read only when derivatives are wanted (else the slices may be empty).
fn point<'a, T: Lane>(du: &'a [f32], dv: &'a [f32]) -> Seed<'a> {
    if T::DUAL {
        Seed::PerFragment(du, dv)
    } else {
        Seed::Constant(0.0, 0.0)
    }
}

/// Lanes `0..values.len()` of `lanes` set to `values`, exactly, as whole slices (which the
/// compiler vectorises; a lane at a time it did not).
#[inline(always)]
fn copy_lanes<R: Real>(lanes: &mut [R], values: &[f32]) {
    for (lane, &x) in lanes[..values.len()].iter_mut().zip(values) {
        *lane = R::of_f32(x);
    }
}

/// Computes the uniform instructions (same for every fragment); once per call.
pub(crate) fn run_uniform<T: Lane>(program: &Program, slots: &mut [T::Real]) {
    run_instrs::<T>(&program.instrs[..program.uniform], slots);
}

/// Runs the per-fragment instructions.
#[cfg(test)]
fn run<T: Lane>(program: &Program, slots: &mut [T::Real]) {
    run_instrs::<T>(&program.instrs[program.uniform..], slots);
}

/// Evaluates fragments `0..len` a chunk at a time: loads a chunk's inputs, runs the
/// per-fragment instructions, and has `store(start, slots)` take its outputs (returning how
/// many were not finite). The whole loop is compiled for the widest SIMD the CPU has, so
/// loading and storing vectorise too (pass an `#[inline(always)]` `store`).
pub(crate) fn run_chunks<T: Lane>(
    program: &Program,
    inputs: &Inputs,
    len: usize,
    slots: &mut [T::Real],
    mut store: impl FnMut(usize, &[T::Real]) -> usize,
) -> usize {
    let per_fragment = &program.instrs[program.uniform..];
    T::prepare(per_fragment, slots);
    crate::simd::widest_rounding(
        #[inline(always)]
        || {
            let mut non_finite = 0;
            for start in (0..len).step_by(CHUNK) {
                let n = CHUNK.min(len - start);
                load_inputs::<T>(program, inputs, start, n, slots);
                run_instrs_here::<T>(per_fragment, slots);
                non_finite += store(start, slots);
            }
            non_finite
        },
    )
}

fn run_instrs<T: Lane>(instrs: &[Instr], slots: &mut [T::Real]) {
    crate::simd::widest_rounding(
        #[inline(always)]
        || run_instrs_here::<T>(instrs, slots),
    );
}

/// The instruction loop, inlined into `run_instrs`'s call so its lane loops are compiled for
/// the widest SIMD the CPU has. Every instruction runs over all `CHUNK` lanes, also in a
/// chunk of fewer fragments: the lanes past its end hold an earlier chunk's values (or the
/// zeros scratch starts with), are computed and never stored. The fixed trip count lets each
/// lane loop compile to straight SIMD with no remainder loop, at the cost of a part chunk per
/// group.
#[inline(always)]
fn run_instrs_here<T: Lane>(instrs: &[Instr], slots: &mut [T::Real]) {
    for instr in instrs {
        let (below, rest) = slots.split_at_mut(instr.dst * T::SLOT);
        let out = &mut rest[..T::SLOT];
        let operands = instr.args.map(|s| slot::<T>(below, s));
        T::run(instr, out, operands);
    }
}

/// One monomorphised lane loop per op, so the op's `match` is resolved outside the loop. Ops of
/// up to three operands read three slots; only `fbm` of (x, y, z) reads a fourth.
macro_rules! lane_loops {
    ($op:expr, $out:expr, $operands:expr; $($name:ident),* $(,)?) => {
        match $op {
            Op::Fbm3 => lanes4::<T>($out, $operands, |a, b, c, d| apply(Op::Fbm3, a, b, c, d)),
            $(Op::$name => {
                let [a, b, c, _] = $operands;
                lanes::<T>($out, a, b, c, |x, y, z| apply(Op::$name, x, y, z, x))
            })*
        }
    };
}

#[inline(always)]
fn dispatch<T: Lane>(op: Op, out: &mut [T::Real], operands: [&[T::Real]; 4]) {
    lane_loops!(op, out, operands;
        Neg, Not, Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Abs, Sign, Floor, Ceil, Fract, Exp, Log,
        Add, Sub, Mul, Div, Pow, Mod, Min, Max, Atan2, Hypot, Step, Lt, Le, Gt, Ge, Eq, Ne, And,
        Or, Noise2, Perlin2, Cells2, Select, Clamp, Mix, Smoothstep, Hypot3, Noise3, Perlin3,
        Cells3, Fbm2,
    );
}

#[inline(always)]
fn lanes<T: Lane>(
    out: &mut [T::Real],
    a: &[T::Real],
    b: &[T::Real],
    c: &[T::Real],
    f: impl Fn(T, T, T) -> T,
) {
    // Exact lengths let the compiler drop the bounds checks in the loop.
    let (out, a, b, c) = (
        &mut out[..T::SLOT],
        &a[..T::SLOT],
        &b[..T::SLOT],
        &c[..T::SLOT],
    );
    for i in 0..CHUNK {
        T::set(out, i, f(T::get(a, i), T::get(b, i), T::get(c, i)));
    }
}

/// An arithmetic op in dual lanes whose first (`FIRST`) or else second operand alone varies:
/// the value, and the varying operand's partials times the op's partial in it. The other
/// operand's partials are not read.
#[inline(always)]
fn arithmetic_lanes<R: Real, const FIRST: bool>(op: Op, out: &mut [R], a: &[R], b: &[R]) {
    macro_rules! each_op {
        ($($name:ident),*) => {
            match op {
                $(Op::$name => one_varies::<R, FIRST>(out, a, b, |x, y| arithmetic(Op::$name, x, y)),)*
                _ => unreachable!("{op:?} has no form with one varying operand"),
            }
        };
    }
    each_op!(Add, Sub, Mul, Div, Mod);
}

/// `arithmetic_lanes`' loop: `rule(x, y)` is the op's value and its partials in x and in y.
#[inline(always)]
fn one_varies<R: Real, const FIRST: bool>(
    out: &mut [R],
    a: &[R],
    b: &[R],
    rule: impl Fn(R, R) -> (R, R, R),
) {
    let slot = Dual::<R>::SLOT;
    let (out, a, b) = (&mut out[..slot], &a[..slot], &b[..slot]);
    let varying = if FIRST { a } else { b };
    for i in 0..CHUNK {
        let (value, pa, pb) = rule(a[i], b[i]);
        let partial = if FIRST { pa } else { pb };
        out[i] = value;
        out[CHUNK + i] = partial * varying[CHUNK + i];
        out[2 * CHUNK + i] = partial * varying[2 * CHUNK + i];
    }
}

/// `a * a` in dual lanes: the full rule's two partial terms, each the same product.
#[inline(always)]
fn square_lanes<R: Real>(out: &mut [R], a: &[R]) {
    let slot = Dual::<R>::SLOT;
    let (out, a) = (&mut out[..slot], &a[..slot]);
    for i in 0..CHUNK {
        let (value, pa, pb) = arithmetic(Op::Mul, a[i], a[i]);
        out[i] = value;
        out[CHUNK + i] = pa * a[CHUNK + i] + pb * a[CHUNK + i];
        out[2 * CHUNK + i] = pa * a[2 * CHUNK + i] + pb * a[2 * CHUNK + i];
    }
}

/// `lanes` for an op of four operands.
#[inline(always)]
fn lanes4<T: Lane>(out: &mut [T::Real], operands: [&[T::Real]; 4], f: impl Fn(T, T, T, T) -> T) {
    let out = &mut out[..T::SLOT];
    let [a, b, c, d] = operands.map(|operand| &operand[..T::SLOT]);
    for i in 0..CHUNK {
        let operand = |slot: &[T::Real]| T::get(slot, i);
        T::set(out, i, f(operand(a), operand(b), operand(c), operand(d)));
    }
}

#[cfg(test)]
mod tests {
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
                    args: [0, 1, 0, 0],
                    form: DualForm::Full,
                },
                Instr {
                    op: Op::Sin,
                    dst: 3,
                    args: [2, 2, 2, 2],
                    form: DualForm::Full,
                },
            ],
            uniform: 0,
            outputs: vec![3],
        }
    }

    #[test]
    fn runs_instructions_over_the_lanes_with_derivatives() {
        let program = program();
        let u = [0.5f32, 1.0, 2.0];
        let mut scratch = Scratch::new();
        let slots = scratch.slots::<Dual<f64>>(4);
        load_uniforms::<Dual<f64>>(&program, |_| 0.0, 0.0, slots);
        load_inputs::<Dual<f64>>(&program, &Inputs::uv(&u, &u, 0.0), 0, 3, slots);
        run::<Dual<f64>>(&program, slots);
        for (i, &u) in u.iter().enumerate() {
            let r = Dual::get(slot::<Dual<f64>>(slots, 3), i);
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
        let slots = scratch.slots::<f64>(4);
        load_uniforms::<f64>(&program, |_| 0.0, 0.0, slots);
        load_inputs::<f64>(&program, &inputs, 64, 6, slots);
        run::<f64>(&program, slots);
        assert_eq!(slot::<f64>(slots, 3)[5], 3.0f64.sin());
    }

    /// Every shipped pattern, run through the dispatching entry (the AVX2 build where the CPU
    /// has it), through the SSE4.1 build and through the portable build, gives the same bits in
    /// every slot.
    #[test]
    fn the_wide_builds_compute_what_the_portable_one_does() {
        fn both_builds<T: Lane>(program: &Program, inputs: &Inputs) {
            let sse41 = |slots: &mut [T::Real]| {
                crate::simd::sse41_tier(
                    #[inline(always)]
                    || run_instrs_here::<T>(&program.instrs, slots),
                )
            };
            let mut portable = Scratch::new();
            let portable = portable.slots::<T>(program.sources.len());
            load_uniforms::<T>(program, |_| 1.5, inputs.t, portable);
            load_inputs::<T>(program, inputs, 0, CHUNK, portable);
            let mut wide = portable.to_vec();
            let mut middle = portable.to_vec();
            run_instrs_here::<T>(&program.instrs, portable);
            run_instrs::<T>(&program.instrs, &mut wide);
            sse41(&mut middle);
            assert_same_bits::<T>(&wide, portable);
            assert_same_bits::<T>(&middle, portable);
        }
        fn assert_same_bits<T: Lane>(a: &[T::Real], b: &[T::Real]) {
            // The same bits, NaN for NaN (which NaN an operation returns from two is the
            // order the compiler picked for its operands, not a value).
            for (i, (&x, &y)) in a.iter().zip(b.iter()).enumerate() {
                let (slot, lane) = (i / T::SLOT, i % T::SLOT);
                let (x, y) = (x.wide(), y.wide());
                assert!(
                    x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()),
                    "slot {slot} lane {lane}: {x:e} against {y:e}"
                );
            }
        }
        let lanes = |f: fn(f32) -> f32| (0..CHUNK).map(|i| f(i as f32)).collect::<Vec<f32>>();
        let chunk = ChunkInputs::new(|input| match input {
            0 => lanes(|i| i * 7.3 - 200.0),
            1 => lanes(|i| 90.0 - i * 3.1),
            2 => lanes(|i| i.sin() * 40.0),
            3 => lanes(|i| i * 0.5),
            4 => lanes(|i| -i),
            _ => lanes(|i| 0.25 + i * 0.01),
        });
        let inputs = chunk.inputs(2.5);
        for (name, source) in super::super::shipped::BUILTINS {
            let pattern = super::super::Pattern::compile(source, name).expect("a shipped pattern");
            let program = &pattern.inner.program;
            both_builds::<f64>(program, &inputs);
            both_builds::<Dual<f64>>(program, &inputs);
            both_builds::<f32>(program, &inputs);
            both_builds::<Dual<f32>>(program, &inputs);
        }
    }

    /// Every shipped pattern, and a program with every specialised form, evaluated with
    /// gradients over spread-out inputs: each slot's value has the bits the full chain rule
    /// gives it, and each varying slot's partials equal the full rule's wherever those are
    /// finite (see `activity`).
    #[test]
    fn specialised_gradients_are_the_full_rules() {
        fn compare<R: Real>(program: &Program, inputs: &Inputs) {
            let run = |program: &Program| {
                let mut scratch = Scratch::new();
                let slots = scratch.slots::<Dual<R>>(program.sources.len());
                load_uniforms::<Dual<R>>(program, |p| 3.0 + p as f64, inputs.t, slots);
                run_uniform::<Dual<R>>(program, slots);
                load_inputs::<Dual<R>>(program, inputs, 0, CHUNK, slots);
                let per_fragment = &program.instrs[program.uniform..];
                Dual::<R>::prepare(per_fragment, slots);
                run_instrs::<Dual<R>>(per_fragment, slots);
                slots.to_vec()
            };
            let mut full = program.clone();
            full.instrs.iter_mut().for_each(|i| i.form = DualForm::Full);
            let (specialised, reference) = (run(program), run(&full));
            for instr in &program.instrs[program.uniform..] {
                let lanes = |slots: &[R]| slot::<Dual<R>>(slots, instr.dst).to_vec();
                let (got, want) = (lanes(&specialised), lanes(&reference));
                for i in 0..CHUNK {
                    let (x, y) = (got[i].wide(), want[i].wide());
                    let same = x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
                    assert!(same, "{instr:?} lane {i}: value {x:e} against {y:e}");
                }
                if instr.form == DualForm::ValueOnly {
                    continue;
                }
                for i in CHUNK..3 * CHUNK {
                    let (x, y) = (got[i].wide(), want[i].wide());
                    assert!(
                        x == y || !y.is_finite(),
                        "{instr:?} partial {i}: {x:e} against {y:e}"
                    );
                }
            }
        }
        let mut state = 7u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        let forms = "param p = 30 in 1..100\n\
            let a = u % p - p / 2\nlet b = p / 3 - 2 * v\nlet c = a * a + (4 / b) % 7\n\
            let k = floor(v) * t + step(u, 3)\nlet e = (5 + v) * (u + 1) - v * 0.5\n\
            height = if c > 10 and a != 0 then c / p - sqrt(abs(c)) * k else min(a, e) + p % u";
        let sources = super::super::shipped::BUILTINS
            .iter()
            .copied()
            .chain([("forms", forms)]);
        for (name, source) in sources {
            let pattern = super::super::Pattern::compile(source, name).expect("a valid pattern");
            let program = &pattern.inner.program;
            for scale in [1.0, 37.0, 4096.0] {
                // u, v, the point and its partials spread around different centres.
                let offsets = [0.5, 0.3, 0.5, 0.0, 0.9, 0.5];
                let chunk = ChunkInputs::new(|input| {
                    let offset = offsets[input.min(5)];
                    (0..CHUNK).map(|_| (next() - offset) * scale).collect()
                });
                let inputs = chunk.inputs(1.25);
                compare::<f32>(program, &inputs);
                compare::<f64>(program, &inputs);
            }
        }
    }

    /// A chunk's per-fragment inputs for tests: u, v, x, y, z and the point's six partials.
    struct ChunkInputs {
        lanes: Vec<Vec<f32>>,
    }

    impl ChunkInputs {
        /// Input `i` (in the order above) is `lanes(i)`, `CHUNK` long.
        fn new(lanes: impl FnMut(usize) -> Vec<f32>) -> ChunkInputs {
            ChunkInputs {
                lanes: (0..11).map(lanes).collect(),
            }
        }

        fn inputs(&self, t: f64) -> Inputs<'_> {
            let [u, v, x, y, z, x_u, x_v, y_u, y_v, z_u, z_v] = &self.lanes[..] else {
                unreachable!("eleven inputs")
            };
            Inputs {
                u,
                v,
                x,
                y,
                z,
                x_u,
                x_v,
                y_u,
                y_v,
                z_u,
                z_v,
                t,
                precision: Precision::Fastest,
            }
        }
    }
}
