//! The pattern language: small text files (`patterns/*.pat`) that describe a bump pattern (a
//! height or its slope) or a colour texture over a surface's (u, v), its object-space point and
//! time. A file is compiled once into a flat program and evaluated over batches of fragments;
//! height gradients come from forward-mode automatic differentiation, so they are exact.
//!
//! ```text
//! # grid of dimples
//! param period = 30 in 4..200
//! let cu = u % period - period / 2
//! let cv = v % period - period / 2
//! let r2 = 125 - cu^2 - cv^2
//! height = if r2 > 0 then 10 - sqrt(225 - cu^2 - cv^2) else 0
//! ```
//!
//! Fragments whose result is not finite (division by zero, `sqrt(-1)`, …) are made flat: height
//! and gradient 0, colour black. Every `eval_*` returns how many there were.

mod activity;
mod ast;
mod cells;
mod check;
mod compile;
mod dual;
mod error;
mod eval;
mod fractal;
mod functions;
mod lexer;
pub mod native;
mod noise;
mod ops;
mod output;
mod parser;
mod perlin;
mod program;
mod real;
mod shipped;
mod time_dependence;
mod value_type;

use crate::bounded_read::ReadFailure;
use std::path::Path;
use std::sync::Arc;

pub use ast::OutputKind;
pub use check::Param;
pub use error::PatternError;
pub use eval::{CHUNK, Inputs, Scratch};
pub use output::BumpSample;
pub use parser::MAX_DEPTH;
pub use real::Precision;
pub use shipped::{BUILTINS, builtin};

use check::Input;
use dual::Dual;
use eval::Lane;
use output::Store;
use program::Program;

/// Largest pattern source accepted, in bytes.
pub const MAX_SOURCE_BYTES: usize = 1 << 20;

/// A compiled pattern: immutable, `Send + Sync`, cheap to clone and share between threads.
#[derive(Clone, Debug)]
pub struct Pattern {
    inner: Arc<Compiled>,
}

#[derive(Debug)]
struct Compiled {
    program: Program,
    params: Vec<Param>,
    output: OutputKind,
}

/// What `bumpwork check FILE` reports about a valid pattern file.
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    pub output: OutputKind,
    pub params: Vec<Param>,
    pub uses_time: bool,
    pub uses_point: bool,
    /// Instructions left after folding, sharing and dead-code removal.
    pub instructions: usize,
}

impl Pattern {
    /// Compiles pattern source. `origin` names it in error messages (usually the file name).
    pub fn compile(source: &str, origin: &str) -> Result<Pattern, PatternError> {
        if source.len() > MAX_SOURCE_BYTES {
            let message = format!(
                "file too large: {} bytes (the limit is {MAX_SOURCE_BYTES})",
                source.len()
            );
            return Err(PatternError::at(source, origin, 0, message));
        }
        let tokens = lexer::lex(source, origin)?;
        let ast = parser::parse(&tokens, source, origin)?;
        let checked = check::check(ast, source, origin)?;
        let program = compile::compile(&checked, source, origin)?;
        let compiled = Compiled {
            program,
            params: checked.params,
            output: checked.output,
        };
        Ok(Pattern {
            inner: Arc::new(compiled),
        })
    }

    /// Reads (at most `MAX_SOURCE_BYTES`) and compiles a pattern file.
    pub fn load(path: &Path) -> Result<Pattern, PatternError> {
        let origin = path.display().to_string();
        let source = read_limited(path, &origin)?;
        Pattern::compile(&source, &origin)
    }

    pub fn output(&self) -> OutputKind {
        self.inner.output
    }

    /// The file's parameters, in declaration order; `params` arguments follow this order.
    pub fn params(&self) -> &[Param] {
        &self.inner.params
    }

    /// Whether the result depends on `t` (so the view must animate).
    pub fn uses_time(&self) -> bool {
        self.inner.program.uses(Input::T)
    }

    /// Whether the result can change with `t` at these parameter values (`params` as for
    /// `eval_bump`): a wave whose speed is 0 stands still.
    pub fn moves_with_time(&self, params: &[f32]) -> bool {
        self.uses_time()
            && time_dependence::moves_with_time(&self.inner.program, |p| {
                self.param_value(p, params)
            })
    }

    /// Whether `Inputs::u` and `Inputs::v` must be supplied.
    pub fn uses_uv(&self) -> bool {
        self.inner.program.uses(Input::U) || self.inner.program.uses(Input::V)
    }

    /// Whether `Inputs::x/y/z` (and, for height gradients, their partials) must be supplied.
    pub fn uses_point(&self) -> bool {
        [Input::X, Input::Y, Input::Z]
            .iter()
            .any(|&i| self.inner.program.uses(i))
    }

    /// Scratch memory already sized for this pattern.
    pub fn scratch(&self) -> Scratch {
        let mut scratch = Scratch::new();
        let slots = self.inner.program.sources.len();
        scratch.slots::<Dual<f32>>(slots);
        scratch.slots::<Dual<f64>>(slots);
        scratch
    }

    pub fn summary(&self) -> Summary {
        Summary {
            output: self.output(),
            params: self.params().to_vec(),
            uses_time: self.uses_time(),
            uses_point: self.uses_point(),
            instructions: self.inner.program.instrs.len(),
        }
    }

    /// Bump height and exact gradient (height patterns) or the given slope with height 0 (slope
    /// patterns) for the first `out.len()` fragments. `params` follow `params()`; missing or
    /// non-finite values take the default, others are clamped to the range. Returns the number
    /// of non-finite fragments, which are made flat.
    ///
    /// # Panics
    /// If the pattern is a colour pattern, or an input slice it needs is shorter than `out`.
    pub fn eval_bump(
        &self,
        inputs: &Inputs,
        params: &[f32],
        scratch: &mut Scratch,
        out: &mut [BumpSample],
    ) -> usize {
        let program = &self.inner.program;
        match self.output() {
            OutputKind::Height => {
                let store = output::HeightGradient { program, out };
                self.evaluate(inputs, params, scratch, store)
            }
            OutputKind::Slope => {
                let store = output::Slope { program, out };
                self.evaluate(inputs, params, scratch, store)
            }
            OutputKind::Color => panic!("eval_bump called on a colour pattern"),
        }
    }

    /// Height only, without derivatives (cheaper; for previews and displacement).
    ///
    /// # Panics
    /// Unless this is a height pattern, or if an input slice it needs is shorter than `out`.
    pub fn eval_height(
        &self,
        inputs: &Inputs,
        params: &[f32],
        scratch: &mut Scratch,
        out: &mut [f32],
    ) -> usize {
        assert_eq!(
            self.output(),
            OutputKind::Height,
            "eval_height needs a height pattern"
        );
        let program = &self.inner.program;
        self.evaluate(inputs, params, scratch, output::Height { program, out })
    }

    /// Linear RGB in 0..1 (clamped); non-finite fragments are black.
    ///
    /// # Panics
    /// Unless this is a colour pattern, or if an input slice it needs is shorter than `out`.
    pub fn eval_color(
        &self,
        inputs: &Inputs,
        params: &[f32],
        scratch: &mut Scratch,
        out: &mut [[f32; 3]],
    ) -> usize {
        assert_eq!(
            self.output(),
            OutputKind::Color,
            "eval_color needs a colour pattern"
        );
        let program = &self.inner.program;
        self.evaluate(inputs, params, scratch, output::Color { program, out })
    }

    /// Runs the program over `store`'s fragments in `f32` where asked and that serves (see
    /// `Real`), else or where that gave a non-finite result in `f64`; returns the non-finite
    /// count.
    fn evaluate<S: Store>(
        &self,
        inputs: &Inputs,
        params: &[f32],
        scratch: &mut Scratch,
        mut store: S,
    ) -> usize {
        if inputs.precision == Precision::Fastest && self.inner.program.single_precision() {
            let flat = self.evaluate_in::<f32, S>(inputs, params, scratch, &mut store);
            if flat == 0 {
                return 0;
            }
        }
        self.evaluate_in::<f64, S>(inputs, params, scratch, &mut store)
    }

    /// `evaluate` in lanes of `R` alone, with no second try.
    #[inline(always)]
    fn evaluate_in<R: real::Real, S: Store>(
        &self,
        inputs: &Inputs,
        params: &[f32],
        scratch: &mut Scratch,
        store: &mut S,
    ) -> usize {
        let len = store.len();
        self.run::<S::Lanes<R>>(
            inputs,
            params,
            scratch,
            len,
            #[inline(always)]
            |start, slots| store.store(start, slots),
        )
    }

    /// Runs the program chunk by chunk in lanes of `T`; `store(start, slots)` writes one
    /// chunk's outputs and returns its non-finite count.
    fn run<T: Lane>(
        &self,
        inputs: &Inputs,
        params: &[f32],
        scratch: &mut Scratch,
        len: usize,
        store: impl FnMut(usize, &[T::Real]) -> usize,
    ) -> usize {
        let program = &self.inner.program;
        self.check_lengths(inputs, len, T::DUAL);
        let slots = scratch.slots::<T>(program.sources.len());
        eval::load_uniforms::<T>(program, |p| self.param_value(p, params), inputs.t, slots);
        eval::run_uniform::<T>(program, slots);
        eval::run_chunks::<T>(program, inputs, len, slots, store)
    }

    fn param_value(&self, index: usize, given: &[f32]) -> f64 {
        let param = &self.inner.params[index];
        match given.get(index) {
            Some(&value) if value.is_finite() => f64::from(value.clamp(param.min, param.max)),
            _ => f64::from(param.default),
        }
    }

    fn check_lengths(&self, inputs: &Inputs, len: usize, derivatives: bool) {
        let program = &self.inner.program;
        let need = |ok: bool, what: &str| assert!(ok, "Inputs::{what} is shorter than the batch");
        need(inputs.u.len() >= len || !program.uses(Input::U), "u");
        need(inputs.v.len() >= len || !program.uses(Input::V), "v");
        let point = [
            (Input::X, inputs.x, inputs.x_u, inputs.x_v, "x"),
            (Input::Y, inputs.y, inputs.y_u, inputs.y_v, "y"),
            (Input::Z, inputs.z, inputs.z_u, inputs.z_v, "z"),
        ];
        for (input, value, du, dv, name) in point {
            if program.uses(input) {
                need(value.len() >= len, name);
                need(!derivatives || du.len().min(dv.len()) >= len, name);
            }
        }
    }
}

impl std::fmt::Display for Summary {
    /// One line for `bumpwork check`, e.g.
    /// `height pattern, 14 instructions; params: period = 30 in 4..300; animated`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let kind = match self.output {
            OutputKind::Height => "height",
            OutputKind::Slope => "slope",
            OutputKind::Color => "colour",
        };
        write!(f, "{kind} pattern, {} instructions", self.instructions)?;
        if !self.params.is_empty() {
            let params: Vec<String> = self
                .params
                .iter()
                .map(|p| format!("{} = {} in {}..{}", p.name, p.default, p.min, p.max))
                .collect();
            write!(f, "; params: {}", params.join(", "))?;
        }
        if self.uses_point {
            write!(f, "; reads the point x, y, z")?;
        }
        if self.uses_time {
            write!(f, "; animated")?;
        }
        Ok(())
    }
}

/// Validates a pattern file (for `bumpwork check`).
pub fn check_file(path: &Path) -> Result<Summary, PatternError> {
    Pattern::load(path).map(|p| p.summary())
}

fn read_limited(path: &Path, origin: &str) -> Result<String, PatternError> {
    let bytes =
        crate::bounded_read::read_bounded(path, MAX_SOURCE_BYTES as u64).map_err(|failure| {
            match failure {
                ReadFailure::TooLarge { .. } => PatternError::whole_file(
                    origin,
                    format!("file too large: more than {MAX_SOURCE_BYTES} bytes"),
                ),
                other => PatternError::whole_file(origin, format!("cannot read: {other}")),
            }
        })?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = e.utf8_error().valid_up_to();
        let text = String::from_utf8_lossy(e.as_bytes()).into_owned();
        PatternError::at(
            &text,
            origin,
            valid,
            "expected UTF-8 text, found an invalid byte",
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "param k = 2 in 1..3\nheight = k * u";

    fn height_at(pattern: &Pattern, params: &[f32], u: f32) -> BumpSample {
        let mut out = [BumpSample::default()];
        let (u, v) = ([u], [0.0]);
        let inputs = Inputs::uv(&u, &v, 0.0);
        pattern.eval_bump(&inputs, params, &mut Scratch::new(), &mut out);
        out[0]
    }

    #[test]
    fn params_default_clamp_and_ignore_non_finite() {
        let p = Pattern::compile(SOURCE, "t").unwrap();
        assert_eq!(height_at(&p, &[], 1.0).height, 2.0);
        assert_eq!(height_at(&p, &[2.5], 1.0).height, 2.5);
        assert_eq!(height_at(&p, &[10.0], 1.0).height, 3.0);
        assert_eq!(height_at(&p, &[f32::NAN], 1.0).du, 2.0);
    }

    #[test]
    fn conditions_compare_as_truth_values() {
        let (u, v) = ([0.0, 0.0, 2.0, 2.0], [0.0, 2.0, 0.0, 2.0]);
        let heights = |source: &str| {
            let pattern = Pattern::compile(source, "t").unwrap();
            let mut out = [BumpSample::default(); 4];
            let inputs = Inputs::uv(&u, &v, 0.0);
            pattern.eval_bump(&inputs, &[], &mut Scratch::new(), &mut out);
            out.map(|s| s.height)
        };
        let same = heights("height = if (u < 1) == (v < 1) then 1 else 0");
        assert_eq!(same, [1.0, 0.0, 0.0, 1.0]);
        let differ = heights("height = if (u < 1) != (v < 1) then 1 else 0");
        assert_eq!(differ, [0.0, 1.0, 1.0, 0.0]);
    }

    /// A colour pattern of the point alone (so given no u or v), over more than a chunk.
    #[test]
    fn colours_clamp_and_non_finite_fragments_turn_black() {
        let pattern = Pattern::compile("color = rgb(x, y, 1 / z)", "t").unwrap();
        assert!(!pattern.uses_uv() && pattern.uses_point());
        let n = eval::CHUNK + 3;
        let x: Vec<f32> = (0..n).map(|i| i as f32 / n as f32 * 3.0 - 1.0).collect();
        let y = vec![0.5; n];
        let z: Vec<f32> = (0..n).map(|i| if i % 7 == 0 { 0.0 } else { 4.0 }).collect();
        let inputs = Inputs {
            x: &x,
            y: &y,
            z: &z,
            ..Inputs::default()
        };
        let mut out = vec![[9.0; 3]; n];
        let black = pattern.eval_color(&inputs, &[], &mut Scratch::new(), &mut out);
        assert_eq!(black, n.div_ceil(7));
        for (i, rgb) in out.iter().enumerate() {
            let want = if i % 7 == 0 {
                [0.0; 3]
            } else {
                [x[i].clamp(0.0, 1.0), 0.5, 0.25]
            };
            assert_eq!(*rgb, want, "fragment {i}");
        }
    }

    /// A short chunk computes all its lanes, the ones past its end on what an earlier call
    /// left there (here non-finite): none of it reaches the outputs or the count.
    #[test]
    fn lanes_past_a_short_chunk_stay_out_of_the_results() {
        let pattern = Pattern::compile("height = 1 / u", "t").unwrap();
        let mut scratch = Scratch::new();
        let zeros = [0.0f32; 70];
        let mut out = [BumpSample::default(); 70];
        let flat = pattern.eval_bump(
            &Inputs::uv(&zeros, &zeros, 0.0),
            &[],
            &mut scratch,
            &mut out,
        );
        assert_eq!(flat, 70);
        let u = [2.0f32, 4.0, 8.0];
        let mut out = [BumpSample::default(); 3];
        let flat = pattern.eval_bump(&Inputs::uv(&u, &u, 0.0), &[], &mut scratch, &mut out);
        assert_eq!(flat, 0);
        assert_eq!(
            out.map(|s| (s.height, s.du)),
            [(0.5, -0.25), (0.25, -0.0625), (0.125, -0.015625)]
        );
    }

    /// In `f32` both exponentials overflow and their quotient is NaN; the batch is evaluated
    /// again in `f64`, where it is e.
    #[test]
    fn an_overflow_in_single_precision_is_evaluated_again_in_double() {
        let pattern = Pattern::compile("height = exp(u) / exp(u - 1)", "t").unwrap();
        assert!(pattern.inner.program.single_precision());
        let u = [100.0f32, 1.0];
        let mut out = [BumpSample::default(); 2];
        let inputs = Inputs::uv(&u, &u, 0.0);
        let flat = pattern.eval_bump(&inputs, &[], &mut Scratch::new(), &mut out);
        assert_eq!(flat, 0);
        for sample in out {
            assert!(
                (sample.height - std::f32::consts::E).abs() < 1e-5,
                "{sample:?}"
            );
            assert!(sample.du.abs() < 1e-5, "{sample:?}");
        }
    }

    /// `t` is read in `f64`: at 1e7 s an `f32` clock steps by a whole second.
    #[test]
    fn patterns_of_time_keep_double_precision() {
        let pattern = Pattern::compile("height = sin(t) + u", "t").unwrap();
        assert!(!pattern.inner.program.single_precision());
        let t = 1e7 + 0.25;
        let u = [0.0f32];
        let mut out = [BumpSample::default()];
        pattern.eval_bump(&Inputs::uv(&u, &u, t), &[], &mut Scratch::new(), &mut out);
        assert!(
            (f64::from(out[0].height) - t.sin()).abs() < 1e-6,
            "{:?}",
            out[0]
        );
    }

    #[test]
    fn pattern_is_shareable_between_threads() {
        fn shareable<T: Send + Sync + Clone>() {}
        shareable::<Pattern>();
    }

    #[test]
    fn one_scratch_serves_patterns_of_any_size() {
        let small = Pattern::compile("height = u", "t").unwrap();
        let big = Pattern::compile(builtin("ripples").unwrap(), "ripples").unwrap();
        let mut scratch = small.scratch();
        let mut out = [BumpSample::default(); 3];
        let u = [1.0, 2.0, 3.0];
        big.eval_bump(&Inputs::uv(&u, &u, 0.0), &[], &mut scratch, &mut out);
        assert!(out.iter().all(|s| s.du != 0.0));
    }

    #[test]
    fn summary_reports_what_the_workbench_needs() {
        let s = Pattern::compile("param a = 1 in 0..2\nslope = (sin(t), a * z)", "t")
            .unwrap()
            .summary();
        assert_eq!(s.output, OutputKind::Slope);
        assert!(s.uses_time && s.uses_point);
        assert_eq!(s.params.len(), 1);
        assert_eq!(
            s.to_string(),
            "slope pattern, 2 instructions; params: a = 1 in 0..2; reads the point x, y, z; animated"
        );
    }
}
