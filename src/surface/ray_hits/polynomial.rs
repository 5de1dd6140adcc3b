//! Every real root of a polynomial of low degree inside an interval, by isolating them between
//! the roots of its derivative (found the same way): on each piece between two critical points
//! the polynomial is monotone, so a sign change brackets exactly one root, which safeguarded
//! Newton then refines. No closed form, so no cancellation (Ferrari's quartic loses most of its
//! digits on a grazing ray); a double root where the polynomial only touches zero is not a sign
//! change and is not reported.

use super::root::safeguarded_root;

/// The highest degree handled.
pub const MAX_DEGREE: usize = 4;

/// The real roots of Σ coefficients[i]·xⁱ (at most `MAX_DEGREE` + 1 coefficients, lowest
/// degree first) in [lo, hi], in increasing order, into `roots`; returns how many there are.
pub fn polynomial_roots_in(coefficients: &[f64], lo: f64, hi: f64, roots: &mut [f64]) -> usize {
    let degree = coefficients.iter().rposition(|&c| c != 0.0).unwrap_or(0);
    assert!(degree <= MAX_DEGREE, "degree {degree} polynomial");
    let c = &coefficients[..=degree];
    let ordered = lo <= hi;
    if degree == 0 || !ordered {
        return 0;
    }
    if degree == 1 {
        let root = -c[0] / c[1];
        let inside = (lo..=hi).contains(&root);
        roots[0] = root;
        return usize::from(inside);
    }
    let mut derivative = [0.0; MAX_DEGREE];
    for i in 1..=degree {
        derivative[i - 1] = c[i] * i as f64;
    }
    let mut critical = [0.0; MAX_DEGREE];
    let found = polynomial_roots_in(&derivative[..degree], lo, hi, &mut critical);
    let value = |x: f64| horner(c, x);
    let slope = |x: f64| horner(&derivative[..degree], x);
    let mut count = 0;
    let mut start = lo;
    for end in critical[..found].iter().copied().chain([hi]) {
        if end <= start && end != hi {
            continue;
        }
        let (f_start, f_end) = (value(start), value(end));
        let root = if f_start == 0.0 {
            Some(start)
        } else if (f_start < 0.0) != (f_end < 0.0) && f_end != 0.0 {
            Some(safeguarded_root(value, slope, start, end))
        } else {
            None
        };
        if let Some(root) = root.filter(|&r| count == 0 || r > roots[count - 1]) {
            roots[count] = root;
            count += 1;
        }
        start = end;
    }
    if value(hi) == 0.0 && (count == 0 || roots[count - 1] < hi) {
        roots[count] = hi;
        count += 1;
    }
    count
}

/// Σ c[i]·xⁱ.
fn horner(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |sum, &ci| sum * x + ci)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots_of(coefficients: &[f64], lo: f64, hi: f64) -> Vec<f64> {
        let mut roots = [0.0; MAX_DEGREE];
        let n = polynomial_roots_in(coefficients, lo, hi, &mut roots);
        roots[..n].to_vec()
    }

    /// (x − a)(x − b)(x − c)(x − d), lowest degree first.
    fn quartic_with_roots([a, b, c, d]: [f64; 4]) -> [f64; 5] {
        let mut p = [1.0, 0.0, 0.0, 0.0, 0.0];
        for (k, root) in [a, b, c, d].into_iter().enumerate() {
            for i in (0..=k + 1).rev() {
                let lower = if i > 0 { p[i - 1] } else { 0.0 };
                p[i] = lower - root * p[i];
            }
        }
        p
    }

    #[test]
    fn finds_four_distinct_roots_in_order() {
        let roots = roots_of(&quartic_with_roots([-3.0, 0.5, 0.25, 7.0]), -10.0, 10.0);
        let expected = [-3.0, 0.25, 0.5, 7.0];
        assert_eq!(roots.len(), 4, "{roots:?}");
        for (got, want) in roots.iter().zip(expected) {
            assert!((got - want).abs() < 1e-12, "{roots:?}");
        }
    }

    #[test]
    fn keeps_to_the_interval() {
        let roots = roots_of(&quartic_with_roots([-3.0, 0.5, 0.25, 7.0]), 0.0, 1.0);
        assert_eq!(roots.len(), 2, "{roots:?}");
        assert!(roots_of(&quartic_with_roots([-3.0, 0.5, 0.25, 7.0]), 8.0, 9.0).is_empty());
    }

    #[test]
    fn close_roots_stay_apart() {
        let p = quartic_with_roots([1.0, 1.0 + 1e-6, 5.0, 6.0]);
        let roots = roots_of(&p, 0.0, 10.0);
        assert_eq!(roots.len(), 4, "{roots:?}");
        assert!((roots[0] - 1.0).abs() < 1e-9 && (roots[1] - 1.0 - 1e-6).abs() < 1e-9);
    }

    #[test]
    fn lower_degrees_and_no_real_roots() {
        assert_eq!(roots_of(&[-2.0, 1.0], 0.0, 5.0), vec![2.0]);
        let r = roots_of(&[-2.0, 0.0, 1.0], -5.0, 5.0);
        assert!(r.len() == 2 && (r[1] - 2f64.sqrt()).abs() < 1e-14, "{r:?}");
        assert!(roots_of(&[1.0, 0.0, 1.0, 0.0, 1.0], -5.0, 5.0).is_empty());
        assert!(roots_of(&[3.0], -5.0, 5.0).is_empty());
    }

    #[test]
    fn a_root_at_an_end_is_reported_once() {
        assert_eq!(roots_of(&[-1.0, 1.0, 0.0], 1.0, 3.0), vec![1.0]);
        let r = roots_of(&quartic_with_roots([0.0, 1.0, 2.0, 3.0]), 0.0, 3.0);
        assert_eq!(r.len(), 4, "{r:?}");
    }
}
