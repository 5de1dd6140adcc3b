//! A compiled pattern: slots filled from inputs, parameters and constants, then flat
//! instructions, each writing one slot from lower ones.

use super::check::Input;
use super::ops::Op;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instr {
    pub op: Op,
    pub dst: usize,
    /// Operand slots; ops with fewer operands repeat the first.
    pub args: [usize; 4],
    /// How it runs when partials are carried (`activity`).
    pub form: DualForm,
}

/// Where a slot's value comes from before the instructions run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Source {
    Input(Input),
    Param(usize),
    Constant(f64),
    Computed,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub sources: Vec<Source>,
    /// Uniform instructions first (they depend only on params, constants and `t`, so they run
    /// once per call), then the per-fragment ones.
    pub instrs: Vec<Instr>,
    /// How many of `instrs` are uniform.
    pub uniform: usize,
    /// Output slots: 1 for a height, 2 for a slope, 3 for a colour.
    pub outputs: Vec<usize>,
}

impl Program {
    pub fn uses(&self, input: Input) -> bool {
        self.sources.contains(&Source::Input(input))
    }

    /// Whether `f32` lanes are accurate enough for this program: when it does not read `t`
    /// and calls no fractal or cellular noise (see `Real`).
    pub fn single_precision(&self) -> bool {
        !self.uses(Input::T) && !self.instrs.iter().any(|i| i.op.amplifies_rounding())
    }
}

/// How an instruction runs in lanes that carry partials (∂/∂u, ∂/∂v).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DualForm {
    /// Value and partials by the op's full chain rule.
    #[default]
    Full,
    /// The result does not vary with (u, v): its value alone. Its partial lanes hold zeros,
    /// set once per evaluation, for the full rules that read them.
    ValueOnly,
    /// An arithmetic op (`Op::Add` … `Op::Mod`) whose first operand varies and second does not.
    FirstVaries,
    /// An arithmetic op whose second operand varies and first does not.
    SecondVaries,
    /// `a * a`: both partial terms are the same product.
    Square,
}
