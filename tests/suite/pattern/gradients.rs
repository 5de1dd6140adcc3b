//! The automatic-differentiation gradient of every shipped height pattern equals a central
//! difference of its height, away from kinks.

use crate::pattern::support::{bump, heights, sample_points, shipped};
use bumpwork::pattern::{BUILTINS, OutputKind, Pattern};

/// Central difference of the height along u (axis 0) or v (axis 1) with step `e`, using the
/// step actually representable in f32.
fn central_difference(pattern: &Pattern, (u, v): (f32, f32), axis: usize, e: f32) -> f64 {
    let (lo, hi) = if axis == 0 {
        ((u - e, v), (u + e, v))
    } else {
        ((u, v - e), (u, v + e))
    };
    let h = heights(pattern, &[lo, hi]);
    let step = if axis == 0 { hi.0 - lo.0 } else { hi.1 - lo.1 };
    (f64::from(h[1]) - f64::from(h[0])) / f64::from(step)
}

const TOLERANCE: f64 = 2e-3;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= TOLERANCE * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn gradients_match_central_differences() {
    let points = sample_points(400, -60.0, 460.0, 7);
    for (name, _) in BUILTINS {
        let pattern = shipped(name);
        if pattern.output() != OutputKind::Height {
            continue;
        }
        let (samples, bad) = bump(&pattern, &points);
        assert_eq!(bad, 0, "{name}: non-finite samples");
        let mut compared = 0;
        for (&point, sample) in points.iter().zip(&samples) {
            for axis in 0..2 {
                let coarse = central_difference(&pattern, point, axis, 0.02);
                let fine = central_difference(&pattern, point, axis, 0.01);
                if !close(coarse, fine) {
                    continue; // the difference straddles a kink or a step
                }
                compared += 1;
                let ad = f64::from(if axis == 0 { sample.du } else { sample.dv });
                assert!(
                    close(ad, fine),
                    "{name} at {point:?} axis {axis}: AD {ad} vs central difference {fine}"
                );
            }
        }
        assert!(
            compared > points.len(),
            "{name}: only {compared} comparisons away from kinks"
        );
    }
}

#[test]
fn gradient_height_equals_value_only_height() {
    let points = sample_points(300, -100.0, 500.0, 3);
    for (name, _) in BUILTINS {
        let pattern = shipped(name);
        if pattern.output() != OutputKind::Height {
            continue;
        }
        let (samples, _) = bump(&pattern, &points);
        let values = heights(&pattern, &points);
        for (s, h) in samples.iter().zip(values) {
            assert_eq!(s.height, h, "{name}");
        }
    }
}

#[test]
fn the_point_partials_flow_into_the_gradient() {
    // bumps.pat reads x, y, z only; its u-gradient must be nonzero somewhere.
    let pattern = shipped("bumps");
    let (samples, _) = bump(&pattern, &sample_points(50, 0.0, 400.0, 1));
    assert!(
        samples
            .iter()
            .any(|s| s.du.abs() > 1e-3 && s.dv.abs() > 1e-3)
    );
}

#[test]
fn batches_give_the_same_result_as_single_fragments() {
    let pattern = shipped("ripples");
    let points = sample_points(1000, 0.0, 400.0, 11); // not a multiple of the chunk size
    let (batch, _) = bump(&pattern, &points);
    for (i, &p) in points.iter().enumerate().step_by(37) {
        assert_eq!(bump(&pattern, &[p]).0[0], batch[i]);
    }
}
