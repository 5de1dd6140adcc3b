//! Feeding a batch of fragments to a compiled pattern: its inputs in structure-of-arrays form,
//! in the pattern's own coordinates (the binding's placement), and its gradient back in (u,v).

use crate::pattern::{BumpSample, Inputs, Scratch};
use crate::raster::Fragment;
use crate::scene::PatternBinding;
use crate::surface::Frame;
use glam::{Vec2, Vec3};

/// Reusable input and output buffers for one pattern evaluation at a time.
#[derive(Default)]
pub struct PatternBatch {
    u: Vec<f32>,
    v: Vec<f32>,
    /// x, y, z and their partials along the pattern's coordinates: [x, y, z, x_u, y_u, z_u, x_v, y_v, z_v].
    point: [Vec<f32>; 9],
    samples: Vec<BumpSample>,
    rgb: Vec<[f32; 3]>,
    /// Grows to fit whichever pattern runs; one serves them all.
    scratch: Scratch,
}

impl PatternBatch {
    /// Loads the group's inputs: pattern coordinates q = J·(u,v) + offset, and the object-space
    /// point with ∂p/∂q = [Pu Pv]·J⁻¹ when the pattern reads x, y or z.
    pub fn load(
        &mut self,
        binding: &PatternBinding,
        fragments: &[Fragment],
        group: &[u32],
        frames: &[Frame],
    ) {
        let jacobian = binding.placement.jacobian();
        self.u.clear();
        self.v.clear();
        for &i in group {
            let q = binding.placement.apply(fragments[i as usize].uv, jacobian);
            self.u.push(q.x);
            self.v.push(q.y);
        }
        for lane in &mut self.point {
            lane.clear();
        }
        if !binding.pattern.uses_point() {
            return;
        }
        let inverse = jacobian.inverse();
        for frame in frames {
            let along_q1 = frame.pu * inverse.x_axis.x + frame.pv * inverse.x_axis.y;
            let along_q2 = frame.pu * inverse.y_axis.x + frame.pv * inverse.y_axis.y;
            for (lanes, vector) in self.point.chunks_mut(3).zip([frame.p, along_q1, along_q2]) {
                push_vector(lanes, vector);
            }
        }
    }

    /// Heights and (u,v) gradients of a bump pattern for the loaded group; returns how many
    /// fragments were made flat because the pattern gave no finite value.
    pub fn bump(
        &mut self,
        binding: &PatternBinding,
        time: f64,
        heights: &mut [f32],
        gradients: &mut [Vec2],
    ) -> usize {
        let n = self.u.len();
        self.samples.clear();
        self.samples.resize(n, BumpSample::default());
        let inputs = inputs(&self.u, &self.v, &self.point, time);
        let flattened = binding.pattern.eval_bump(
            &inputs,
            &binding.params,
            &mut self.scratch,
            &mut self.samples,
        );
        // ∂B/∂(u,v) = Jᵀ·∂B/∂q.
        let jacobian = binding.placement.jacobian();
        for ((sample, h), g) in self.samples.iter().zip(heights).zip(gradients) {
            let dq = Vec2::new(sample.du, sample.dv);
            *h = sample.height;
            *g = Vec2::new(jacobian.x_axis.dot(dq), jacobian.y_axis.dot(dq));
        }
        flattened
    }

    /// Colours of a colour pattern for the loaded group.
    pub fn colors(&mut self, binding: &PatternBinding, time: f64, colors: &mut [Vec3]) -> usize {
        let n = self.u.len();
        self.rgb.clear();
        self.rgb.resize(n, [0.0; 3]);
        let inputs = inputs(&self.u, &self.v, &self.point, time);
        let flattened =
            binding
                .pattern
                .eval_color(&inputs, &binding.params, &mut self.scratch, &mut self.rgb);
        for (rgb, color) in self.rgb.iter().zip(colors) {
            *color = Vec3::from_array(*rgb);
        }
        flattened
    }
}

fn inputs<'a>(u: &'a [f32], v: &'a [f32], point: &'a [Vec<f32>; 9], time: f64) -> Inputs<'a> {
    let [x, y, z, x_u, y_u, z_u, x_v, y_v, z_v] = point;
    Inputs {
        u,
        v,
        x,
        y,
        z,
        x_u,
        x_v,
        y_u,
        y_v,
        z_u,
        z_v,
        t: time,
    }
}

fn push_vector(lanes: &mut [Vec<f32>], v: Vec3) {
    lanes[0].push(v.x);
    lanes[1].push(v.y);
    lanes[2].push(v.z);
}
