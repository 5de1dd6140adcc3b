//! Checker: resolves names, checks types and argument counts, and finds the single output.

use std::collections::HashMap;

use super::ast::{Ast, BinaryOp, ExprId, ExprKind, OutputKind, Stmt, UnaryOp};
use super::error::{PatternError, Span};
use super::functions::{self, Function};
use super::parser::OUTPUT_NAMES;
use super::value_type::Type;

/// The per-fragment inputs, in slot order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    U,
    V,
    X,
    Y,
    Z,
    T,
}

pub const INPUTS: [(&str, Input); 6] = [
    ("u", Input::U),
    ("v", Input::V),
    ("x", Input::X),
    ("y", Input::Y),
    ("z", Input::Z),
    ("t", Input::T),
];

/// What a name in an expression refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Binding {
    Input(Input),
    Pi,
    Param(usize),
    Let(usize),
}

/// A named, ranged parameter; the workbench shows it as a live control.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    pub name: String,
    pub default: f32,
    pub min: f32,
    pub max: f32,
}

/// A type-checked file, ready to compile.
#[derive(Debug)]
pub struct Checked {
    pub ast: Ast,
    pub bindings: HashMap<ExprId, Binding>,
    pub calls: HashMap<ExprId, Function>,
    pub params: Vec<Param>,
    /// Value expression of each `let`, in order.
    pub lets: Vec<ExprId>,
    pub output: OutputKind,
    pub output_values: Vec<ExprId>,
}

pub fn check(ast: Ast, source: &str, origin: &str) -> Result<Checked, PatternError> {
    let mut checker = Checker {
        ast: &ast,
        source,
        origin,
        scope: HashMap::new(),
        bindings: HashMap::new(),
        calls: HashMap::new(),
        let_types: Vec::new(),
        params: Vec::new(),
        lets: Vec::new(),
        output: None,
    };
    for stmt in &ast.stmts {
        checker.statement(stmt)?;
    }
    let Some((output, output_values)) = checker.output.take() else {
        let end = source.len();
        return Err(checker.error(
            Span::new(end, end),
            "expected an output: `height = …`, `slope = (…, …)` or `color = rgb(…)`",
        ));
    };
    Ok(Checked {
        bindings: checker.bindings,
        calls: checker.calls,
        params: checker.params,
        lets: checker.lets,
        output,
        output_values,
        ast,
    })
}

struct Checker<'a> {
    ast: &'a Ast,
    source: &'a str,
    origin: &'a str,
    scope: HashMap<String, Binding>,
    bindings: HashMap<ExprId, Binding>,
    calls: HashMap<ExprId, Function>,
    let_types: Vec<Type>,
    params: Vec<Param>,
    lets: Vec<ExprId>,
    output: Option<(OutputKind, Vec<ExprId>)>,
}

impl Checker<'_> {
    fn error(&self, span: Span, message: impl Into<String>) -> PatternError {
        PatternError::at(self.source, self.origin, span.start, message)
    }

    fn statement(&mut self, stmt: &Stmt) -> Result<(), PatternError> {
        match stmt {
            Stmt::Param {
                name,
                name_span,
                default,
                min,
                max,
            } => {
                self.declare(name, *name_span, Binding::Param(self.params.len()))?;
                self.params.push(Param {
                    name: name.clone(),
                    default: *default,
                    min: *min,
                    max: *max,
                });
            }
            Stmt::Let {
                name,
                name_span,
                value,
            } => {
                let ty = self.expr(*value)?;
                self.declare(name, *name_span, Binding::Let(self.lets.len()))?;
                self.lets.push(*value);
                self.let_types.push(ty);
            }
            Stmt::Output {
                kind,
                keyword_span,
                values,
            } => self.output_statement(*kind, *keyword_span, values)?,
        }
        Ok(())
    }

    fn declare(&mut self, name: &str, span: Span, binding: Binding) -> Result<(), PatternError> {
        let builtin = name == "pi"
            || OUTPUT_NAMES.contains(&name)
            || INPUTS.iter().any(|(n, _)| *n == name)
            || functions::lookup(name).is_some();
        if builtin {
            return Err(self.error(span, format!("`{name}` is built in; choose another name")));
        }
        if self.scope.contains_key(name) {
            return Err(self.error(span, format!("`{name}` is already defined")));
        }
        self.scope.insert(name.to_string(), binding);
        Ok(())
    }

    fn output_statement(
        &mut self,
        kind: OutputKind,
        span: Span,
        values: &[ExprId],
    ) -> Result<(), PatternError> {
        if self.output.is_some() {
            return Err(self.error(span, "expected one output per file, found a second one"));
        }
        let wanted = if kind == OutputKind::Color {
            Type::Color
        } else {
            Type::Number
        };
        for &value in values {
            self.expect_type(value, wanted)?;
        }
        self.output = Some((kind, values.to_vec()));
        Ok(())
    }

    fn expect_type(&mut self, id: ExprId, wanted: Type) -> Result<(), PatternError> {
        let ty = self.expr(id)?;
        if ty == wanted {
            return Ok(());
        }
        Err(self.error(
            self.ast.expr(id).span,
            format!("expected {}, found {}", wanted.describe(), ty.describe()),
        ))
    }

    /// Type of an expression. Recursion is bounded by the parser's depth limit.
    fn expr(&mut self, id: ExprId) -> Result<Type, PatternError> {
        let ty = match &self.ast.expr(id).kind {
            ExprKind::Number(_) => Type::Number,
            ExprKind::Bool(_) => Type::Bool,
            ExprKind::Name(name) => self.name(id, name)?,
            ExprKind::Unary(UnaryOp::Neg, a) => {
                self.expect_type(*a, Type::Number)?;
                Type::Number
            }
            ExprKind::Unary(UnaryOp::Not, a) => {
                self.expect_type(*a, Type::Bool)?;
                Type::Bool
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, *a, *b)?,
            ExprKind::If(c, a, b) => self.conditional(*c, *a, *b)?,
            ExprKind::Call {
                name,
                name_span,
                args,
            } => self.call(id, name, *name_span, args)?,
        };
        Ok(ty)
    }

    fn name(&mut self, id: ExprId, name: &str) -> Result<Type, PatternError> {
        let binding = if name == "pi" {
            Some(Binding::Pi)
        } else if let Some(&(_, input)) = INPUTS.iter().find(|(n, _)| *n == name) {
            Some(Binding::Input(input))
        } else {
            self.scope.get(name).copied()
        };
        let Some(binding) = binding else {
            let span = self.ast.expr(id).span;
            let hint = if functions::lookup(name).is_some() {
                format!("; `{name}` is a function: call it as `{name}(…)`")
            } else {
                self.suggestion(name)
            };
            return Err(self.error(span, format!("unknown name `{name}`{hint}")));
        };
        self.bindings.insert(id, binding);
        Ok(match binding {
            Binding::Let(i) => self.let_types[i],
            _ => Type::Number,
        })
    }

    fn suggestion(&self, name: &str) -> String {
        let known = self
            .scope
            .keys()
            .map(String::as_str)
            .chain(INPUTS.iter().map(|(n, _)| *n))
            .chain(functions::names())
            .chain(["pi"]);
        closest(name, known).map_or(String::new(), |n| format!("; did you mean `{n}`?"))
    }

    fn binary(&mut self, op: BinaryOp, a: ExprId, b: ExprId) -> Result<Type, PatternError> {
        use BinaryOp::*;
        let (operands, result) = match op {
            Add | Sub | Mul | Div | Pow | Mod => (Type::Number, Type::Number),
            Lt | Le | Gt | Ge => (Type::Number, Type::Bool),
            Eq | Ne => return self.equality(a, b),
            And | Or => (Type::Bool, Type::Bool),
        };
        self.expect_type(a, operands)?;
        self.expect_type(b, operands)?;
        Ok(result)
    }

    /// `==` and `!=` compare two numbers or two conditions (`!=` of conditions is their
    /// exclusive or), whichever the left side is.
    fn equality(&mut self, a: ExprId, b: ExprId) -> Result<Type, PatternError> {
        let left = self.expr(a)?;
        if left == Type::Color {
            return Err(self.error(
                self.ast.expr(a).span,
                "expected a number or a condition, found a colour",
            ));
        }
        self.expect_type(b, left)?;
        Ok(Type::Bool)
    }

    fn conditional(&mut self, c: ExprId, a: ExprId, b: ExprId) -> Result<Type, PatternError> {
        self.expect_type(c, Type::Bool)?;
        let ty = self.expr(a)?;
        if ty == Type::Bool {
            return Err(self.error(
                self.ast.expr(a).span,
                "expected a number or a colour in `then`, found a condition",
            ));
        }
        self.expect_type(b, ty)?;
        Ok(ty)
    }

    fn call(
        &mut self,
        id: ExprId,
        name: &str,
        span: Span,
        args: &[ExprId],
    ) -> Result<Type, PatternError> {
        let Some(function) = functions::lookup(name) else {
            let hint = closest(name, functions::names())
                .map_or(String::new(), |n| format!("; did you mean `{n}`?"));
            return Err(self.error(span, format!("unknown function `{name}`{hint}")));
        };
        if !function.arities().contains(&args.len()) {
            let call_span = self.ast.expr(id).span;
            return Err(self.error(
                call_span,
                format!(
                    "`{name}` expects {}, found {}",
                    function.describe_arities(),
                    args.len()
                ),
            ));
        }
        let mut types = Vec::with_capacity(args.len());
        for &arg in args {
            types.push(self.expr(arg)?);
        }
        self.calls.insert(id, function);
        function.result_type(&types).map_err(|(i, wanted)| {
            self.error(
                self.ast.expr(args[i]).span,
                format!(
                    "argument {} of `{name}`: expected {}, found {}",
                    i + 1,
                    wanted.describe(),
                    types[i].describe()
                ),
            )
        })
    }
}

/// The known name closest to `name` by edit distance, if it is close enough to be a likely typo.
pub fn closest<'a>(name: &str, known: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (name.chars().count() / 3).max(1);
    known
        .map(|k| (edit_distance(name, k), k))
        .filter(|&(d, _)| d <= limit)
        .min()
        .map(|(_, k)| k)
}

/// Optimal-string-alignment distance: insertions, deletions, substitutions and swaps of
/// neighbours (the commonest typo) each cost 1.
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let width = b.len() + 1;
    let mut d = vec![0; (a.len() + 1) * width];
    for i in 0..=a.len() {
        for j in 0..=b.len() {
            d[i * width + j] = if i == 0 || j == 0 {
                i + j
            } else {
                let cost = usize::from(a[i - 1] != b[j - 1]);
                let mut best = (d[(i - 1) * width + j] + 1)
                    .min(d[i * width + j - 1] + 1)
                    .min(d[(i - 1) * width + j - 1] + cost);
                if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                    best = best.min(d[(i - 2) * width + j - 2] + 1);
                }
                best
            };
        }
    }
    d[a.len() * width + b.len()]
}

#[cfg(test)]
mod tests {
    use super::super::{lexer::lex, parser::parse};
    use super::*;

    fn check_src(src: &str) -> Result<Checked, PatternError> {
        check(parse(&lex(src, "t")?, src, "t")?, src, "t")
    }

    #[test]
    fn edit_distance_counts_edits() {
        assert_eq!(edit_distance("perod", "period"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("dpeth", "depth"), 1);
    }

    #[test]
    fn unknown_name_suggests_the_closest() {
        let e = check_src("param period = 30 in 1..100\nheight = u / perod").unwrap_err();
        assert!(e.message.contains("did you mean `period`"), "{}", e.message);
        assert_eq!((e.line, e.column), (2, 14));
    }

    #[test]
    fn colour_where_number_needed_is_an_error() {
        let e = check_src("height = rgb(1, 0, 0) + 1").unwrap_err();
        assert!(e.message.contains("expected a number, found a colour"));
    }

    #[test]
    fn colour_conditionals_and_mix_are_colours() {
        let c =
            check_src("let r = rgb(1,0,0)\ncolor = mix(r, if u < 1 then r else rgb(0,0,1), 0.5)");
        assert_eq!(c.unwrap().output, OutputKind::Color);
    }

    #[test]
    fn wrong_argument_count_is_an_error() {
        let e = check_src("height = atan2(u)").unwrap_err();
        assert!(
            e.message.contains("expects 2 arguments, found 1"),
            "{}",
            e.message
        );
    }

    #[test]
    fn zero_or_two_outputs_are_errors() {
        assert!(check_src("let a = 1").is_err());
        assert!(check_src("height = u\nheight = v").is_err());
    }

    #[test]
    fn equality_compares_two_numbers_or_two_conditions() {
        assert!(check_src("height = if (u < 1) == (v < 1) then 1 else 0").is_ok());
        assert!(check_src("height = if (u < 1) != (v < 1) then 1 else 0").is_ok());
        assert!(check_src("height = if u == v then 1 else 0").is_ok());
        let mixed = check_src("height = if (u < 1) == v then 1 else 0").unwrap_err();
        assert!(
            mixed
                .message
                .contains("expected a condition (true/false), found a number"),
            "{}",
            mixed.message
        );
        let colour = check_src("height = if rgb(1, 0, 0) == u then 1 else 0").unwrap_err();
        assert!(
            colour.message.contains("found a colour"),
            "{}",
            colour.message
        );
    }

    #[test]
    fn lets_are_visible_only_after_their_definition() {
        assert!(check_src("let a = b\nlet b = 1\nheight = a").is_err());
    }
}
