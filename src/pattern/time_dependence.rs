//! Whether a program's result moves with `t` at given parameter values: `speed * t` with
//! `speed = 0` does not, so a view of it can settle.
//!
//! Each slot is followed forward as a known value (constants, parameters and what is computed
//! from them alone), a value that varies without `t` (anything read per fragment), or a value
//! that moves with `t`. A product with a known zero, and an `if` whose condition is known, stop
//! `t` from reaching further.

use super::check::Input;
use super::ops::{Op, apply};
use super::program::{Program, Source};

/// What is known of one slot's value over time.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Slot {
    /// The same for every fragment and time (`f64`, as the evaluator's uniforms are computed).
    Known(f64),
    /// Varies over fragments, not with time.
    Still,
    Moving,
}

/// Whether any output of `program` can change with `t` when parameter `p` has `param(p)`.
pub fn moves_with_time(program: &Program, param: impl Fn(usize) -> f64) -> bool {
    let mut slots: Vec<Slot> = program
        .sources
        .iter()
        .map(|source| match *source {
            Source::Param(p) => Slot::Known(param(p)),
            Source::Constant(c) => Slot::Known(c),
            Source::Input(Input::T) => Slot::Moving,
            Source::Input(_) | Source::Computed => Slot::Still,
        })
        .collect();
    for instr in &program.instrs {
        let args = instr.args.map(|a| slots[a]);
        slots[instr.dst] = result(instr.op, args);
    }
    program.outputs.iter().any(|&o| slots[o] == Slot::Moving)
}

fn result(op: Op, args: [Slot; 4]) -> Slot {
    let known = |slot: Slot| match slot {
        Slot::Known(value) => Some(value),
        _ => None,
    };
    if let [Some(a), Some(b), Some(c), Some(d)] = args.map(known) {
        return Slot::Known(apply::<f64>(op, a, b, c, d));
    }
    match (op, args) {
        // `t` is finite, and so is all that is made of it but for an overflow, which the
        // evaluator draws flat at any time.
        (Op::Mul, [Slot::Known(z), _, _, _] | [_, Slot::Known(z), _, _]) if z == 0.0 => {
            Slot::Known(0.0)
        }
        (Op::Select, [Slot::Known(condition), then, otherwise, _]) => match condition != 0.0 {
            true => then,
            false => otherwise,
        },
        _ if args.contains(&Slot::Moving) => Slot::Moving,
        _ => Slot::Still,
    }
}

#[cfg(test)]
mod tests {
    use crate::pattern::Pattern;

    fn moves(source: &str, params: &[f32]) -> bool {
        Pattern::compile(source, "test")
            .unwrap()
            .moves_with_time(params)
    }

    #[test]
    fn a_zero_speed_stops_time() {
        let source = "param speed = 0 in -10..10\nheight = sin(u + speed * t)";
        assert!(!moves(source, &[0.0]));
        assert!(moves(source, &[0.5]));
        assert!(moves(source, &[-0.5]));
    }

    #[test]
    fn time_through_any_op_moves_and_without_it_nothing_does() {
        assert!(moves("height = floor(t) + u", &[]));
        assert!(moves("height = perlin(u, v, t)", &[]));
        assert!(!moves("height = perlin(u, v, 3)", &[]));
    }

    #[test]
    fn a_known_condition_picks_its_branch() {
        let source = "param on = 0 in 0..1\nheight = if on > 0.5 then sin(t) else u";
        assert!(!moves(source, &[0.0]));
        assert!(moves(source, &[1.0]));
        let unknown = "height = if u > 0.5 then sin(t) else u";
        assert!(moves(unknown, &[]));
    }

    /// Heights (or the first colour channel) of `pattern` over a few points at time `t`.
    fn samples(pattern: &Pattern, params: &[f32], t: f64) -> Vec<f32> {
        use crate::pattern::{Inputs, OutputKind, Scratch};
        let u: Vec<f32> = (0..64).map(|i| i as f32 * 13.7).collect();
        let v: Vec<f32> = (0..64).map(|i| 400.0 - i as f32 * 5.3).collect();
        let point: Vec<f32> = (0..64).map(|i| i as f32 * 3.1 - 90.0).collect();
        let zero = vec![0.0; 64];
        let inputs = Inputs {
            x: &point,
            y: &point,
            z: &point,
            x_u: &zero,
            x_v: &zero,
            y_u: &zero,
            y_v: &zero,
            z_u: &zero,
            z_v: &zero,
            ..Inputs::uv(&u, &v, t)
        };
        let mut scratch = Scratch::new();
        match pattern.output() {
            OutputKind::Color => {
                let mut out = vec![[0.0; 3]; 64];
                pattern.eval_color(&inputs, params, &mut scratch, &mut out);
                out.iter().map(|c| c[0]).collect()
            }
            _ => {
                let mut out = vec![Default::default(); 64];
                pattern.eval_bump(&inputs, params, &mut scratch, &mut out);
                out.iter()
                    .map(|s: &crate::pattern::BumpSample| s.height + s.du)
                    .collect()
            }
        }
    }

    #[test]
    fn a_shipped_pattern_said_to_stand_still_gives_the_same_values_at_any_time() {
        let mut still = 0;
        for &(name, source) in crate::pattern::BUILTINS {
            let pattern = Pattern::compile(source, name).unwrap();
            let params: Vec<f32> = pattern.params().iter().map(|p| p.default).collect();
            if !pattern.uses_time() {
                continue;
            }
            if !pattern.moves_with_time(&params) {
                still += 1;
                assert_eq!(
                    samples(&pattern, &params, 0.0),
                    samples(&pattern, &params, 7.3),
                    "{name}"
                );
            }
            // Every parameter that is 0 at its default, set to 1, starts the motion or not; the
            // answer must match the values either way.
            for i in 0..params.len() {
                let mut moved = params.clone();
                moved[i] = if moved[i] == 0.0 { 1.0 } else { moved[i] };
                let same = samples(&pattern, &moved, 0.0) == samples(&pattern, &moved, 7.3);
                assert!(
                    pattern.moves_with_time(&moved) || same,
                    "{name} with param {i}"
                );
            }
        }
        assert!(
            still >= 3,
            "the ripple and wave patterns stand still at speed 0"
        );
    }
}
