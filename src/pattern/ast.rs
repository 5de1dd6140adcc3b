//! Syntax tree of a pattern file. Expressions live in an arena (`Vec<Expr>`, children by index) so
//! that even a huge file never recurses on drop.

use super::error::Span;

pub type ExprId = usize;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Not,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Mod,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Number(f64),
    Bool(bool),
    Name(String),
    Unary(UnaryOp, ExprId),
    Binary(BinaryOp, ExprId, ExprId),
    If(ExprId, ExprId, ExprId),
    Call {
        name: String,
        name_span: Span,
        args: Vec<ExprId>,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

/// Which kind of pattern a file is, decided by its single output statement.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputKind {
    /// `height = EXPR`: a bump height; the gradient comes from automatic differentiation.
    Height,
    /// `slope = (BU, BV)`: the bump gradient given directly.
    Slope,
    /// `color = EXPR`: a linear RGB texture.
    Color,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    Param {
        name: String,
        name_span: Span,
        default: f32,
        min: f32,
        max: f32,
    },
    Let {
        name: String,
        name_span: Span,
        value: ExprId,
    },
    Output {
        kind: OutputKind,
        keyword_span: Span,
        values: Vec<ExprId>,
    },
}

/// A parsed file.
#[derive(Clone, Debug, Default)]
pub struct Ast {
    pub exprs: Vec<Expr>,
    pub stmts: Vec<Stmt>,
}

impl Ast {
    pub fn expr(&self, id: ExprId) -> &Expr {
        &self.exprs[id]
    }

    /// Direct sub-expressions of `id`.
    pub fn children(&self, id: ExprId) -> Vec<ExprId> {
        match &self.exprs[id].kind {
            ExprKind::Number(_) | ExprKind::Bool(_) | ExprKind::Name(_) => vec![],
            ExprKind::Unary(_, a) => vec![*a],
            ExprKind::Binary(_, a, b) => vec![*a, *b],
            ExprKind::If(c, a, b) => vec![*c, *a, *b],
            ExprKind::Call { args, .. } => args.clone(),
        }
    }
}
