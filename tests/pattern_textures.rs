//! Stripes and checks use a floored modulo: periodic, and the same size across 0
//! (unlike the seed's `x % 50`, which mirrors there).

mod pattern_support;

use pattern_support::{colors, shipped};

const PERIOD: f32 = 50.0;
const RED: [f32; 3] = [1.0, 0.0, 0.0];
const BLUE: [f32; 3] = [0.0, 0.0, 1.0];

/// (u, v) that the support map sends to object point (x, y, ·).
fn at(x: f32, y: f32) -> (f32, f32) {
    (x + 200.0, y + 200.0)
}

#[test]
fn stripes_are_periodic_across_zero() {
    let stripes = shipped("stripes");
    let e = 0.01;
    let c = colors(
        &stripes,
        &[
            at(-e, 0.0),
            at(e, 0.0),
            at(PERIOD - e, 0.0),
            at(PERIOD + e, 0.0),
        ],
    );
    assert_eq!(c[0], c[2], "colour at -ε equals colour at period-ε");
    assert_eq!(c[1], c[3], "colour at +ε equals colour at period+ε");
    assert_eq!((c[0], c[1]), (BLUE, RED));
    let xs: Vec<f32> = (-100..100).map(|i| i as f32 * 2.5 + 0.3).collect();
    let here = colors(
        &stripes,
        &xs.iter().map(|&x| at(x, 0.0)).collect::<Vec<_>>(),
    );
    let there = colors(
        &stripes,
        &xs.iter().map(|&x| at(x + PERIOD, 0.0)).collect::<Vec<_>>(),
    );
    assert_eq!(here, there);
    let red = here.iter().filter(|&&c| c == RED).count();
    assert_eq!(red, here.len() / 2, "stripes keep equal widths across 0");
}

#[test]
fn checks_are_periodic_in_x_and_y_across_zero() {
    let checks = shipped("checks");
    let e = 0.01;
    for (x, y) in [(-e, -e), (e, -e), (-e, e), (e, e), (-e, 10.0), (10.0, -e)] {
        let c = colors(&checks, &[at(x, y), at(x + PERIOD, y), at(x, y + PERIOD)]);
        assert_eq!(c[0], c[1], "period in x at ({x}, {y})");
        assert_eq!(c[0], c[2], "period in y at ({x}, {y})");
    }
    let c = colors(&checks, &[at(-e, -e), at(e, -e), at(e, e)]);
    assert_ne!(c[0], c[1], "colour changes across x = 0");
    assert_eq!(c[0], c[2], "diagonal neighbours across the corner match");
}

#[test]
fn stripe_period_is_a_live_parameter() {
    let stripes = shipped("stripes");
    let batch = pattern_support::Batch::new(&[at(30.0, 0.0)]);
    let mut out = [[0.0; 3]];
    stripes.eval_color(&batch.inputs(), &[100.0], &mut stripes.scratch(), &mut out);
    assert_eq!(out[0], RED, "30 is in the first half of a 100 period");
}
