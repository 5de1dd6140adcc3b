//! The bump stage of the scene's fragment program: each fragment's bump height and its (u,v)
//! gradient, from a pattern, a height image or a normal map, by the shader's gradient method.

use super::colour_stage::{mapping_on, surface_points};
use super::frame_object::FrameObject;
use super::gradient::{GradientMethod, central_difference, shifted_fragments};
use super::pattern_batch::{PatternBatch, Sites};
use super::shade_scratch::{HeightLookups, ShadeScratch, Shifted};
use crate::pattern::OutputKind;
use crate::raster::Fragment;
use crate::scene::BumpSource;
use crate::surface::{Frame, Frames, Surface};
use crate::texture::{Footprint, HeightSample};
use glam::{Mat2, Vec2};

/// What the bump stage needs of the shader.
#[derive(Clone, Copy)]
pub(super) struct BumpStage {
    /// Seconds, for animated patterns.
    pub time: f64,
    pub gradient: GradientMethod,
}

impl BumpStage {
    /// The bump height and its (u,v) gradient per fragment, by the shader's gradient method,
    /// into `scratch.heights` and `scratch.gradients` (zero without a bump).
    pub(super) fn gradients(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        scratch: &mut ShadeScratch,
    ) -> usize {
        let Some(bump) = &object.prepared.material.bump else {
            scratch.heights.clear();
            scratch.gradients.clear();
            return 0;
        };
        let gives_slope = matches!(&bump.source,
            BumpSource::Pattern(b) if b.pattern.output() == OutputKind::Slope);
        let flattened = match self.gradient {
            GradientMethod::SeedLattice => {
                let shifted = &mut scratch.shifted;
                shifted_fragments(fragments, group, Vec2::floor, &mut shifted.fragments);
                let base = (&scratch.frames, fragments, group);
                let flattened = self.shifted_bump(
                    object,
                    shifted,
                    base,
                    (&mut scratch.patterns, &mut scratch.height_lookups),
                );
                std::mem::swap(&mut scratch.heights, &mut shifted.heights);
                std::mem::swap(&mut scratch.gradients, &mut shifted.gradients);
                flattened
            }
            GradientMethod::CentralDifference { step } if !gives_slope => {
                let flattened = self.samples(object, fragments, group, scratch);
                self.central_gradients(object, fragments, group, step, scratch);
                flattened
            }
            _ => self.samples(object, fragments, group, scratch),
        };
        let scale = bump.scale();
        for (h, g) in scratch.heights.iter_mut().zip(&mut scratch.gradients) {
            *h *= scale;
            *g *= scale;
        }
        flattened
    }

    /// Replaces `scratch.gradients` by central differences of heights a `step` away.
    fn central_gradients(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        step: f32,
        scratch: &mut ShadeScratch,
    ) {
        let shifts = [
            Vec2::new(step, 0.0),
            Vec2::new(-step, 0.0),
            Vec2::new(0.0, step),
            Vec2::new(0.0, -step),
        ];
        let shifted = &mut scratch.shifted;
        for (k, shift) in shifts.into_iter().enumerate() {
            shifted_fragments(fragments, group, |uv| uv + shift, &mut shifted.fragments);
            let work = (&mut scratch.patterns, &mut scratch.height_lookups);
            let base = (&scratch.frames, fragments, group);
            self.shifted_bump(object, shifted, base, work);
            std::mem::swap(&mut shifted.around[k], &mut shifted.heights);
        }
        let around = &shifted.around;
        for (k, g) in scratch.gradients.iter_mut().enumerate() {
            let heights = [around[0][k], around[1][k], around[2][k], around[3][k]];
            *g = central_difference(heights, step);
        }
    }

    /// Heights and exact gradients at `shifted.fragments` (each with its own surface frame),
    /// into `shifted.heights` and `shifted.gradients`.
    fn shifted_bump(
        &self,
        object: &FrameObject,
        shifted: &mut Shifted,
        base: (&Frames, &[Fragment], &[u32]),
        (patterns, height_lookups): (&mut PatternBatch, &mut HeightLookups),
    ) -> usize {
        let surface = &object.prepared.surface;
        let n = shifted.fragments.len();
        shifted.identity.clear();
        shifted.identity.extend(0..n as u32);
        shifted.frames.clear();
        let fragments = &shifted.fragments;
        match surface {
            // A model's (u,v) name no point: its shifted frames step along its unshifted ones.
            Surface::Model(_) => {
                let (frames, originals, group) = base;
                shifted.frames.extend((0..n).map(|k| {
                    let step = fragments[k].uv - originals[group[k] as usize].uv;
                    let frame = frames.at(k);
                    Frame {
                        p: frame.p + frame.pu * step.x + frame.pv * step.y,
                        ..frame
                    }
                }));
            }
            _ => surface.frames(n, |k| fragments[k].uv, &mut shifted.frames),
        }
        let mut output = BumpOutput {
            frames: &shifted.frames,
            patterns,
            height_lookups,
            heights: &mut shifted.heights,
            gradients: &mut shifted.gradients,
        };
        self.evaluate(object, &shifted.fragments, &shifted.identity, &mut output)
    }

    /// Unscaled heights and exact gradients of the group at its own (u,v).
    fn samples(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        scratch: &mut ShadeScratch,
    ) -> usize {
        let mut output = BumpOutput {
            frames: &scratch.frames,
            patterns: &mut scratch.patterns,
            height_lookups: &mut scratch.height_lookups,
            heights: &mut scratch.heights,
            gradients: &mut scratch.gradients,
        };
        self.evaluate(object, fragments, group, &mut output)
    }

    /// The bump source's height and exact (u,v) gradient, before the bump's strength.
    fn evaluate(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        output: &mut BumpOutput,
    ) -> usize {
        let Some(bump) = &object.prepared.material.bump else {
            reset(output.heights, group.len(), 0.0);
            reset(output.gradients, group.len(), Vec2::ZERO);
            return 0;
        };
        // Both sources write every height and gradient: resized, not cleared.
        output.heights.resize(group.len(), 0.0);
        output.gradients.resize(group.len(), Vec2::ZERO);
        match &bump.source {
            BumpSource::Pattern(binding) => {
                let at = Sites {
                    fragments,
                    group,
                    frames: output.frames,
                };
                let (heights, gradients) = (&mut *output.heights, &mut *output.gradients);
                output
                    .patterns
                    .bump(binding, at, self.time, heights, gradients)
            }
            BumpSource::Image(image) => {
                let surface = &object.prepared.surface;
                let mapping = mapping_on(&image.mapping, surface, image.wrap_s);
                let point = surface_points(self.time, fragments, group, output.frames);
                let lookups = &mut *output.height_lookups;
                // Every entry is written below: resized, not cleared.
                lookups.st.resize(group.len(), Vec2::ZERO);
                lookups.footprints.resize(group.len(), Footprint::POINT);
                lookups.jacobians.resize(group.len(), Mat2::ZERO);
                mapping.map_each(group.len(), point, |k, mapped| {
                    let fragment = &fragments[group[k] as usize];
                    lookups.st[k] = mapped.st;
                    lookups.footprints[k] = mapped.footprint(fragment.duv_dx, fragment.duv_dy);
                    lookups.jacobians[k] = mapped.jacobian;
                });
                lookups.samples.resize(group.len(), HeightSample::default());
                let wraps = (image.wrap_s, image.wrap_t);
                let (st, footprints) = (&lookups.st, &lookups.footprints);
                (image.map).sample_gradient_many(st, footprints, wraps, &mut lookups.samples);
                let samples = lookups.samples.iter().zip(&lookups.jacobians);
                for ((height, gradient), (sample, &jacobian)) in output
                    .heights
                    .iter_mut()
                    .zip(output.gradients.iter_mut())
                    .zip(samples)
                {
                    *height = sample.height;
                    *gradient = sample.surface_gradient(jacobian);
                }
                0
            }
            BumpSource::NormalMap(map) => {
                let point = surface_points(self.time, fragments, group, output.frames);
                let each = output.heights.iter_mut().zip(output.gradients.iter_mut());
                for (k, (height, gradient)) in each.enumerate() {
                    *height = 0.0;
                    *gradient = map.gradient(&point(k));
                }
                0
            }
        }
    }
}

/// Where one bump evaluation reads its frames and writes its results.
struct BumpOutput<'a> {
    frames: &'a Frames,
    patterns: &'a mut PatternBatch,
    height_lookups: &'a mut HeightLookups,
    heights: &'a mut Vec<f32>,
    gradients: &'a mut Vec<Vec2>,
}

fn reset<T: Copy>(values: &mut Vec<T>, len: usize, value: T) {
    values.clear();
    values.resize(len, value);
}
