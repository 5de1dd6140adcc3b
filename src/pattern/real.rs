//! The float type a program is evaluated in. `f64` always serves; `f32` serves programs that do
//! not read `t` (see `Program::single_precision`), with twice the lanes per SIMD register.
//!
//! Programs that call `perlin`, `cells` or `fbm` run in `f64` too: their slopes change many
//! times per unit, so the independent `f32` roundings of two of their arguments show in the
//! gradient more than any one shift of the inputs would.
//!
//! Why `f32` is accurate enough there: a program's inputs (u, v, the point and its partials) are
//! `f32` already, so its `f64` result is the exact result at inputs carrying up to half an `f32`
//! ulp of error. Each `f32` operation adds a relative error of the same size to its own result
//! (tested for every shipped pattern: the `f32` result lies within the `f64` results at inputs
//! up to 8 ulps away, give or take 1e-5 of its channel's scale, which the roundings of
//! intermediates larger than the inputs take). Floored `mod` by a whole period is exact in
//! `f32` but for the floor at a boundary, where both sides of the step are as right. `t` is the
//! exception: a clock of 1e7 s is exact in `f64` but has a step of a whole second in `f32`.
//! Where an `f32` evaluation overflows to a non-finite result, the batch is evaluated again in
//! `f64`.

use num_traits::Float;
use std::fmt::Debug;

/// Which float a pattern's lanes use: a quality knob (`Quality::pattern_precision`).
#[derive(
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    serde::Serialize,
    serde::Deserialize,
    strum::IntoStaticStr,
)]
#[serde(rename_all = "kebab-case")]
#[strum(serialize_all = "kebab-case")]
pub enum Precision {
    /// `f32` for programs that do not read `t` (twice the lanes), `f64` for the rest.
    #[default]
    Fastest,
    /// `f64` for every program: the reference's, and the `exact` preset's.
    Double,
}

impl Precision {
    pub fn name(self) -> &'static str {
        self.into()
    }
}

pub trait Real: Float + Default + Debug + Send + Sync + 'static {
    /// The nearest value to `x`.
    fn of(x: f64) -> Self;

    /// `x`, exactly.
    fn of_f32(x: f32) -> Self;

    /// The nearest `f32` (±∞ beyond its range).
    fn narrow(self) -> f32;

    /// This value, exactly.
    fn wide(self) -> f64;

    /// The working memory that holds lanes of this type.
    fn lanes(storage: &mut LaneStorage) -> &mut Vec<Self>;
}

/// Lanes of either precision, grown as programs need and kept.
#[derive(Clone, Debug, Default)]
pub struct LaneStorage {
    single: Vec<f32>,
    double: Vec<f64>,
}

impl Real for f64 {
    #[inline(always)]
    fn of(x: f64) -> f64 {
        x
    }

    #[inline(always)]
    fn of_f32(x: f32) -> f64 {
        f64::from(x)
    }

    #[inline(always)]
    fn narrow(self) -> f32 {
        self as f32
    }

    #[inline(always)]
    fn wide(self) -> f64 {
        self
    }

    fn lanes(storage: &mut LaneStorage) -> &mut Vec<f64> {
        &mut storage.double
    }
}

impl Real for f32 {
    #[inline(always)]
    fn of(x: f64) -> f32 {
        x as f32
    }

    #[inline(always)]
    fn of_f32(x: f32) -> f32 {
        x
    }

    #[inline(always)]
    fn narrow(self) -> f32 {
        self
    }

    #[inline(always)]
    fn wide(self) -> f64 {
        f64::from(self)
    }

    fn lanes(storage: &mut LaneStorage) -> &mut Vec<f32> {
        &mut storage.single
    }
}

#[cfg(test)]
mod tests {
    use super::super::{BUILTINS, BumpSample, Inputs, OutputKind, Pattern, Scratch, output};
    use super::Real;

    /// Fragments per pattern.
    const N: usize = 4096;
    /// How far (in `f32` ulps) the inputs of the `f64` evaluations reach.
    const ULPS: i32 = 8;
    /// How far the `f32` result may stray beyond those results, relative to the largest
    /// magnitude of its channel over all fragments: the roundings of intermediate values larger
    /// than the inputs, as `u + period / 2` for a small u near a line of a mesh.
    const SLACK: f32 = 1e-5;

    /// The outputs of `pattern` evaluated in lanes of `R` alone: height (0 for slopes) and
    /// gradient, or colour.
    fn outputs<R: Real>(pattern: &Pattern, inputs: &Inputs) -> Vec<[f32; 3]> {
        let program = &pattern.inner.program;
        let scratch = &mut Scratch::new();
        let mut bump = vec![BumpSample::default(); N];
        let mut color = vec![[0.0; 3]; N];
        match pattern.output() {
            OutputKind::Height => {
                let out = &mut bump;
                pattern.evaluate_in::<R, _>(
                    inputs,
                    &[],
                    scratch,
                    &mut output::HeightGradient { program, out },
                )
            }
            OutputKind::Slope => {
                let out = &mut bump;
                pattern.evaluate_in::<R, _>(
                    inputs,
                    &[],
                    scratch,
                    &mut output::Slope { program, out },
                )
            }
            OutputKind::Color => {
                let out = &mut color;
                pattern.evaluate_in::<R, _>(
                    inputs,
                    &[],
                    scratch,
                    &mut output::Color { program, out },
                )
            }
        };
        match pattern.output() {
            OutputKind::Color => color,
            _ => bump.iter().map(|s| [s.height, s.du, s.dv]).collect(),
        }
    }

    /// Deterministic inputs of every magnitude from 1e-2 to 1e4, both signs, never 0.
    fn spread(seed: u32) -> Vec<f32> {
        let mut state = seed.wrapping_mul(2_654_435_761).max(1);
        (0..N)
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 17;
                state ^= state << 5;
                let unit = (state >> 8) as f32 / (1 << 24) as f32;
                let magnitude = 10f32.powf(-2.0 + 6.0 * unit);
                if state & 1 == 0 {
                    magnitude
                } else {
                    -magnitude
                }
            })
            .collect()
    }

    /// `x` moved `ulps` steps away from (or, negative, towards) 0.
    fn nudge(x: f32, ulps: i32) -> f32 {
        f32::from_bits(x.to_bits().wrapping_add_signed(ulps))
    }

    /// Every shipped pattern that `f32` lanes serve gives, in them, a result that the `f64`
    /// evaluation gives for inputs at most `ULPS` away (within the spread of its results over
    /// the corners of that box of inputs, give or take `SLACK`): `f32` costs about the accuracy
    /// the `f32` inputs already do. Steps (check edges, dimple rims) are covered: a step through
    /// the box has corners on both of its sides.
    #[test]
    fn single_precision_results_are_double_results_of_inputs_a_few_ulps_away() {
        let coordinates: Vec<Vec<f32>> = (1..=5).map(spread).collect();
        let partials: Vec<f32> = spread(6).iter().map(|p| p.clamp(-2.0, 2.0)).collect();
        fn inputs<'a>(c: &'a [Vec<f32>], partials: &'a [f32]) -> Inputs<'a> {
            Inputs {
                u: &c[0],
                v: &c[1],
                x: &c[2],
                y: &c[3],
                z: &c[4],
                x_u: partials,
                x_v: partials,
                y_u: partials,
                y_v: partials,
                z_u: partials,
                z_v: partials,
                t: 0.0,
                precision: super::Precision::Fastest,
            }
        }
        let mut checked = 0;
        for (name, source) in BUILTINS {
            let pattern = Pattern::compile(source, name).expect("a shipped pattern");
            if !pattern.inner.program.single_precision() {
                continue;
            }
            checked += 1;
            let single = outputs::<f32>(&pattern, &inputs(&coordinates, &partials));
            let mut low = outputs::<f64>(&pattern, &inputs(&coordinates, &partials));
            let mut high = low.clone();
            for corner in 0..32 {
                let nudged: Vec<Vec<f32>> = (coordinates.iter().enumerate())
                    .map(|(i, c)| {
                        let ulps = if corner >> i & 1 == 1 { ULPS } else { -ULPS };
                        c.iter().map(|&x| nudge(x, ulps)).collect()
                    })
                    .collect();
                let double = outputs::<f64>(&pattern, &inputs(&nudged, &partials));
                for (i, d) in double.iter().enumerate() {
                    for c in 0..3 {
                        low[i][c] = low[i][c].min(d[c]);
                        high[i][c] = high[i][c].max(d[c]);
                    }
                }
            }
            let scale: [f32; 3] = std::array::from_fn(|c| {
                (low.iter().zip(&high)).fold(0.0f32, |m, (l, h)| m.max(l[c].abs()).max(h[c].abs()))
            });
            for (i, s) in single.iter().enumerate() {
                for c in 0..3 {
                    let slack = SLACK * scale[c];
                    assert!(
                        (low[i][c] - slack..=high[i][c] + slack).contains(&s[c]),
                        "{name}, fragment {i}, channel {c}: f32 gave {}, f64 {}..{} (u {}, v {})",
                        s[c],
                        low[i][c],
                        high[i][c],
                        coordinates[0][i],
                        coordinates[1][i]
                    );
                }
            }
        }
        assert!(checked >= 10, "only {checked} shipped patterns run in f32");
    }
}
