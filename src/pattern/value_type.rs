//! The types of pattern expressions.

/// What a pattern expression evaluates to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Type {
    Number,
    Bool,
    Color,
}

impl Type {
    pub(super) fn describe(self) -> &'static str {
        match self {
            Type::Number => "a number",
            Type::Bool => "a condition (true/false)",
            Type::Color => "a colour",
        }
    }
}
