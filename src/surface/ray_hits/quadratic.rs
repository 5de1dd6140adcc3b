//! Quadratic roots without cancellation, for the ray intersections.

/// The distinct real roots of a·t² + b·t + c = 0 in increasing order (NaN where there are fewer
/// than two), without cancellation (see `ordered_roots`).
pub fn quadratic_roots(a: f64, b: f64, c: f64) -> [f64; 2] {
    let (first, second, real) = ordered_roots(a, b, c);
    let root = |t: f64| if real && t.is_finite() { t } else { f64::NAN };
    let second = if second == first { f64::NAN } else { second };
    [root(first), root(second)]
}

/// The roots of a·t² + b·t + c = 0 in increasing order and whether they are real (either may be
/// non-finite where `a` vanishes), without cancellation: c/q and q/a for
/// q = −(b + sign(b)·√disc)/2, so a vanishing `a` (a ray along a cone's side) leaves the linear
/// root −c/b accurate. Branch-free, so loops of it vectorise.
#[inline(always)]
pub(crate) fn ordered_roots(a: f64, b: f64, c: f64) -> (f64, f64, bool) {
    let discriminant = b * b - 4.0 * a * c;
    let q = -0.5 * (b + discriminant.max(0.0).sqrt().copysign(b));
    // q = 0 only when b = 0 and a or c is 0: a root at 0 where c is 0, none where only a is.
    let real = discriminant >= 0.0 && discriminant.is_finite() && (q != 0.0 || c == 0.0);
    let (one, other) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q / a) };
    let (first, second) = if other < one {
        (other, one)
    } else {
        (one, other)
    };
    (first, second, real)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sorted(roots: [f64; 2]) -> Vec<f64> {
        let mut roots: Vec<f64> = roots.into_iter().filter(|r| !r.is_nan()).collect();
        roots.sort_by(f64::total_cmp);
        roots
    }

    #[test]
    fn finds_both_roots_without_cancellation() {
        let r = sorted(quadratic_roots(1.0, -1e8, 1.0));
        assert!((r[0] - 1e-8).abs() < 1e-20, "{r:?}");
        assert!((r[1] - 1e8).abs() < 1e-4);
    }

    #[test]
    fn degenerates_gracefully() {
        assert_eq!(sorted(quadratic_roots(0.0, 2.0, -4.0)), vec![2.0]);
        assert!(sorted(quadratic_roots(0.0, 0.0, 1.0)).is_empty());
        assert!(sorted(quadratic_roots(1.0, 0.0, 1.0)).is_empty());
        assert_eq!(sorted(quadratic_roots(1.0, 0.0, 0.0)), vec![0.0]);
        let tiny_a = sorted(quadratic_roots(1e-30, 2.0, -4.0));
        assert!(tiny_a.iter().any(|r| (r - 2.0).abs() < 1e-12), "{tiny_a:?}");
    }

    #[test]
    fn roots_come_in_order_without_cancellation() {
        // (s − 1e-6)(s − 1e6) = s² − (1e6 + 1e-6)s + 1.
        let (small, large, real) = ordered_roots(1.0, -(1e6 + 1e-6), 1.0);
        assert!(real && (small - 1e-6).abs() < 1e-18 && (large - 1e6).abs() < 1e-6);
        // a = 0: the linear root, and the other one at infinity.
        let (none, only, real) = ordered_roots(0.0, 2.0, -4.0);
        assert!(real && only == 2.0 && !none.is_finite());
        assert!(!ordered_roots(1.0, 0.0, 1.0).2);
        assert!(!ordered_roots(0.0, 0.0, 1.0).2);
        assert_eq!(ordered_roots(1.0, 0.0, 0.0), (0.0, 0.0, true));
        assert_eq!(ordered_roots(1.0, -2.0, -15.0), (-3.0, 5.0, true));
    }
}
