//! Parser: tokens to `Ast`. Precedence climbing with an explicit depth limit, so a file of a
//! million `(` is an error, not a stack overflow.

use super::ast::{Ast, BinaryOp, Expr, ExprId, ExprKind, OutputKind, Stmt, UnaryOp};
use super::error::{PatternError, Span};
use super::lexer::{Tok, Token};

/// Names that start an output statement; reserved, so a dangling operator before the next
/// line's output is reported there rather than swallowing the output's name.
pub const OUTPUT_NAMES: [&str; 4] = ["height", "slope", "color", "colour"];

/// Deepest expression nesting accepted (parentheses, operators, calls, `if`s).
pub const MAX_DEPTH: usize = 256;

/// Parses a token list (ending in `Eof`) into statements.
pub fn parse(tokens: &[Token], source: &str, origin: &str) -> Result<Ast, PatternError> {
    let mut parser = Parser {
        tokens,
        pos: 0,
        source,
        origin,
        ast: Ast::default(),
        depths: Vec::new(),
        recursion: 0,
    };
    while parser.peek() != Tok::Eof {
        parser.statement()?;
    }
    Ok(parser.ast)
}

struct Parser<'a> {
    tokens: &'a [Token],
    pos: usize,
    source: &'a str,
    origin: &'a str,
    ast: Ast,
    /// Tree depth of each expression, parallel to `ast.exprs` (left-leaning chains like
    /// `1+1+1…` are built without recursion, so the tree depth is tracked separately).
    depths: Vec<usize>,
    recursion: usize,
}

/// Binding power of infix operators: (left, right). Higher binds tighter.
fn infix(tok: Tok) -> Option<(BinaryOp, u8, u8)> {
    let (op, left) = match tok {
        Tok::Or => (BinaryOp::Or, 1),
        Tok::And => (BinaryOp::And, 2),
        Tok::Lt => (BinaryOp::Lt, 4),
        Tok::Le => (BinaryOp::Le, 4),
        Tok::Gt => (BinaryOp::Gt, 4),
        Tok::Ge => (BinaryOp::Ge, 4),
        Tok::EqEq => (BinaryOp::Eq, 4),
        Tok::Ne => (BinaryOp::Ne, 4),
        Tok::Plus => (BinaryOp::Add, 5),
        Tok::Minus => (BinaryOp::Sub, 5),
        Tok::Star => (BinaryOp::Mul, 6),
        Tok::Slash => (BinaryOp::Div, 6),
        Tok::Percent => (BinaryOp::Mod, 6),
        Tok::Caret => return Some((BinaryOp::Pow, 8, 8)), // right-associative
        _ => return None,
    };
    Some((op, left, left + 1))
}

const NOT_POWER: u8 = 3;
const NEG_POWER: u8 = 7;
const COMPARISON_POWER: u8 = 4;

impl Parser<'_> {
    fn peek(&self) -> Tok {
        self.tokens[self.pos].tok
    }

    fn span(&self) -> Span {
        self.tokens[self.pos].span
    }

    fn text(&self, span: Span) -> &str {
        &self.source[span.start..span.end]
    }

    fn advance(&mut self) -> Token {
        let token = self.tokens[self.pos];
        if token.tok != Tok::Eof {
            self.pos += 1;
        }
        token
    }

    fn error(&self, span: Span, message: impl Into<String>) -> PatternError {
        PatternError::at(self.source, self.origin, span.start, message)
    }

    /// An error at the current token: "expected X, found Y".
    fn expected(&self, what: &str) -> PatternError {
        let found = match self.peek() {
            Tok::Eof => "the end of the file".to_string(),
            _ => format!("`{}`", self.text(self.span())),
        };
        self.error(self.span(), format!("expected {what}, found {found}"))
    }

    fn expect(&mut self, tok: Tok, what: &str) -> Result<Token, PatternError> {
        if self.peek() == tok {
            Ok(self.advance())
        } else {
            Err(self.expected(what))
        }
    }

    fn statement(&mut self) -> Result<(), PatternError> {
        match self.peek() {
            Tok::Param => self.param(),
            Tok::Let => self.let_binding(),
            Tok::Ident => self.output(),
            Tok::Semicolon => {
                self.advance();
                Ok(())
            }
            _ => Err(self.expected("`param`, `let`, `height =`, `slope =` or `color =`")),
        }
    }

    fn name(&mut self) -> Result<(String, Span), PatternError> {
        let token = self.expect(Tok::Ident, "a name")?;
        Ok((self.text(token.span).to_string(), token.span))
    }

    fn param(&mut self) -> Result<(), PatternError> {
        self.advance();
        let (name, name_span) = self.name()?;
        self.expect(Tok::Assign, "`=` and the default value")?;
        let (default, default_span) = self.param_number()?;
        self.expect(Tok::In, "`in MIN..MAX` (the parameter's range)")?;
        let (min, min_span) = self.param_number()?;
        self.expect(Tok::DotDot, "`..` between the range's ends")?;
        let (max, _) = self.param_number()?;
        if min >= max {
            return Err(self.error(min_span, "expected a range MIN..MAX with MIN < MAX"));
        }
        if !(min..=max).contains(&default) {
            return Err(self.error(
                default_span,
                format!("default {default} is outside the range {min}..{max}"),
            ));
        }
        self.ast.stmts.push(Stmt::Param {
            name,
            name_span,
            default,
            min,
            max,
        });
        Ok(())
    }

    /// A parameter's default or range end; parameters are `f32` for the workbench's controls.
    fn param_number(&mut self) -> Result<(f32, Span), PatternError> {
        let (value, span) = self.signed_number()?;
        let narrow = value as f32;
        if !narrow.is_finite() {
            return Err(self.error(span, "expected a number within ±3.4e38"));
        }
        Ok((narrow, span))
    }

    fn signed_number(&mut self) -> Result<(f64, Span), PatternError> {
        let start = self.span();
        let sign = if self.peek() == Tok::Minus {
            self.advance();
            -1.0
        } else {
            1.0
        };
        match self.peek() {
            Tok::Number(value) => {
                self.advance();
                Ok((sign * value, start))
            }
            Tok::Ident if self.text(self.span()) == "pi" => {
                self.advance();
                Ok((sign * std::f64::consts::PI, start))
            }
            _ => Err(self.expected("a number")),
        }
    }

    fn let_binding(&mut self) -> Result<(), PatternError> {
        self.advance();
        let (name, name_span) = self.name()?;
        self.expect(Tok::Assign, "`=` after the name")?;
        let value = self.expression(0)?;
        self.ast.stmts.push(Stmt::Let {
            name,
            name_span,
            value,
        });
        Ok(())
    }

    fn output(&mut self) -> Result<(), PatternError> {
        let keyword_span = self.span();
        let kind = match self.text(keyword_span) {
            "height" => OutputKind::Height,
            "slope" => OutputKind::Slope,
            "color" | "colour" => OutputKind::Color,
            _ => return Err(self.expected("`param`, `let`, `height =`, `slope =` or `color =`")),
        };
        self.advance();
        self.expect(Tok::Assign, "`=`")?;
        let values = if kind == OutputKind::Slope {
            self.expect(Tok::LParen, "`(BU, BV)`: the slope's two components")?;
            let bu = self.expression(0)?;
            self.expect(Tok::Comma, "`,` between the slope's two components")?;
            let bv = self.expression(0)?;
            self.expect(Tok::RParen, "`)` after the slope's two components")?;
            vec![bu, bv]
        } else {
            vec![self.expression(0)?]
        };
        self.ast.stmts.push(Stmt::Output {
            kind,
            keyword_span,
            values,
        });
        Ok(())
    }

    /// Parses an expression whose operators bind at least as tightly as `min_power`.
    fn expression(&mut self, min_power: u8) -> Result<ExprId, PatternError> {
        self.recursion += 1;
        if self.recursion > MAX_DEPTH {
            return Err(self.too_deep(self.span()));
        }
        let result = self.expression_inner(min_power);
        self.recursion -= 1;
        result
    }

    fn expression_inner(&mut self, min_power: u8) -> Result<ExprId, PatternError> {
        let mut left = self.prefix()?;
        while let Some((op, left_power, right_power)) = infix(self.peek()) {
            if left_power < min_power {
                break;
            }
            let op_span = self.advance().span;
            let right = self.expression(right_power)?;
            let span = self.ast.expr(left).span.to(self.ast.expr(right).span);
            left = self.push(ExprKind::Binary(op, left, right), span)?;
            if left_power == COMPARISON_POWER && infix(self.peek()).map(|i| i.1) == Some(left_power)
            {
                return Err(self.error(
                    op_span.to(self.span()),
                    "comparisons do not chain: write `a < b and b < c`",
                ));
            }
        }
        Ok(left)
    }

    fn prefix(&mut self) -> Result<ExprId, PatternError> {
        let token = self.advance();
        match token.tok {
            Tok::Number(value) => self.push(ExprKind::Number(value), token.span),
            Tok::True => self.push(ExprKind::Bool(true), token.span),
            Tok::False => self.push(ExprKind::Bool(false), token.span),
            Tok::Minus => self.unary(UnaryOp::Neg, NEG_POWER, token.span),
            Tok::Not => self.unary(UnaryOp::Not, NOT_POWER, token.span),
            Tok::LParen => {
                let inner = self.expression(0)?;
                self.expect(Tok::RParen, "`)`")?;
                Ok(inner)
            }
            Tok::If => self.conditional(token.span),
            Tok::Ident if !OUTPUT_NAMES.contains(&self.text(token.span)) => {
                self.name_or_call(token.span)
            }
            _ => {
                self.pos -= usize::from(token.tok != Tok::Eof);
                Err(self.expected("an expression"))
            }
        }
    }

    fn unary(&mut self, op: UnaryOp, power: u8, span: Span) -> Result<ExprId, PatternError> {
        let operand = self.expression(power)?;
        let span = span.to(self.ast.expr(operand).span);
        self.push(ExprKind::Unary(op, operand), span)
    }

    fn conditional(&mut self, span: Span) -> Result<ExprId, PatternError> {
        let condition = self.expression(0)?;
        self.expect(Tok::Then, "`then`")?;
        let yes = self.expression(0)?;
        self.expect(Tok::Else, "`else` (an `if` needs both branches)")?;
        let no = self.expression(0)?;
        let span = span.to(self.ast.expr(no).span);
        self.push(ExprKind::If(condition, yes, no), span)
    }

    fn name_or_call(&mut self, name_span: Span) -> Result<ExprId, PatternError> {
        let name = self.text(name_span).to_string();
        if self.peek() != Tok::LParen {
            return self.push(ExprKind::Name(name), name_span);
        }
        self.advance();
        let mut args = Vec::new();
        if self.peek() != Tok::RParen {
            loop {
                args.push(self.expression(0)?);
                if self.peek() != Tok::Comma {
                    break;
                }
                self.advance();
            }
        }
        let close = self.expect(Tok::RParen, "`,` or `)` in the argument list")?;
        let kind = ExprKind::Call {
            name,
            name_span,
            args,
        };
        self.push(kind, name_span.to(close.span))
    }

    fn too_deep(&self, span: Span) -> PatternError {
        self.error(
            span,
            format!(
                "expression nests too deeply (more than {MAX_DEPTH} levels): split it with `let`"
            ),
        )
    }

    fn push(&mut self, kind: ExprKind, span: Span) -> Result<ExprId, PatternError> {
        let id = self.ast.exprs.len();
        self.ast.exprs.push(Expr { kind, span });
        let depth = 1 + self
            .ast
            .children(id)
            .iter()
            .map(|&c| self.depths[c])
            .max()
            .unwrap_or(0);
        self.depths.push(depth);
        if depth > MAX_DEPTH {
            return Err(self.too_deep(span));
        }
        Ok(id)
    }
}

#[cfg(test)]
mod tests {
    use super::super::lexer::lex;
    use super::*;

    fn parse_src(src: &str) -> Result<Ast, PatternError> {
        parse(&lex(src, "t.pat")?, src, "t.pat")
    }

    fn output_expr(src: &str) -> (Ast, ExprId) {
        let ast = parse_src(src).unwrap();
        let Some(Stmt::Output { values, .. }) = ast.stmts.last().cloned() else {
            panic!("no output")
        };
        (ast, values[0])
    }

    #[test]
    fn multiplication_binds_tighter_than_addition() {
        let (ast, root) = output_expr("height = 1 + 2 * 3");
        assert!(matches!(
            ast.expr(root).kind,
            ExprKind::Binary(BinaryOp::Add, _, _)
        ));
    }

    #[test]
    fn power_is_right_associative_and_above_negation() {
        let (ast, root) = output_expr("height = -2 ^ 3 ^ 2");
        let ExprKind::Unary(UnaryOp::Neg, pow) = ast.expr(root).kind else {
            panic!()
        };
        let ExprKind::Binary(BinaryOp::Pow, _, right) = ast.expr(pow).kind else {
            panic!()
        };
        assert!(matches!(
            ast.expr(right).kind,
            ExprKind::Binary(BinaryOp::Pow, _, _)
        ));
    }

    #[test]
    fn params_lets_and_outputs() {
        let ast = parse_src("param p = 2 in -1..3\nlet a = p * u\nslope = (a, 0)").unwrap();
        assert_eq!(ast.stmts.len(), 3);
        assert!(matches!(ast.stmts[0], Stmt::Param { min: -1.0, .. }));
    }

    #[test]
    fn bad_range_and_default_are_errors() {
        assert!(parse_src("param p = 5 in 0..3").is_err());
        assert!(parse_src("param p = 1 in 3..3").is_err());
        assert!(
            parse_src("param p = 1 in 1..1.00000001").is_err(),
            "equal as f32"
        );
        assert!(parse_src("param p = 1 in 0..1e39").is_err());
    }

    #[test]
    fn chained_comparison_is_an_error() {
        assert!(parse_src("height = if 1 < u < 2 then 1 else 0").is_err());
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_crash() {
        let src = format!(
            "height = {}1{}",
            "(".repeat(1_000_000),
            ")".repeat(1_000_000)
        );
        let e = parse_src(&src).unwrap_err();
        assert!(e.message.contains("too deeply"));
        let chain = format!("height = 1{}", "+1".repeat(1000));
        assert!(parse_src(&chain).is_err());
    }

    #[test]
    fn missing_else_points_at_the_spot() {
        let e = parse_src("height = if u > 1 then 1").unwrap_err();
        assert_eq!((e.line, e.column), (1, 25));
    }
}
