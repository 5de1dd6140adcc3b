//! Forward-mode automatic differentiation: `Dual` carries a value and its partials with respect
//! to the surface parameters u and v. `Scalar` lets one definition of every operation serve both
//! plain values (derivatives never computed) and duals, in either precision.

use super::real::Real;

/// A number the evaluator computes with: a `Real` for values only, `Dual` for value + gradient.
pub trait Scalar: Copy + Default + Send + Sync + 'static {
    /// The float type of the value and partials.
    type Real: Real;

    /// Whether this type carries derivatives (so inputs must supply their partials).
    const DUAL: bool;

    /// A value that does not vary with u or v.
    fn constant(value: Self::Real) -> Self;

    /// An input with its partials ∂/∂u and ∂/∂v.
    fn input(value: Self::Real, du: Self::Real, dv: Self::Real) -> Self;

    fn value(self) -> Self::Real;

    /// `f(a)` given its value `f` and, lazily, `f'(a)`.
    fn chain1(f: Self::Real, a: Self, partial: impl FnOnce() -> Self::Real) -> Self;

    /// `f(a, b)` given its value and, lazily, `(∂f/∂a, ∂f/∂b)`.
    fn chain2(
        f: Self::Real,
        a: Self,
        b: Self,
        partials: impl FnOnce() -> (Self::Real, Self::Real),
    ) -> Self;

    /// Like `chain2`, for partials that are finite wherever `f` is (arithmetic): skips the
    /// 0·∞ guard, which is then never needed.
    fn arith2(f: Self::Real, a: Self, b: Self, pa: Self::Real, pb: Self::Real) -> Self;

    /// `f(a, b, c)` given its value and, lazily, its three partials.
    fn chain3(
        f: Self::Real,
        a: Self,
        b: Self,
        c: Self,
        partials: impl FnOnce() -> (Self::Real, Self::Real, Self::Real),
    ) -> Self;
}

impl<R: Real> Scalar for R {
    type Real = R;

    const DUAL: bool = false;

    #[inline(always)]
    fn constant(value: R) -> R {
        value
    }

    #[inline(always)]
    fn input(value: R, _: R, _: R) -> R {
        value
    }

    #[inline(always)]
    fn value(self) -> R {
        self
    }

    #[inline(always)]
    fn chain1(f: R, _: R, _: impl FnOnce() -> R) -> R {
        f
    }

    #[inline(always)]
    fn chain2(f: R, _: R, _: R, _: impl FnOnce() -> (R, R)) -> R {
        f
    }

    #[inline(always)]
    fn chain3(f: R, _: R, _: R, _: R, _: impl FnOnce() -> (R, R, R)) -> R {
        f
    }

    #[inline(always)]
    fn arith2(f: R, _: R, _: R, _: R, _: R) -> R {
        f
    }
}

/// A value with its partial derivatives with respect to u and v.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Dual<R> {
    pub value: R,
    pub du: R,
    pub dv: R,
}

/// `partial · derivative`, taking 0 · ∞ as 0: an argument that does not vary contributes nothing,
/// even where the function's slope is infinite (e.g. `sqrt(max(0, r))` outside the bump).
#[inline(always)]
fn times<R: Real>(partial: R, derivative: R) -> R {
    if derivative == R::zero() {
        R::zero()
    } else {
        partial * derivative
    }
}

impl<R: Real> Scalar for Dual<R> {
    type Real = R;

    const DUAL: bool = true;

    #[inline(always)]
    fn constant(value: R) -> Dual<R> {
        Dual {
            value,
            du: R::zero(),
            dv: R::zero(),
        }
    }

    #[inline(always)]
    fn input(value: R, du: R, dv: R) -> Dual<R> {
        Dual { value, du, dv }
    }

    #[inline(always)]
    fn value(self) -> R {
        self.value
    }

    #[inline(always)]
    fn chain1(f: R, a: Dual<R>, partial: impl FnOnce() -> R) -> Dual<R> {
        let p = partial();
        Dual {
            value: f,
            du: times(p, a.du),
            dv: times(p, a.dv),
        }
    }

    #[inline(always)]
    fn chain2(f: R, a: Dual<R>, b: Dual<R>, partials: impl FnOnce() -> (R, R)) -> Dual<R> {
        let (pa, pb) = partials();
        Dual {
            value: f,
            du: times(pa, a.du) + times(pb, b.du),
            dv: times(pa, a.dv) + times(pb, b.dv),
        }
    }

    #[inline(always)]
    fn arith2(f: R, a: Dual<R>, b: Dual<R>, pa: R, pb: R) -> Dual<R> {
        Dual {
            value: f,
            du: pa * a.du + pb * b.du,
            dv: pa * a.dv + pb * b.dv,
        }
    }

    #[inline(always)]
    fn chain3(
        f: R,
        a: Dual<R>,
        b: Dual<R>,
        c: Dual<R>,
        partials: impl FnOnce() -> (R, R, R),
    ) -> Dual<R> {
        let (pa, pb, pc) = partials();
        Dual {
            value: f,
            du: times(pa, a.du) + times(pb, b.du) + times(pc, c.du),
            dv: times(pa, a.dv) + times(pb, b.dv) + times(pc, c.dv),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_rule() {
        let a = Dual::<f64>::input(3.0, 1.0, 0.0);
        let b = Dual::input(2.0, 0.0, 1.0);
        let p = Dual::chain2(6.0, a, b, || (b.value, a.value));
        assert_eq!(p, Dual::input(6.0, 2.0, 3.0));
    }

    #[test]
    fn infinite_slope_times_constant_is_zero() {
        let c = Dual::<f64>::constant(0.0);
        let r = Dual::chain1(0.0, c, || f64::INFINITY);
        assert_eq!((r.du, r.dv), (0.0, 0.0));
    }

    #[test]
    fn plain_values_skip_partials() {
        let r = f64::chain1(2.0, 1.0, || panic!("partials computed for a plain value"));
        assert_eq!(r, 2.0);
    }
}
