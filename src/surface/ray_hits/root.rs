//! Safeguarded Newton root finding, for surfaces without a closed-form intersection.

/// A root of `f` in [lo, hi], where f(lo) and f(hi) differ in sign (or one is zero): Newton steps
/// on f and its derivative, falling back to bisection whenever a step would leave the bracket or
/// fails to halve it, so it always converges (to f64 resolution of the bracket).
pub(super) fn safeguarded_root(
    f: impl Fn(f64) -> f64,
    df: impl Fn(f64) -> f64,
    mut lo: f64,
    mut hi: f64,
) -> f64 {
    let f_lo = f(lo);
    if f_lo == 0.0 {
        return lo;
    }
    if f(hi) == 0.0 {
        return hi;
    }
    let lo_negative = f_lo < 0.0;
    let mut t = 0.5 * (lo + hi);
    let mut previous_width = hi - lo;
    for _ in 0..200 {
        let value = f(t);
        if value == 0.0 {
            return t;
        }
        if (value < 0.0) == lo_negative {
            lo = t;
        } else {
            hi = t;
        }
        let width = hi - lo;
        if width <= 1e-14 * lo.abs().max(hi.abs()).max(1e-300) {
            break;
        }
        let newton = t - value / df(t);
        let stalled = width > 0.5 * previous_width;
        previous_width = width;
        t = if newton > lo && newton < hi && !stalled {
            newton
        } else {
            0.5 * (lo + hi)
        };
    }
    0.5 * (lo + hi)
}

/// Where the monotone function `g` changes sign in [lo, hi] (g(lo) and g(hi) of opposite signs),
/// by bisection: for the extremum of a convex or concave piece, where g is its derivative.
pub(super) fn bisect_sign_change(g: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let lo_negative = g(lo) < 0.0;
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if (g(mid) < 0.0) == lo_negative {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn converges_on_a_smooth_root() {
        let r = safeguarded_root(|t| t * t - 2.0, |t| 2.0 * t, 0.0, 2.0);
        assert!((r - 2f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn survives_a_useless_derivative() {
        // The derivative is zero at the start and wrong everywhere: bisection carries it.
        let r = safeguarded_root(|t| (t - 0.3).powi(3), |_| 0.0, -1.0, 1.0);
        assert!((r - 0.3).abs() < 1e-4, "{r}");
    }
}
