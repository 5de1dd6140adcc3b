//! The evaluator's f64 arithmetic keeps long animation clocks and large sphere coordinates
//! accurate (f32 would not: at t = 1e7 its step is a whole second).

use bumpwork::pattern::{BumpSample, Inputs, Pattern, builtin};

fn bump_at(pattern: &Pattern, u: f32, v: f32, t: f64) -> BumpSample {
    let (u, v) = ([u], [v]);
    let mut out = [BumpSample::default()];
    pattern.eval_bump(
        &Inputs::uv(&u, &v, t),
        &[],
        &mut pattern.scratch(),
        &mut out,
    );
    out[0]
}

#[test]
fn a_ten_million_second_clock_keeps_sub_second_phase() {
    let pattern = Pattern::compile("height = sin(2 * pi * t) + 0 * u", "t.pat").unwrap();
    for (t, expected) in [(1e7 + 0.25, 1.0), (1e7 + 0.75, -1.0), (1e7 + 0.5, 0.0)] {
        let h = bump_at(&pattern, 0.0, 0.0, t).height;
        assert!((h - expected).abs() < 1e-6, "t = {t}: {h}");
    }
}

#[test]
fn a_30_unit_period_holds_at_the_far_end_of_a_sphere() {
    let dimples = Pattern::compile(builtin("dimples").unwrap(), "dimples").unwrap();
    // u = 719.3 on the sphere is 23 periods past u = 29.3.
    for v in [5.3f32, 14.9, 200.7, 359.1] {
        let far = bump_at(&dimples, 719.3, v, 0.0);
        let near = bump_at(&dimples, 29.3, v, 0.0);
        assert!((far.height - near.height).abs() < 1e-3, "v = {v}");
        assert!((far.du - near.du).abs() < 1e-3 && (far.dv - near.dv).abs() < 1e-3);
    }
}
