//! Stripes and checks use a floored modulo: periodic, and the same size across 0
//! (unlike the seed's `x % 50`, which mirrors there). Checks are solid (x, y and z), so every
//! plane parallel to a coordinate plane shows squares.

use crate::pattern::support::{colors, shipped};

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

const CYAN: [f32; 3] = [0.0, 1.0, 1.0];
const MAGENTA: [f32; 3] = [1.0, 0.0, 1.0];

/// The shipped checks at object points (x, y, z).
fn checks_at(points: &[[f32; 3]]) -> Vec<[f32; 3]> {
    let checks = shipped("checks");
    let mut batch = crate::pattern::support::Batch::default();
    for point in points {
        batch.u.push(0.0);
        batch.v.push(0.0);
        for (k, lane) in batch.p.iter_mut().enumerate() {
            lane.push(if k < 3 { point[k] } else { 0.0 });
        }
    }
    let mut out = vec![[0.0; 3]; points.len()];
    checks.eval_color(&batch.inputs(), &[], &mut checks.scratch(), &mut out);
    out
}

#[test]
fn checks_are_the_seeds_with_a_floored_modulo_where_z_is_zero() {
    let low = |a: f32| a.rem_euclid(PERIOD) < PERIOD / 2.0;
    let points: Vec<[f32; 3]> = (-40..40)
        .flat_map(|i| (-40..40).map(move |j| [i as f32 * 3.7 + 0.1, j as f32 * 4.3 + 0.2, 0.0]))
        .collect();
    for (point, colour) in points.iter().zip(checks_at(&points)) {
        let [x, y, _] = *point;
        let seed = if low(x) == low(y) { CYAN } else { MAGENTA };
        assert_eq!(colour, seed, "at ({x}, {y}, 0)");
    }
}

#[test]
fn checks_are_squares_on_a_plane_parallel_to_each_coordinate_plane_across_zero() {
    let e = 0.01;
    // Each plane: a point on it and its two in-plane axes.
    let planes: [([f32; 3], usize, usize); 3] = [
        ([0.0, 0.0, 0.0], 0, 2), // the floor, y = 0 (where x and y alone gave stripes)
        ([0.0, 0.0, -137.0], 0, 1), // a wall z = const
        ([512.0, 0.0, 0.0], 1, 2), // a wall x = const
    ];
    for (origin, a, b) in planes {
        let along = |da: f32, db: f32| {
            let mut p = origin;
            p[a] += da;
            p[b] += db;
            p
        };
        for (da, db) in [(-e, -e), (e, e), (10.0, -e), (-e, 30.0), (-60.0, 70.0)] {
            let c = checks_at(&[
                along(da, db),
                along(da + PERIOD, db),
                along(da, db + PERIOD),
                along(da + PERIOD / 2.0, db),
                along(da, db + PERIOD / 2.0),
                along(da + PERIOD / 2.0, db + PERIOD / 2.0),
            ]);
            let at = format!("plane through {origin:?}, offset ({da}, {db})");
            assert_eq!(c[0], c[1], "period along the first axis: {at}");
            assert_eq!(c[0], c[2], "period along the second axis: {at}");
            assert_ne!(
                c[0], c[3],
                "half a period along the first axis changes it: {at}"
            );
            assert_ne!(
                c[0], c[4],
                "half a period along the second axis changes it: {at}"
            );
            assert_eq!(c[0], c[5], "diagonal neighbours match: {at}");
        }
    }
}

#[test]
fn stripe_period_is_a_live_parameter() {
    let stripes = shipped("stripes");
    let batch = crate::pattern::support::Batch::new(&[at(30.0, 0.0)]);
    let mut out = [[0.0; 3]];
    stripes.eval_color(&batch.inputs(), &[100.0], &mut stripes.scratch(), &mut out);
    assert_eq!(out[0], RED, "30 is in the first half of a 100 period");
}
