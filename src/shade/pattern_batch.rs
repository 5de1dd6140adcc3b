//! Feeding a batch of fragments to a compiled pattern: its inputs in structure-of-arrays form,
//! in the pattern's own coordinates (the binding's placement), and its gradient back in (u,v).

use crate::pattern::{BumpSample, Inputs, Precision, Scratch};
use crate::raster::Fragment;
use crate::scene::{PatternBinding, Placement};
use crate::surface::{Frames, Vectors};
use glam::{Vec2, Vec3};

/// Where a pattern is evaluated: the fragments `group` picks out, and their surface frames in
/// the group's order.
#[derive(Clone, Copy)]
pub struct Sites<'a> {
    pub fragments: &'a [Fragment],
    pub group: &'a [u32],
    pub frames: &'a Frames,
}

/// Whether the point's partials are loaded: only a height's gradient reads them.
#[derive(Clone, Copy, PartialEq)]
enum PointPartials {
    Needed,
    Unneeded,
}

/// Reusable input and output buffers for one pattern evaluation at a time. They grow to the
/// largest group seen and never shrink: each evaluation writes the first `group.len()` entries
/// of those it uses (shrinking and regrowing them, as groups of two patterns alternate, would
/// zero them again each time).
#[derive(Default)]
pub struct PatternBatch {
    /// The lanes the patterns are evaluated in.
    pub precision: Precision,
    inputs: InputLanes,
    samples: Vec<BumpSample>,
    /// Grows to fit whichever pattern runs; one serves them all.
    scratch: Scratch,
}

/// A group's pattern inputs, structure-of-arrays.
#[derive(Default)]
struct InputLanes {
    u: Vec<f32>,
    v: Vec<f32>,
    /// x, y, z and their partials along the pattern's coordinates: [x, y, z, x_u, y_u, z_u, x_v, y_v, z_v].
    point: [Vec<f32>; 9],
}

impl InputLanes {
    /// Loads the group's inputs that the pattern reads: pattern coordinates q = J·(u,v) +
    /// offset, and the object-space point, with ∂p/∂q = [Pu Pv]·J⁻¹ if `partials` asks.
    /// Returns them, each `group.len()` long (or empty where the pattern does not read it),
    /// at time `t`.
    fn load<'a>(
        &'a mut self,
        binding: &PatternBinding,
        at: Sites,
        partials: PointPartials,
        t: f64,
        precision: Precision,
    ) -> Inputs<'a> {
        let jacobian = binding.placement.jacobian();
        let n = at.group.len();
        let pattern = &binding.pattern;
        if pattern.uses_uv() {
            let (u, v) = (at_least(&mut self.u, n), at_least(&mut self.v, n));
            let placed = binding.placement != Placement::default();
            for ((&i, u), v) in at.group.iter().zip(u).zip(v) {
                let uv = at.fragments[i as usize].uv;
                let q = if placed {
                    binding.placement.apply(uv, jacobian)
                } else {
                    uv
                };
                (*u, *v) = (q.x, q.y);
            }
        }
        let lanes = match (pattern.uses_point(), partials) {
            (false, _) => 0,
            (true, PointPartials::Unneeded) => 3,
            (true, PointPartials::Needed) => 9,
        };
        let [x, y, z, x_u, y_u, z_u, x_v, y_v, z_v] = &mut self.point;
        if lanes >= 3 {
            copy_vectors([x, y, z], n, &at.frames.p);
        }
        if lanes == 9 {
            let inverse = jacobian.inverse();
            let tangents = (&at.frames.pu, &at.frames.pv);
            write_combined([x_u, y_u, z_u], n, tangents, inverse.x_axis);
            write_combined([x_v, y_v, z_v], n, tangents, inverse.y_axis);
        }
        let read = |lane: &'a [f32], used: bool| if used { &lane[..n] } else { &[][..] };
        let uv = pattern.uses_uv();
        let [x, y, z, x_u, y_u, z_u, x_v, y_v, z_v] = &self.point;
        Inputs {
            u: read(&self.u, uv),
            v: read(&self.v, uv),
            x: read(x, lanes >= 3),
            y: read(y, lanes >= 3),
            z: read(z, lanes >= 3),
            x_u: read(x_u, lanes == 9),
            x_v: read(x_v, lanes == 9),
            y_u: read(y_u, lanes == 9),
            y_v: read(y_v, lanes == 9),
            z_u: read(z_u, lanes == 9),
            z_v: read(z_v, lanes == 9),
            t,
            precision,
        }
    }
}

impl PatternBatch {
    /// Heights and (u,v) gradients of a bump pattern for the loaded group; returns how many
    /// fragments were made flat because the pattern gave no finite value.
    pub fn bump(
        &mut self,
        binding: &PatternBinding,
        at: Sites,
        time: f64,
        heights: &mut [f32],
        gradients: &mut [Vec2],
    ) -> usize {
        let n = at.group.len();
        at_least(&mut self.samples, n);
        let inputs = (self.inputs).load(binding, at, PointPartials::Needed, time, self.precision);
        let samples = &mut self.samples[..n];
        let flattened =
            binding
                .pattern
                .eval_bump(&inputs, &binding.params, &mut self.scratch, samples);
        // ∂B/∂(u,v) = Jᵀ·∂B/∂q.
        let jacobian = binding.placement.jacobian();
        let placed = binding.placement != Placement::default();
        for ((sample, h), g) in samples.iter().zip(heights).zip(gradients) {
            let dq = Vec2::new(sample.du, sample.dv);
            *h = sample.height;
            *g = if placed {
                Vec2::new(jacobian.x_axis.dot(dq), jacobian.y_axis.dot(dq))
            } else {
                dq
            };
        }
        flattened
    }

    /// Colours of a colour pattern for the group, into `colors` (the group's length).
    pub fn colors(
        &mut self,
        binding: &PatternBinding,
        at: Sites,
        time: f64,
        colors: &mut [Vec3],
    ) -> usize {
        let inputs = (self.inputs).load(binding, at, PointPartials::Unneeded, time, self.precision);
        binding.pattern.eval_color(
            &inputs,
            &binding.params,
            &mut self.scratch,
            bytemuck::cast_slice_mut(colors),
        )
    }
}

/// The first `n` entries of `values`, grown (never shrunk) to have them.
fn at_least<T: Clone + Default>(values: &mut Vec<T>, n: usize) -> &mut [T] {
    if values.len() < n {
        values.resize(n, T::default());
    }
    &mut values[..n]
}

/// The first `n` of `vectors` into `lanes`, a coordinate to a lane.
fn copy_vectors(lanes: [&mut Vec<f32>; 3], n: usize, vectors: &Vectors) {
    for (lane, coordinate) in lanes.into_iter().zip(vectors.coordinates()) {
        at_least(lane, n).copy_from_slice(&coordinate[..n]);
    }
}

/// The first `n` of a·w.x + b·w.y into `lanes`, a coordinate to a lane.
fn write_combined(lanes: [&mut Vec<f32>; 3], n: usize, (a, b): (&Vectors, &Vectors), w: Vec2) {
    let pairs = a.coordinates().into_iter().zip(b.coordinates());
    for (lane, (a, b)) in lanes.into_iter().zip(pairs) {
        let each = at_least(lane, n).iter_mut().zip(&a[..n]).zip(&b[..n]);
        each.for_each(|((out, &a), &b)| *out = a * w.x + b * w.y);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::Pattern;

    fn fragment(uv: Vec2) -> Fragment {
        Fragment {
            object: 0,
            uv,
            duv_dx: Vec2::ZERO,
            duv_dy: Vec2::ZERO,
            depth: 1.0,
            x: 0,
            y: 0,
        }
    }

    /// Heights and (u,v) gradients at `uvs`.
    fn bump(binding: &PatternBinding, uvs: &[Vec2]) -> (Vec<f32>, Vec<Vec2>) {
        let fragments: Vec<Fragment> = uvs.iter().map(|&uv| fragment(uv)).collect();
        let group: Vec<u32> = (0..uvs.len() as u32).collect();
        let at = Sites {
            fragments: &fragments,
            group: &group,
            frames: &Frames::default(),
        };
        let (mut heights, mut gradients) = (vec![0.0; uvs.len()], vec![Vec2::ZERO; uvs.len()]);
        PatternBatch::default().bump(binding, at, 0.0, &mut heights, &mut gradients);
        (heights, gradients)
    }

    /// The gradient in (u,v) is the chain rule through the placement: it matches central
    /// differences of the height, placed or not, and unplaced it is the pattern's own.
    #[test]
    fn gradients_follow_the_placement() {
        let pattern = Pattern::compile("height = 5 * sin(0.3 * u) * cos(0.2 * v) + 0.1 * u", "t")
            .expect("a valid pattern");
        let placements = [
            Placement::default(),
            Placement {
                scale: Vec2::new(2.0, 0.5),
                rotate_degrees: 30.0,
                offset: Vec2::new(7.0, -3.0),
            },
        ];
        let uvs: Vec<Vec2> = (0..100)
            .map(|k| Vec2::new(k as f32 * 1.7 - 40.0, 25.0 - k as f32 * 0.9))
            .collect();
        let h = 1e-2;
        for placement in placements {
            let binding = PatternBinding {
                name: "t".into(),
                pattern: pattern.clone(),
                params: Vec::new(),
                placement,
            };
            let (_, gradients) = bump(&binding, &uvs);
            let height_at = |shift: Vec2| {
                let shifted: Vec<Vec2> = uvs.iter().map(|&uv| uv + shift).collect();
                bump(&binding, &shifted).0
            };
            let [east, west, north, south] = [
                Vec2::new(h, 0.0),
                Vec2::new(-h, 0.0),
                Vec2::new(0.0, h),
                Vec2::new(0.0, -h),
            ]
            .map(height_at);
            for (k, g) in gradients.iter().enumerate() {
                let by_differences = Vec2::new(
                    (east[k] - west[k]) / (2.0 * h),
                    (north[k] - south[k]) / (2.0 * h),
                );
                assert!(
                    (*g - by_differences).length() < 2e-2,
                    "{placement:?} at {}: {g} against {by_differences}",
                    uvs[k]
                );
            }
            if placement == Placement::default() {
                let (u, v) = (uvs[3].x as f64, uvs[3].y as f64);
                let du = 1.5 * (0.3 * u).cos() * (0.2 * v).cos() + 0.1;
                assert!((f64::from(gradients[3].x) - du).abs() < 1e-5);
            }
        }
    }
}
