//! Quadratic roots without cancellation, for the ray intersections.

/// The real roots of a·t² + b·t + c = 0 (unsorted; NaN where there are fewer than two), without
/// cancellation: the larger root in magnitude from the stable formula and the other from the
/// product of the roots (c/a), so that a nearly vanishing `a` (a ray almost parallel to a cone's
/// side) still gives the near-linear root accurately.
pub(super) fn quadratic_roots(a: f64, b: f64, c: f64) -> [f64; 2] {
    const NONE: f64 = f64::NAN;
    if a == 0.0 {
        return if b == 0.0 { [NONE; 2] } else { [-c / b, NONE] };
    }
    let discriminant = b * b - 4.0 * a * c;
    if discriminant < 0.0 || !discriminant.is_finite() {
        return [NONE; 2];
    }
    let q = -0.5 * (b + discriminant.sqrt().copysign(b));
    if q == 0.0 {
        // b = 0 and c = 0: a double root at 0.
        return [0.0, NONE];
    }
    [q / a, c / q]
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
}
