//! The built-in functions of the language: names, arities and argument types.

use super::check::Type;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Function {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sqrt,
    Abs,
    Sign,
    Floor,
    Ceil,
    Fract,
    Mod,
    Min,
    Max,
    Clamp,
    Mix,
    Step,
    Smoothstep,
    Exp,
    Log,
    Pow,
    Hypot,
    Length,
    Noise,
    Rgb,
}

/// Every function name, for lookup and "did you mean" suggestions.
pub const FUNCTIONS: &[(&str, Function)] = &[
    ("sin", Function::Sin),
    ("cos", Function::Cos),
    ("tan", Function::Tan),
    ("asin", Function::Asin),
    ("acos", Function::Acos),
    ("atan", Function::Atan),
    ("atan2", Function::Atan2),
    ("sqrt", Function::Sqrt),
    ("abs", Function::Abs),
    ("sign", Function::Sign),
    ("floor", Function::Floor),
    ("ceil", Function::Ceil),
    ("fract", Function::Fract),
    ("mod", Function::Mod),
    ("min", Function::Min),
    ("max", Function::Max),
    ("clamp", Function::Clamp),
    ("mix", Function::Mix),
    ("step", Function::Step),
    ("smoothstep", Function::Smoothstep),
    ("exp", Function::Exp),
    ("log", Function::Log),
    ("pow", Function::Pow),
    ("hypot", Function::Hypot),
    ("length", Function::Length),
    ("noise", Function::Noise),
    ("rgb", Function::Rgb),
];

pub fn lookup(name: &str) -> Option<Function> {
    FUNCTIONS.iter().find(|(n, _)| *n == name).map(|&(_, f)| f)
}

impl Function {
    /// The argument counts this function accepts.
    pub fn arities(self) -> &'static [usize] {
        use Function::*;
        match self {
            Sin | Cos | Tan | Asin | Acos | Atan | Sqrt | Abs | Sign | Floor | Ceil | Fract
            | Exp | Log => &[1],
            Atan2 | Mod | Min | Max | Step | Pow | Hypot => &[2],
            Clamp | Mix | Smoothstep | Rgb => &[3],
            Length | Noise => &[2, 3],
        }
    }

    /// Result type for the given argument types, or the index of the first bad argument and
    /// the type it should have had.
    pub fn result_type(self, args: &[Type]) -> Result<Type, (usize, Type)> {
        let colour_mix = self == Function::Mix && args.first() == Some(&Type::Color);
        let expected = |i: usize| {
            if colour_mix && i < 2 {
                Type::Color
            } else {
                Type::Number
            }
        };
        for (i, &arg) in args.iter().enumerate() {
            if arg != expected(i) {
                return Err((i, expected(i)));
            }
        }
        Ok(if colour_mix || self == Function::Rgb {
            Type::Color
        } else {
            Type::Number
        })
    }

    pub fn describe_arities(self) -> String {
        let counts: Vec<String> = self.arities().iter().map(usize::to_string).collect();
        let n = counts.join(" or ");
        let plural = if self.arities() == [1] { "" } else { "s" };
        format!("{n} argument{plural}")
    }
}
