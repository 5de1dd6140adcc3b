//! The built-in functions of the language: names, arities and argument types.

use super::value_type::Type;

/// A built-in function; its name in a pattern file is the variant's, in lower case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, strum::VariantArray, strum::IntoStaticStr)]
#[strum(serialize_all = "lowercase")]
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
    Perlin,
    Cells,
    Fbm,
    Rgb,
}

/// Every function's name as a pattern file writes it, for lookup and "did you mean"
/// suggestions.
pub fn names<'a>() -> impl Iterator<Item = &'a str> {
    <Function as strum::VariantArray>::VARIANTS
        .iter()
        .map(|&f| -> &'a str { f.name() })
}

pub fn lookup(name: &str) -> Option<Function> {
    <Function as strum::VariantArray>::VARIANTS
        .iter()
        .copied()
        .find(|f| f.name() == name)
}

impl Function {
    /// The name a pattern file calls it by.
    pub fn name(self) -> &'static str {
        self.into()
    }

    /// The argument counts this function accepts.
    pub fn arities(self) -> &'static [usize] {
        use Function::*;
        match self {
            Sin | Cos | Tan | Asin | Acos | Atan | Sqrt | Abs | Sign | Floor | Ceil | Fract
            | Exp | Log => &[1],
            Atan2 | Mod | Min | Max | Step | Pow | Hypot => &[2],
            Clamp | Mix | Smoothstep | Rgb => &[3],
            Length | Noise | Perlin | Cells => &[2, 3],
            Fbm => &[3, 4],
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

#[cfg(test)]
mod name_tests {
    use super::*;

    #[test]
    fn every_function_is_found_by_its_name_and_the_language_reference_lists_it() {
        let reference = include_str!("../../patterns/README.md");
        for name in names() {
            let function = lookup(name).expect("a name finds its function");
            assert_eq!(function.name(), name);
            assert!(
                reference.contains(name),
                "patterns/README.md does not list `{name}`"
            );
        }
        assert_eq!(lookup("atan2"), Some(Function::Atan2));
        assert_eq!(lookup("smoothstep"), Some(Function::Smoothstep));
        assert_eq!(lookup("Sin"), None, "names are lower case");
    }
}
