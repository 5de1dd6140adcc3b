//! Division by zero, square roots of negatives and logs of zero never reach the output as NaN
//! or infinity; the evaluator reports how many fragments were made flat.

use bumpwork::pattern::{BumpSample, Inputs, Pattern};

fn us(values: &[f32]) -> (Vec<f32>, Vec<f32>) {
    (values.to_vec(), vec![0.0; values.len()])
}

fn run_bump(source: &str, u: &[f32]) -> (Vec<BumpSample>, usize) {
    let pattern = Pattern::compile(source, "test.pat").unwrap();
    let (u, v) = us(u);
    let mut out = vec![BumpSample::default(); u.len()];
    let bad = pattern.eval_bump(
        &Inputs::uv(&u, &v, 0.0),
        &[],
        &mut pattern.scratch(),
        &mut out,
    );
    (out, bad)
}

fn all_finite(samples: &[BumpSample]) -> bool {
    samples
        .iter()
        .all(|s| s.height.is_finite() && s.du.is_finite() && s.dv.is_finite())
}

#[test]
fn division_by_zero_is_counted_and_flattened() {
    let (out, bad) = run_bump("height = 1 / (u - 10)", &[9.0, 10.0, 11.0, 10.0]);
    assert_eq!(bad, 2);
    assert!(all_finite(&out));
    assert_eq!(out[1], BumpSample::default());
    assert_eq!(out[0].height, -1.0);
}

#[test]
fn sqrt_of_negative_and_infinite_slope_are_counted() {
    let u: Vec<f32> = (1..=10).map(|i| i as f32).collect();
    // u < 5: NaN value; u = 5: value 0 but slope 1/(2·0) is infinite.
    let (out, bad) = run_bump("height = sqrt(u - 5)", &u);
    assert_eq!(bad, 5);
    assert!(all_finite(&out));
    let pattern = Pattern::compile("height = sqrt(u - 5)", "t").unwrap();
    let (u, v) = us(&u);
    let mut heights = vec![0.0; u.len()];
    let bad = pattern.eval_height(
        &Inputs::uv(&u, &v, 0.0),
        &[],
        &mut pattern.scratch(),
        &mut heights,
    );
    assert_eq!(bad, 4, "the value alone is finite at u = 5");
}

#[test]
fn log_zero_in_a_slope_is_counted() {
    let (out, bad) = run_bump("slope = (log(u), 1)", &[0.0, 1.0, 0.0, -1.0]);
    assert_eq!(bad, 3);
    assert!(all_finite(&out));
    assert_eq!(out[1].dv, 1.0);
}

#[test]
fn colour_non_finite_is_black_and_counted() {
    let pattern = Pattern::compile("color = rgb(1 / u, 0.5, 0)", "t").unwrap();
    let (u, v) = us(&[0.0, 2.0]);
    let mut out = [[0.0; 3]; 2];
    let bad = pattern.eval_color(
        &Inputs::uv(&u, &v, 0.0),
        &[],
        &mut pattern.scratch(),
        &mut out,
    );
    assert_eq!(bad, 1);
    assert_eq!(out, [[0.0, 0.0, 0.0], [0.5, 0.5, 0.0]]);
}

#[test]
fn an_unselected_branch_does_not_count() {
    let (out, bad) = run_bump("height = if u != 0 then 1 / u else 0", &[0.0, 2.0]);
    assert_eq!(bad, 0);
    assert_eq!(out[0], BumpSample::default());
}

#[test]
fn huge_values_that_overflow_f32_are_counted() {
    let (out, bad) = run_bump("height = exp(u)", &[100.0, 1.0]);
    assert_eq!(bad, 1);
    assert!(all_finite(&out));
}
