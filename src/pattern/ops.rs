//! The operations of a compiled program and their meaning, defined once for plain values and
//! duals. At kinks (floor, step, abs at 0, comparisons, min/max ties) the derivative is the
//! one-sided or zero one, as usual in automatic differentiation.

use super::cells::{cells2, cells3};
use super::dual::Scalar;
use super::fractal::{fbm2, fbm3};
use super::noise::{noise2, noise3};
use super::perlin::{Graded, perlin2, perlin3};
use super::real::Real;
use num_traits::{Float, One, Zero};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Op {
    // one operand
    Neg,
    Not,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Abs,
    Sign,
    Floor,
    Ceil,
    Fract,
    Exp,
    Log,
    // two operands
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    /// Floored modulo: `a - b·floor(a/b)`, continuous across 0 (unlike C's `%`).
    Mod,
    Min,
    Max,
    Atan2,
    Hypot,
    Step,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Noise2,
    Perlin2,
    Cells2,
    // three operands
    /// `if a then b else c`; both branches are evaluated (branch-free batches).
    Select,
    Clamp,
    Mix,
    Smoothstep,
    Hypot3,
    Noise3,
    Perlin3,
    Cells3,
    /// fBm of (x, y) over `c` octaves.
    Fbm2,
    // four operands
    /// fBm of (x, y, z) over `d` octaves.
    Fbm3,
}

impl Op {
    /// Whether the op's slope changes so fast over its arguments that the `f32` rounding of
    /// two of them (`u / 14` and `u / 6`, say) shows in a gradient beyond what a shift of the
    /// inputs explains: the gradient noises, whose octaves' slopes change many times per unit.
    /// They compute in `f64` whatever their lanes, so `f64` lanes cost them little.
    pub fn amplifies_rounding(self) -> bool {
        matches!(
            self,
            Op::Perlin2 | Op::Perlin3 | Op::Cells2 | Op::Cells3 | Op::Fbm2 | Op::Fbm3
        )
    }

    /// Whether the op's result has zero partials whatever its operands (`T::constant` in
    /// `apply`): a gradient needs its value alone (`activity`).
    pub fn has_no_partials(self) -> bool {
        matches!(
            self,
            Op::Not
                | Op::Sign
                | Op::Floor
                | Op::Ceil
                | Op::Step
                | Op::Lt
                | Op::Le
                | Op::Gt
                | Op::Ge
                | Op::Eq
                | Op::Ne
                | Op::And
                | Op::Or
        )
    }
}

fn truth<R: Real>(b: bool) -> R {
    if b { R::one() } else { R::zero() }
}

/// `x` as the program's float type.
#[inline(always)]
fn k<R: Real>(x: f64) -> R {
    R::of(x)
}

/// The result of `op` on `a`, `b`, `c`, `d` (operands past the op's arity are ignored).
#[inline(always)]
pub fn apply<T: Scalar>(op: Op, a: T, b: T, c: T, d: T) -> T {
    let x = a.value();
    let one = T::Real::one();
    match op {
        Op::Neg => T::chain1(-x, a, || -one),
        Op::Not => T::constant(truth(x == T::Real::zero())),
        Op::Sin => T::chain1(x.sin(), a, || x.cos()),
        Op::Cos => T::chain1(x.cos(), a, || -x.sin()),
        Op::Tan => T::chain1(x.tan(), a, || one / (x.cos() * x.cos())),
        Op::Asin => T::chain1(x.asin(), a, || one / (one - x * x).sqrt()),
        Op::Acos => T::chain1(x.acos(), a, || -one / (one - x * x).sqrt()),
        Op::Atan => T::chain1(x.atan(), a, || one / (one + x * x)),
        Op::Sqrt => {
            let r = x.sqrt();
            T::chain1(r, a, || k::<T::Real>(0.5) / r)
        }
        Op::Abs => T::chain1(x.abs(), a, || sign(x)),
        Op::Sign => T::constant(sign(x)),
        Op::Floor => T::constant(x.floor()),
        Op::Ceil => T::constant(x.ceil()),
        Op::Fract => T::chain1(x - x.floor(), a, || one),
        Op::Exp => {
            let r = x.exp();
            T::chain1(r, a, || r)
        }
        Op::Log => T::chain1(x.ln(), a, || one / x),
        _ => apply_binary(op, a, b, c, d),
    }
}

fn sign<R: Real>(x: R) -> R {
    if x > R::zero() {
        R::one()
    } else if x < R::zero() {
        -R::one()
    } else {
        R::zero()
    }
}

#[inline(always)]
fn apply_binary<T: Scalar>(op: Op, a: T, b: T, c: T, d: T) -> T {
    let (x, y) = (a.value(), b.value());
    let (zero, one) = (T::Real::zero(), T::Real::one());
    match op {
        // Arithmetic partials are non-finite only where the value is too, so no 0·∞ guard.
        Op::Add | Op::Sub | Op::Mul | Op::Div | Op::Mod => {
            let (f, pa, pb) = arithmetic(op, x, y);
            T::arith2(f, a, b, pa, pb)
        }
        Op::Pow => {
            let r = x.powf(y);
            // x^y has no real slope in y for x <= 0; take 0 there.
            T::chain2(r, a, b, || {
                (
                    y * x.powf(y - one),
                    if x > zero { r * x.ln() } else { zero },
                )
            })
        }
        Op::Min => pick(x <= y, a, b),
        Op::Max => pick(x >= y, a, b),
        Op::Atan2 => T::chain2(y_atan2(x, y), a, b, || {
            let r2 = x * x + y * y;
            if r2 == zero {
                (zero, zero)
            } else {
                (y / r2, -x / r2)
            }
        }),
        Op::Hypot => {
            let h = x.hypot(y);
            T::chain2(h, a, b, || {
                if h == zero {
                    (zero, zero)
                } else {
                    (x / h, y / h)
                }
            })
        }
        Op::Step => T::constant(truth(y >= x)),
        Op::Lt => T::constant(truth(x < y)),
        Op::Le => T::constant(truth(x <= y)),
        Op::Gt => T::constant(truth(x > y)),
        Op::Ge => T::constant(truth(x >= y)),
        Op::Eq => T::constant(truth(x == y)),
        Op::Ne => T::constant(truth(x != y)),
        Op::And => T::constant(truth(x != zero && y != zero)),
        Op::Or => T::constant(truth(x != zero || y != zero)),
        Op::Noise2 => {
            let (n, gx, gy) = noise2(x.wide(), y.wide());
            T::chain2(k(n), a, b, || (k(gx), k(gy)))
        }
        Op::Perlin2 => graded2(perlin2(x.wide(), y.wide()), a, b),
        Op::Cells2 => graded2(cells2(x.wide(), y.wide()), a, b),
        _ => apply_ternary(op, a, b, c, d),
    }
}

/// An arithmetic op's value at (x, y) and its partials in x and in y: the one definition the
/// full chain rule and the gradient's specialised forms (`activity`) share.
#[inline(always)]
pub(crate) fn arithmetic<R: Real>(op: Op, x: R, y: R) -> (R, R, R) {
    let one = R::one();
    match op {
        Op::Add => (x + y, one, one),
        Op::Sub => (x - y, one, -one),
        Op::Mul => (x * y, y, x),
        Op::Div => {
            let q = x / y;
            (q, one / y, -q / y)
        }
        // q is finite wherever the value is (y = 0 or x/y out of range gives NaN), so the
        // arithmetic form applies.
        Op::Mod => {
            let q = (x / y).floor();
            (x - y * q, one, -q)
        }
        _ => unreachable!("{op:?} is not arithmetic"),
    }
}

/// atan2 with the language's argument order `atan2(y, x)`.
fn y_atan2<R: Real>(y: R, x: R) -> R {
    y.atan2(x)
}

#[inline(always)]
fn pick<T: Scalar>(first: bool, a: T, b: T) -> T {
    if first { a } else { b }
}

#[inline(always)]
fn apply_ternary<T: Scalar>(op: Op, a: T, b: T, c: T, d: T) -> T {
    let (x, y, z) = (a.value(), b.value(), c.value());
    let (zero, one) = (T::Real::zero(), T::Real::one());
    match op {
        Op::Select => pick(x != zero, b, c),
        Op::Clamp => {
            if x < y {
                b
            } else if x > z {
                c
            } else {
                a
            }
        }
        Op::Mix => T::chain3(x + (y - x) * z, a, b, c, || (one - z, z, y - x)),
        Op::Smoothstep => smoothstep(a, b, c),
        Op::Hypot3 => {
            let h = (x * x + y * y + z * z).sqrt();
            T::chain3(h, a, b, c, || {
                if h == zero {
                    (zero, zero, zero)
                } else {
                    (x / h, y / h, z / h)
                }
            })
        }
        Op::Noise3 => {
            let (n, g) = noise3(x.wide(), y.wide(), z.wide());
            T::chain3(k(n), a, b, c, || (k(g[0]), k(g[1]), k(g[2])))
        }
        Op::Perlin3 => graded3(perlin3(x.wide(), y.wide(), z.wide()), a, b, c),
        Op::Cells3 => graded3(cells3(x.wide(), y.wide(), z.wide()), a, b, c),
        Op::Fbm2 => graded2(fbm2(x.wide(), y.wide(), z.wide()), a, b),
        Op::Fbm3 => {
            let octaves = d.value().wide();
            graded3(fbm3([x, y, z].map(Real::wide), octaves), a, b, c)
        }
        _ => unreachable!("{op:?} is not an op of three or four operands"),
    }
}

/// A function of (a, b) computed in f64 with its gradient, as the program's scalar.
#[inline(always)]
fn graded2<T: Scalar>(result: Graded<2>, a: T, b: T) -> T {
    let [ga, gb] = result.gradient;
    T::chain2(k(result.value), a, b, || (k(ga), k(gb)))
}

/// `graded2` for a function of (a, b, c).
#[inline(always)]
fn graded3<T: Scalar>(result: Graded<3>, a: T, b: T, c: T) -> T {
    let [ga, gb, gc] = result.gradient;
    T::chain3(k(result.value), a, b, c, || (k(ga), k(gb), k(gc)))
}

/// GLSL `smoothstep(e0, e1, x)`, with its partials in all three arguments.
fn smoothstep<T: Scalar>(e0: T, e1: T, x: T) -> T {
    let (a, b, v) = (e0.value(), e1.value(), x.value());
    let (zero, one) = (T::Real::zero(), T::Real::one());
    let width = b - a;
    let s = ((v - a) / width).clamp(zero, one);
    T::chain3(
        s * s * (k::<T::Real>(3.0) - k::<T::Real>(2.0) * s),
        e0,
        e1,
        x,
        || {
            if s <= zero || s >= one {
                return (zero, zero, zero);
            }
            let slope = k::<T::Real>(6.0) * s * (one - s);
            let w2 = width * width;
            (slope * (v - b) / w2, -slope * (v - a) / w2, slope / width)
        },
    )
}

#[cfg(test)]
mod tests {
    use super::super::dual::Dual;
    use super::*;

    fn d(x: f64) -> Dual<f64> {
        Dual::input(x, 1.0, 0.0)
    }

    fn c(x: f64) -> Dual<f64> {
        Dual::constant(x)
    }

    #[test]
    fn floored_mod_is_continuous_across_zero() {
        let m = |x: f64| apply::<f64>(Op::Mod, x, 50.0, 0.0, 0.0);
        assert_eq!(m(-10.0), 40.0);
        assert_eq!(m(60.0), 10.0);
        assert_eq!(apply(Op::Mod, d(-10.0), c(50.0), c(0.0), c(0.0)).du, 1.0);
    }

    #[test]
    fn derivatives_of_unary_functions() {
        let r = apply(Op::Sin, d(0.3), c(0.0), c(0.0), c(0.0));
        assert!((r.du - 0.3f64.cos()).abs() < 1e-15);
        let r = apply(Op::Log, d(2.0), c(0.0), c(0.0), c(0.0));
        assert_eq!(r.du, 0.5);
        assert_eq!(apply(Op::Floor, d(2.5), c(0.0), c(0.0), c(0.0)).du, 0.0);
    }

    #[test]
    fn smoothstep_partials_match_finite_differences() {
        let h = 1e-6;
        let f = |e0: f64, e1: f64, x: f64| apply::<f64>(Op::Smoothstep, e0, e1, x, 0.0);
        let (e0, e1, x) = (1.0, 3.0, 1.7);
        let r = smoothstep(Dual::input(e0, 1.0, 0.0), c(e1), Dual::input(x, 0.0, 1.0));
        assert!((r.du - (f(e0 + h, e1, x) - f(e0 - h, e1, x)) / (2.0 * h)).abs() < 1e-6);
        assert!((r.dv - (f(e0, e1, x + h) - f(e0, e1, x - h)) / (2.0 * h)).abs() < 1e-6);
    }

    #[test]
    fn select_takes_the_chosen_branch_with_its_derivative() {
        let r = apply(Op::Select, c(1.0), d(2.0), c(f64::NAN), c(0.0));
        assert_eq!((r.value, r.du), (2.0, 1.0));
    }
}
