//! Forward-mode automatic differentiation: `Dual` carries a value and its partials with respect
//! to the surface parameters u and v. `Scalar` lets one definition of every operation serve both
//! plain values (`f64`, derivatives never computed) and duals.

/// A number the evaluator computes with: `f64` for values only, `Dual` for value + gradient.
pub trait Scalar: Copy + Default + Send + Sync + 'static {
    /// Whether this type carries derivatives (so inputs must supply their partials).
    const DUAL: bool;

    /// A value that does not vary with u or v.
    fn constant(value: f64) -> Self;

    /// An input with its partials ∂/∂u and ∂/∂v.
    fn input(value: f64, du: f64, dv: f64) -> Self;

    fn value(self) -> f64;

    /// `f(a)` given its value `f` and, lazily, `f'(a)`.
    fn chain1(f: f64, a: Self, partial: impl FnOnce() -> f64) -> Self;

    /// `f(a, b)` given its value and, lazily, `(∂f/∂a, ∂f/∂b)`.
    fn chain2(f: f64, a: Self, b: Self, partials: impl FnOnce() -> (f64, f64)) -> Self;

    /// Like `chain2`, for partials that are finite wherever `f` is (arithmetic): skips the
    /// 0·∞ guard, which is then never needed.
    fn arith2(f: f64, a: Self, b: Self, pa: f64, pb: f64) -> Self;

    /// `f(a, b, c)` given its value and, lazily, its three partials.
    fn chain3(
        f: f64,
        a: Self,
        b: Self,
        c: Self,
        partials: impl FnOnce() -> (f64, f64, f64),
    ) -> Self;
}

impl Scalar for f64 {
    const DUAL: bool = false;

    fn constant(value: f64) -> f64 {
        value
    }

    fn input(value: f64, _: f64, _: f64) -> f64 {
        value
    }

    fn value(self) -> f64 {
        self
    }

    fn chain1(f: f64, _: f64, _: impl FnOnce() -> f64) -> f64 {
        f
    }

    fn chain2(f: f64, _: f64, _: f64, _: impl FnOnce() -> (f64, f64)) -> f64 {
        f
    }

    fn chain3(f: f64, _: f64, _: f64, _: f64, _: impl FnOnce() -> (f64, f64, f64)) -> f64 {
        f
    }

    fn arith2(f: f64, _: f64, _: f64, _: f64, _: f64) -> f64 {
        f
    }
}

/// A value with its partial derivatives with respect to u and v.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Dual {
    pub value: f64,
    pub du: f64,
    pub dv: f64,
}

/// `partial · derivative`, taking 0 · ∞ as 0: an argument that does not vary contributes nothing,
/// even where the function's slope is infinite (e.g. `sqrt(max(0, r))` outside the bump).
#[inline(always)]
fn times(partial: f64, derivative: f64) -> f64 {
    if derivative == 0.0 {
        0.0
    } else {
        partial * derivative
    }
}

impl Scalar for Dual {
    const DUAL: bool = true;

    fn constant(value: f64) -> Dual {
        Dual {
            value,
            du: 0.0,
            dv: 0.0,
        }
    }

    fn input(value: f64, du: f64, dv: f64) -> Dual {
        Dual { value, du, dv }
    }

    fn value(self) -> f64 {
        self.value
    }

    #[inline(always)]
    fn chain1(f: f64, a: Dual, partial: impl FnOnce() -> f64) -> Dual {
        let p = partial();
        Dual {
            value: f,
            du: times(p, a.du),
            dv: times(p, a.dv),
        }
    }

    #[inline(always)]
    fn chain2(f: f64, a: Dual, b: Dual, partials: impl FnOnce() -> (f64, f64)) -> Dual {
        let (pa, pb) = partials();
        Dual {
            value: f,
            du: times(pa, a.du) + times(pb, b.du),
            dv: times(pa, a.dv) + times(pb, b.dv),
        }
    }

    #[inline(always)]
    fn arith2(f: f64, a: Dual, b: Dual, pa: f64, pb: f64) -> Dual {
        Dual {
            value: f,
            du: pa * a.du + pb * b.du,
            dv: pa * a.dv + pb * b.dv,
        }
    }

    #[inline(always)]
    fn chain3(
        f: f64,
        a: Dual,
        b: Dual,
        c: Dual,
        partials: impl FnOnce() -> (f64, f64, f64),
    ) -> Dual {
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
        let a = Dual::input(3.0, 1.0, 0.0);
        let b = Dual::input(2.0, 0.0, 1.0);
        let p = Dual::chain2(6.0, a, b, || (b.value, a.value));
        assert_eq!(p, Dual::input(6.0, 2.0, 3.0));
    }

    #[test]
    fn infinite_slope_times_constant_is_zero() {
        let c = Dual::constant(0.0);
        let r = Dual::chain1(0.0, c, || f64::INFINITY);
        assert_eq!((r.du, r.dv), (0.0, 0.0));
    }

    #[test]
    fn plain_values_skip_partials() {
        let r = f64::chain1(2.0, 1.0, || panic!("partials computed for a plain value"));
        assert_eq!(r, 2.0);
    }
}
