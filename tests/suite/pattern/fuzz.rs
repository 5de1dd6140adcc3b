//! `Pattern::compile` never panics, whatever the input; what compiles evaluates to finite
//! outputs.

use bumpwork::pattern::{BumpSample, Inputs, OutputKind, Pattern};
use proptest::prelude::*;

const TOKENS: &[&str] = &[
    "height", "slope", "color", "=", "let", "param", "in", "..", "if", "then", "else", "and", "or",
    "not", "(", ")", ",", "+", "-", "*", "/", "^", "%", "<", "<=", "==", "!=", ">", "u", "v", "x",
    "t", "pi", "a", "b", "1", "0", "2.5", "1e9", "sin", "sqrt", "noise", "rgb", "mix", "clamp",
    "length", "perlin", "cells", "fbm", "#", "\n", "\u{1b}", "é", "true",
];

fn tokens(max: usize) -> impl Strategy<Value = String> {
    prop::collection::vec(prop::sample::select(TOKENS), 0..max).prop_map(|t| t.join(" "))
}

fn token_soup() -> impl Strategy<Value = String> {
    tokens(60)
}

const OPERATORS: &[&str] = &["+", "-", "*", "/", "^", "%"];
const OPERANDS: &[&str] = &[
    "u",
    "v",
    "x",
    "y",
    "z",
    "t",
    "pi",
    "0",
    "1",
    "2.5",
    "1e9",
    "-3",
    "sin(u)",
    "sqrt(v - 100)",
    "log(x)",
    "noise(u, v)",
    "noise(x, y, z)",
    "perlin(u, v)",
    "perlin(x, y, t)",
    "cells(u / 9, v)",
    "cells(x, y, 1e30)",
    "fbm(u, v, 1e9)",
    "fbm(x, y, z, v)",
    "(u - 200)",
    "atan2(v, u)",
    "floor(u / 7)",
    "smoothstep(0, 1, v)",
    "if u < v then 1 / x else t",
];

/// A few operator-operand pairs and, now and then, a stray token.
fn splice() -> impl Strategy<Value = String> {
    let term = (
        prop::sample::select(OPERATORS),
        prop::sample::select(OPERANDS),
    );
    (prop::collection::vec(term, 0..5), tokens(2)).prop_map(|(terms, stray)| {
        let terms: Vec<String> = terms.iter().map(|(op, x)| format!("{op} {x}")).collect();
        format!("{} {stray}", terms.join(" "))
    })
}

/// Arithmetic on the inputs with stray tokens, so that many programs (about a quarter) compile and get
/// evaluated.
fn near_valid() -> impl Strategy<Value = String> {
    (splice(), splice(), 0..3usize).prop_map(|(a, b, kind)| {
        let (open, close) = [
            ("height = ", ""),
            ("slope = (u, ", ")"),
            ("color = rgb(1, ", ", 0)"),
        ][kind];
        format!("let a = u {a}\n{open}a {b}{close}")
    })
}

fn evaluate(pattern: &Pattern) {
    let u: Vec<f32> = (0..100).map(|i| i as f32 * 7.3 - 300.0).collect();
    let v: Vec<f32> = u.iter().rev().copied().collect();
    let inputs = Inputs {
        x: &u,
        y: &v,
        z: &u,
        x_u: &v,
        x_v: &u,
        y_u: &u,
        y_v: &v,
        z_u: &v,
        z_v: &u,
        ..Inputs::uv(&u, &v, 1e7)
    };
    let mut scratch = pattern.scratch();
    if pattern.output() == OutputKind::Color {
        let mut out = vec![[0.0; 3]; u.len()];
        pattern.eval_color(&inputs, &[], &mut scratch, &mut out);
        assert!(out.iter().flatten().all(|c| (0.0..=1.0).contains(c)));
    } else {
        let mut out = vec![BumpSample::default(); u.len()];
        pattern.eval_bump(&inputs, &[], &mut scratch, &mut out);
        assert!(
            out.iter()
                .all(|s| s.height.is_finite() && s.du.is_finite() && s.dv.is_finite())
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_text_never_panics(source in "\\PC{0,200}") {
        let _ = Pattern::compile(&source, "fuzz.pat");
    }

    #[test]
    fn token_soups_never_panic(source in token_soup()) {
        if let Ok(pattern) = Pattern::compile(&source, "fuzz.pat") {
            evaluate(&pattern);
        }
    }

    #[test]
    fn near_valid_programs_never_panic(source in near_valid()) {
        match Pattern::compile(&source, "fuzz.pat") {
            Ok(pattern) => evaluate(&pattern),
            Err(e) => prop_assert!(e.line >= 1 && e.column >= 1),
        }
    }
}
