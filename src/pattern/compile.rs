//! Compiler: checked tree to a flat slot program. Constants are folded, repeated sub-expressions
//! shared, unused `let`s never lowered and dead instructions dropped, and each instruction's form
//! for gradients is chosen (`activity`).
//!
//! Every slot is written once, and an instruction's operands always live in lower slots than its
//! result; the evaluator relies on that to borrow them disjointly.

use std::collections::HashMap;

use super::activity::choose_dual_forms;
use super::ast::{BinaryOp, ExprId, ExprKind, UnaryOp};
use super::check::{Binding, Checked, Input};
use super::error::PatternError;
use super::functions::Function;
use super::ops::{Op, apply};
use super::program::{DualForm, Instr, Program, Source};

/// Most slots a program may use (each costs a few KiB of scratch).
pub const MAX_SLOTS: usize = 8192;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Operand {
    Const(f64),
    Slot(usize),
}

impl Operand {
    /// The same slot, or constants with the same bits (so 0 and −0 differ, and NaN is itself).
    fn same(self, other: Operand) -> bool {
        match (self, other) {
            (Operand::Const(a), Operand::Const(b)) => a.to_bits() == b.to_bits(),
            (Operand::Slot(a), Operand::Slot(b)) => a == b,
            _ => false,
        }
    }
}

#[derive(Clone, Copy, Debug)]
enum Value {
    Num(Operand),
    Color([Operand; 3]),
}

pub fn compile(checked: &Checked, source: &str, origin: &str) -> Result<Program, PatternError> {
    let mut lowering = Lowering {
        checked,
        sources: Vec::new(),
        instrs: Vec::new(),
        shared: HashMap::new(),
        named_slots: HashMap::new(),
        lets: vec![None; checked.lets.len()],
    };
    let live = live_lets(checked);
    for (i, &value) in checked.lets.iter().enumerate() {
        if live[i] {
            lowering.lets[i] = Some(lowering.expr(value));
        }
    }
    let mut outputs = Vec::new();
    for &value in &checked.output_values {
        match lowering.expr(value) {
            Value::Num(n) => outputs.push(lowering.slot(n)),
            Value::Color(c) => outputs.extend(c.map(|n| lowering.slot(n))),
        }
    }
    let mut program = hoist_uniform(prune(lowering.sources, lowering.instrs, outputs));
    choose_dual_forms(&mut program);
    if program.sources.len() > MAX_SLOTS {
        let message = format!(
            "pattern too large: {} values after simplification (the limit is {MAX_SLOTS})",
            program.sources.len()
        );
        return Err(PatternError::at(source, origin, 0, message));
    }
    Ok(program)
}

/// Which `let`s the output needs, directly or through other `let`s (walked backwards, so no
/// recursion across bindings).
fn live_lets(checked: &Checked) -> Vec<bool> {
    let mut live = vec![false; checked.lets.len()];
    let mark = |root: ExprId, live: &mut Vec<bool>| {
        let mut stack = vec![root];
        while let Some(id) = stack.pop() {
            if let Some(Binding::Let(i)) = checked.bindings.get(&id) {
                live[*i] = true;
            }
            stack.extend(checked.ast.children(id));
        }
    };
    for &value in &checked.output_values {
        mark(value, &mut live);
    }
    for i in (0..checked.lets.len()).rev() {
        if live[i] {
            mark(checked.lets[i], &mut live);
        }
    }
    live
}

struct Lowering<'a> {
    checked: &'a Checked,
    sources: Vec<Source>,
    instrs: Vec<Instr>,
    /// (op, operands) already computed, for sharing repeated sub-expressions.
    shared: HashMap<(Op, [usize; 4]), usize>,
    /// Slots of inputs, params and constants (constants keyed by their bits).
    named_slots: HashMap<(u8, u64), usize>,
    lets: Vec<Option<Value>>,
}

impl Lowering<'_> {
    fn new_slot(&mut self, source: Source) -> usize {
        self.sources.push(source);
        self.sources.len() - 1
    }

    fn named_slot(&mut self, key: (u8, u64), source: Source) -> usize {
        if let Some(&slot) = self.named_slots.get(&key) {
            return slot;
        }
        let slot = self.new_slot(source);
        self.named_slots.insert(key, slot);
        slot
    }

    fn slot(&mut self, operand: Operand) -> usize {
        match operand {
            Operand::Slot(s) => s,
            Operand::Const(c) => self.named_slot((0, c.to_bits()), Source::Constant(c)),
        }
    }

    /// Emits `op`, folding it when every operand is a constant.
    fn emit(&mut self, op: Op, args: [Operand; 4]) -> Operand {
        if let [
            Operand::Const(a),
            Operand::Const(b),
            Operand::Const(c),
            Operand::Const(d),
        ] = args
        {
            return Operand::Const(apply::<f64>(op, a, b, c, d));
        }
        if op == Op::Select
            && let Operand::Const(condition) = args[0]
        {
            return if condition != 0.0 { args[1] } else { args[2] };
        }
        if op == Op::Select && args[1].same(args[2]) {
            return args[1];
        }
        if op == Op::Pow
            && let Operand::Const(exponent) = args[1]
            && let Some(reduced) = self.small_power(args[0], exponent)
        {
            return reduced;
        }
        let args = args.map(|a| self.slot(a));
        if let Some(&slot) = self.shared.get(&(op, args)) {
            return Operand::Slot(slot);
        }
        let dst = self.new_slot(Source::Computed);
        self.instrs.push(Instr {
            op,
            dst,
            args,
            form: DualForm::Full,
        });
        self.shared.insert((op, args), dst);
        Operand::Slot(dst)
    }

    /// `a^n` for the exponents patterns use most, by multiplication or `sqrt` instead of the
    /// far slower `powf`.
    fn small_power(&mut self, a: Operand, exponent: f64) -> Option<Operand> {
        Some(match exponent {
            0.5 => self.emit1(Op::Sqrt, a),
            1.0 => a,
            2.0 => self.emit2(Op::Mul, a, a),
            3.0 => {
                let square = self.emit2(Op::Mul, a, a);
                self.emit2(Op::Mul, square, a)
            }
            4.0 => {
                let square = self.emit2(Op::Mul, a, a);
                self.emit2(Op::Mul, square, square)
            }
            -1.0 => self.emit2(Op::Div, Operand::Const(1.0), a),
            _ => return None,
        })
    }

    fn emit1(&mut self, op: Op, a: Operand) -> Operand {
        self.emit(op, [a, a, a, a])
    }

    fn emit2(&mut self, op: Op, a: Operand, b: Operand) -> Operand {
        self.emit(op, [a, b, a, a])
    }

    fn num(&mut self, id: ExprId) -> Operand {
        match self.expr(id) {
            Value::Num(n) => n,
            Value::Color(_) => unreachable!("the checker rejects colours where numbers go"),
        }
    }

    fn expr(&mut self, id: ExprId) -> Value {
        let checked = self.checked;
        match &checked.ast.expr(id).kind {
            ExprKind::Number(n) => Value::Num(Operand::Const(*n)),
            ExprKind::Bool(b) => Value::Num(Operand::Const(f64::from(u8::from(*b)))),
            ExprKind::Name(_) => self.name(checked.bindings[&id]),
            ExprKind::Unary(op, a) => {
                let a = self.num(*a);
                let op = match op {
                    UnaryOp::Neg => Op::Neg,
                    UnaryOp::Not => Op::Not,
                };
                Value::Num(self.emit1(op, a))
            }
            ExprKind::Binary(op, a, b) => {
                let (a, b) = (self.num(*a), self.num(*b));
                Value::Num(self.emit2(binary_op(*op), a, b))
            }
            ExprKind::If(c, a, b) => {
                let c = self.num(*c);
                let (a, b) = (self.expr(*a), self.expr(*b));
                self.zip(a, b, |l, x, y| l.emit(Op::Select, [c, x, y, c]))
            }
            ExprKind::Call { args, .. } => self.call(checked.calls[&id], args),
        }
    }

    fn name(&mut self, binding: Binding) -> Value {
        let operand = match binding {
            Binding::Pi => Operand::Const(std::f64::consts::PI),
            Binding::Input(input) => {
                let key = (1, input as u64);
                Operand::Slot(self.named_slot(key, Source::Input(input)))
            }
            Binding::Param(p) => Operand::Slot(self.named_slot((2, p as u64), Source::Param(p))),
            Binding::Let(i) => return self.lets[i].expect("live lets are lowered before use"),
        };
        Value::Num(operand)
    }

    /// Applies `f` channel by channel (numbers have one channel, colours three).
    fn zip(
        &mut self,
        a: Value,
        b: Value,
        mut f: impl FnMut(&mut Self, Operand, Operand) -> Operand,
    ) -> Value {
        match (a, b) {
            (Value::Num(x), Value::Num(y)) => Value::Num(f(self, x, y)),
            (Value::Color(x), Value::Color(y)) => Value::Color([
                f(self, x[0], y[0]),
                f(self, x[1], y[1]),
                f(self, x[2], y[2]),
            ]),
            _ => unreachable!("the checker makes both branches the same type"),
        }
    }

    fn call(&mut self, function: Function, args: &[ExprId]) -> Value {
        if function == Function::Mix {
            let (a, b) = (self.expr(args[0]), self.expr(args[1]));
            let t = self.num(args[2]);
            return self.zip(a, b, |l, x, y| l.emit(Op::Mix, [x, y, t, x]));
        }
        let a: Vec<Operand> = args.iter().map(|&arg| self.num(arg)).collect();
        if function == Function::Rgb {
            return Value::Color([a[0], a[1], a[2]]);
        }
        let op = function_op(function, a.len());
        let operand = |k: usize| a.get(k).copied().unwrap_or(a[0]);
        Value::Num(self.emit(op, [a[0], operand(1), operand(2), operand(3)]))
    }
}

fn binary_op(op: BinaryOp) -> Op {
    match op {
        BinaryOp::Add => Op::Add,
        BinaryOp::Sub => Op::Sub,
        BinaryOp::Mul => Op::Mul,
        BinaryOp::Div => Op::Div,
        BinaryOp::Pow => Op::Pow,
        BinaryOp::Mod => Op::Mod,
        BinaryOp::Lt => Op::Lt,
        BinaryOp::Le => Op::Le,
        BinaryOp::Gt => Op::Gt,
        BinaryOp::Ge => Op::Ge,
        BinaryOp::Eq => Op::Eq,
        BinaryOp::Ne => Op::Ne,
        BinaryOp::And => Op::And,
        BinaryOp::Or => Op::Or,
    }
}

fn function_op(function: Function, arity: usize) -> Op {
    use Function as F;
    match function {
        F::Sin => Op::Sin,
        F::Cos => Op::Cos,
        F::Tan => Op::Tan,
        F::Asin => Op::Asin,
        F::Acos => Op::Acos,
        F::Atan => Op::Atan,
        F::Atan2 => Op::Atan2,
        F::Sqrt => Op::Sqrt,
        F::Abs => Op::Abs,
        F::Sign => Op::Sign,
        F::Floor => Op::Floor,
        F::Ceil => Op::Ceil,
        F::Fract => Op::Fract,
        F::Mod => Op::Mod,
        F::Min => Op::Min,
        F::Max => Op::Max,
        F::Clamp => Op::Clamp,
        F::Step => Op::Step,
        F::Smoothstep => Op::Smoothstep,
        F::Exp => Op::Exp,
        F::Log => Op::Log,
        F::Pow => Op::Pow,
        F::Hypot => Op::Hypot,
        F::Length if arity == 2 => Op::Hypot,
        F::Length => Op::Hypot3,
        F::Noise if arity == 2 => Op::Noise2,
        F::Noise => Op::Noise3,
        F::Perlin if arity == 2 => Op::Perlin2,
        F::Perlin => Op::Perlin3,
        F::Cells if arity == 2 => Op::Cells2,
        F::Cells => Op::Cells3,
        F::Fbm if arity == 3 => Op::Fbm2,
        F::Fbm => Op::Fbm3,
        F::Mix | F::Rgb => unreachable!("handled by Lowering::call"),
    }
}

/// Drops instructions and slots the outputs do not depend on, and renumbers the rest in order
/// (which keeps operands below results).
fn prune(sources: Vec<Source>, instrs: Vec<Instr>, outputs: Vec<usize>) -> Program {
    let mut needed = vec![false; sources.len()];
    for &o in &outputs {
        needed[o] = true;
    }
    for instr in instrs.iter().rev() {
        if needed[instr.dst] {
            for &a in &instr.args {
                needed[a] = true;
            }
        }
    }
    let mut renumber = vec![usize::MAX; sources.len()];
    let mut kept_sources = Vec::new();
    for (slot, source) in sources.into_iter().enumerate() {
        if needed[slot] {
            renumber[slot] = kept_sources.len();
            kept_sources.push(source);
        }
    }
    let instrs = instrs
        .into_iter()
        .filter(|i| needed[i.dst])
        .map(|i| Instr {
            op: i.op,
            dst: renumber[i.dst],
            args: i.args.map(|a| renumber[a]),
            form: i.form,
        })
        .collect();
    Program {
        sources: kept_sources,
        instrs,
        uniform: 0,
        outputs: outputs.iter().map(|&o| renumber[o]).collect(),
    }
}

/// Moves instructions that are the same for every fragment to the front. Order within each
/// group is kept, so every operand is still computed before it is read.
fn hoist_uniform(mut program: Program) -> Program {
    let mut uniform: Vec<bool> = program
        .sources
        .iter()
        .map(|s| !matches!(s, Source::Input(i) if *i != Input::T) && *s != Source::Computed)
        .collect();
    for instr in &program.instrs {
        uniform[instr.dst] = instr.args.iter().all(|&a| uniform[a]);
    }
    let (mut front, back): (Vec<Instr>, Vec<Instr>) =
        program.instrs.into_iter().partition(|i| uniform[i.dst]);
    program.uniform = front.len();
    front.extend(back);
    program.instrs = front;
    program
}

#[cfg(test)]
mod tests {
    use super::super::{check::check, lexer::lex, parser::parse};
    use super::*;

    fn program(src: &str) -> Program {
        let checked = check(parse(&lex(src, "t").unwrap(), src, "t").unwrap(), src, "t").unwrap();
        compile(&checked, src, "t").unwrap()
    }

    #[test]
    fn constants_fold_away() {
        let p = program("height = u * (2 * pi / 4) + sin(0)");
        assert_eq!(p.instrs.len(), 2); // mul, add of the folded 0
        assert!(
            p.sources
                .contains(&Source::Constant(std::f64::consts::PI / 2.0))
        );
    }

    #[test]
    fn unused_lets_and_dead_branches_are_dropped() {
        let p =
            program("let unused = sin(u)\nlet a = cos(v)\nheight = if 1 < 2 then a else sqrt(u)");
        assert_eq!(p.instrs.len(), 1);
        assert!(!p.uses(Input::U));
    }

    #[test]
    fn small_integer_powers_become_multiplications() {
        let p = program("height = u^2 + pow(v, 3) + u^2.5");
        let ops: Vec<Op> = p.instrs.iter().map(|i| i.op).collect();
        assert_eq!(ops.iter().filter(|&&o| o == Op::Pow).count(), 1);
        assert_eq!(ops.iter().filter(|&&o| o == Op::Mul).count(), 3);
    }

    #[test]
    fn uniform_instructions_are_hoisted() {
        let p = program("param w = 20 in 1..100\nheight = sin(u * (2 * pi / w)) + cos(t)");
        assert_eq!(p.uniform, 2); // 2π/w and cos(t)
        let ops: Vec<Op> = p.instrs.iter().map(|i| i.op).collect();
        assert_eq!(ops[..2], [Op::Div, Op::Cos]);
    }

    #[test]
    fn a_choice_between_equal_values_is_that_value() {
        // Red is 1 and blue 0 either way: only green is chosen.
        let p = program("color = if u < 1 then rgb(1, 0, 0) else rgb(1, 1, 0)");
        let ops: Vec<Op> = p.instrs.iter().map(|i| i.op).collect();
        assert_eq!(ops, [Op::Lt, Op::Select]);
        // 0 and −0 are different values.
        let signed = program("height = if u < 1 then 0 else -0");
        assert_eq!(signed.instrs.last().map(|i| i.op), Some(Op::Select));
    }

    #[test]
    fn repeated_sub_expressions_are_shared() {
        let p = program("height = sin(u) * sin(u)");
        assert_eq!(p.instrs.len(), 2);
    }

    #[test]
    fn operands_precede_results() {
        let p = program("param k = 1 in 0..2\nlet a = u * k + 3\nheight = a * a - noise(a, v, t)");
        for i in &p.instrs {
            assert!(i.args.iter().all(|&a| a < i.dst));
        }
    }
}
