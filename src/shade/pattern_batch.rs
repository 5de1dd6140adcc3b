//! Feeding a batch of fragments to a compiled pattern: its inputs in structure-of-arrays form,
//! in the pattern's own coordinates (the binding's placement), and its gradient back in (u,v).

use crate::pattern::{BumpSample, Inputs, Scratch};
use crate::raster::Fragment;
use crate::scene::PatternBinding;
use crate::surface::Frame;
use glam::{Vec2, Vec3};

/// Where a pattern is evaluated: the fragments `group` picks out, and their surface frames in
/// the group's order.
#[derive(Clone, Copy)]
pub struct Sites<'a> {
    pub fragments: &'a [Fragment],
    pub group: &'a [u32],
    pub frames: &'a [Frame],
}

/// Whether the point's partials are loaded: only a height's gradient reads them.
#[derive(Clone, Copy, PartialEq)]
enum PointPartials {
    Needed,
    Unneeded,
}

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
    /// Loads the group's inputs: pattern coordinates q = J·(u,v) + offset, and, when the pattern
    /// reads x, y or z, the object-space point, with ∂p/∂q = [Pu Pv]·J⁻¹ if `partials` asks.
    fn load(&mut self, binding: &PatternBinding, at: Sites, partials: PointPartials) {
        let jacobian = binding.placement.jacobian();
        let n = at.group.len();
        self.u.resize(n, 0.0);
        self.v.resize(n, 0.0);
        for ((&i, u), v) in at.group.iter().zip(&mut self.u).zip(&mut self.v) {
            let q = binding
                .placement
                .apply(at.fragments[i as usize].uv, jacobian);
            (*u, *v) = (q.x, q.y);
        }
        let lanes = match (binding.pattern.uses_point(), partials) {
            (false, _) => 0,
            (true, PointPartials::Unneeded) => 3,
            (true, PointPartials::Needed) => 9,
        };
        for (k, lane) in self.point.iter_mut().enumerate() {
            lane.resize(if k < lanes { n } else { 0 }, 0.0);
        }
        if lanes == 0 {
            return;
        }
        let [x, y, z, rest @ ..] = &mut self.point;
        write_vectors([x, y, z], at.frames.iter().map(|frame| frame.p));
        if lanes == 9 {
            let inverse = jacobian.inverse();
            let [x_u, y_u, z_u, x_v, y_v, z_v] = rest;
            let along =
                |column: glam::Vec2| move |frame: &Frame| frame.pu * column.x + frame.pv * column.y;
            write_vectors([x_u, y_u, z_u], at.frames.iter().map(along(inverse.x_axis)));
            write_vectors([x_v, y_v, z_v], at.frames.iter().map(along(inverse.y_axis)));
        }
    }

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
        self.load(binding, at, PointPartials::Needed);
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
    pub fn colors(
        &mut self,
        binding: &PatternBinding,
        at: Sites,
        time: f64,
        colors: &mut [Vec3],
    ) -> usize {
        self.load(binding, at, PointPartials::Unneeded);
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

/// Writes each vector's x, y and z into the three lanes (already the group's length).
fn write_vectors(lanes: [&mut Vec<f32>; 3], vectors: impl Iterator<Item = Vec3>) {
    let [x, y, z] = lanes;
    for (((v, x), y), z) in vectors.zip(x).zip(y).zip(z) {
        (*x, *y, *z) = (v.x, v.y, v.z);
    }
}
