//! Activity analysis for gradients: which of a program's slots vary with (u, v), decided when
//! the program is compiled, so that evaluating a gradient carries partials only where they can
//! be other than zero. A comparison, a `floor`, a parameter or `period / 2` has no partials; an
//! arithmetic op with one such operand needs only the other's.
//!
//! The specialised forms compute the value exactly as the full chain rule does, and every
//! partial the full rule would form, less its terms `p · 0` for operands that do not vary. The
//! gradient is therefore the full rule's wherever that is finite (a sum that came to zero may
//! differ in its sign); where an operand that does not vary is itself infinite, the full rule's
//! `∞ · 0` gives NaN and the specialised form the true partial.

use super::check::Input;
use super::ops::Op;
use super::program::{DualForm, Instr, Program, Source};

/// Sets the form of each per-fragment instruction of `program`. The uniform instructions keep
/// the full rule: they run once per evaluation, and their partials are what the full rule makes.
pub fn choose_dual_forms(program: &mut Program) {
    let mut varies: Vec<bool> = program.sources.iter().map(source_varies).collect();
    let uniform = program.uniform;
    for (index, instr) in program.instrs.iter_mut().enumerate() {
        varies[instr.dst] = !instr.op.has_no_partials() && instr.args.iter().any(|&a| varies[a]);
        if index >= uniform {
            instr.form = form(instr, &varies);
        }
    }
}

/// Whether an input slot varies with (u, v): the surface parameters and the point do; `t`,
/// parameters and constants do not.
fn source_varies(source: &Source) -> bool {
    matches!(source, Source::Input(input) if *input != Input::T)
}

fn form(instr: &Instr, varies: &[bool]) -> DualForm {
    let [a, b, ..] = instr.args;
    let arithmetic = matches!(instr.op, Op::Add | Op::Sub | Op::Mul | Op::Div | Op::Mod);
    if !varies[instr.dst] {
        DualForm::ValueOnly
    } else if instr.op == Op::Mul && a == b {
        DualForm::Square
    } else if arithmetic && !varies[b] {
        DualForm::FirstVaries
    } else if arithmetic && !varies[a] {
        DualForm::SecondVaries
    } else {
        DualForm::Full
    }
}

#[cfg(test)]
mod tests {
    use super::super::{check::check, compile::compile, lexer::lex, parser::parse};
    use super::*;

    fn forms(src: &str) -> Vec<(Op, DualForm)> {
        let checked = check(parse(&lex(src, "t").unwrap(), src, "t").unwrap(), src, "t").unwrap();
        let program = compile(&checked, src, "t").unwrap();
        program.instrs[program.uniform..]
            .iter()
            .map(|i| (i.op, i.form))
            .collect()
    }

    #[test]
    fn operands_that_do_not_vary_are_left_out_of_the_partials() {
        let src = "param p = 30 in 1..100\nlet c = u % p - p / 2\n\
                   height = if c * c > 4 then 2 - c / p else floor(v) * t";
        let forms = forms(src);
        use DualForm::*;
        assert!(forms.contains(&(Op::Mod, FirstVaries)), "{forms:?}");
        assert!(forms.contains(&(Op::Sub, FirstVaries)), "{forms:?}");
        assert!(forms.contains(&(Op::Mul, Square)), "{forms:?}");
        assert!(forms.contains(&(Op::Gt, ValueOnly)), "{forms:?}");
        assert!(forms.contains(&(Op::Div, FirstVaries)), "{forms:?}");
        assert!(forms.contains(&(Op::Sub, SecondVaries)), "{forms:?}");
        assert!(forms.contains(&(Op::Floor, ValueOnly)), "{forms:?}");
        // floor(v) has no partials, nor has t: their product does not vary.
        assert!(forms.contains(&(Op::Mul, ValueOnly)), "{forms:?}");
        assert!(forms.contains(&(Op::Select, Full)), "{forms:?}");
    }
}
