//! The lighting stage of the scene's fragment program: how much of each light reaches each
//! fragment (shadows and the geometric terminator), the facing (bumped) normals, and
//! Blinn-Phong over a group of fragments.

use super::bump::{
    NormalForm, blinn_normals, blinn_normals_on_flat, bumped_normal, full_normals_in_closed_form,
};
use super::frame_object::FrameObject;
use super::lighting::{
    FrameLights, Reach, RelativeLight, blinn_phong_many, faces_light, facing_sign,
};
use super::shade_scratch::ShadeScratch;
use super::shadowing::Shadowing;
use crate::raster::Fragment;
use crate::scene::Material;
use glam::Vec3;
use std::ops::Range;

/// What the lighting stage needs of the shader.
#[derive(Clone, Copy)]
pub(super) struct LightStage<'a> {
    pub lights: &'a FrameLights,
    /// What else blocks the lights (`None`: nothing does).
    pub shadows: Option<&'a dyn Shadowing>,
    /// Whether each light stops at every surface's geometric terminator.
    pub terminators: bool,
    pub normal_form: NormalForm,
}

impl LightStage<'_> {
    /// Whether any light casts shadows in this frame.
    pub(super) fn any_light_casts(&self) -> bool {
        let lights = self.lights.lights.len();
        let shadows = self.shadows.as_ref();
        shadows.is_some_and(|shadows| (0..lights).any(|light| shadows.casts(light)))
    }

    /// The lighting of one group of fragments with their base `colors`.
    pub(super) fn group<'a>(
        &'a self,
        material: &'a Material,
        group: &'a [u32],
        colors: &'a [Vec3],
        reach: Reach<'a>,
    ) -> GroupLighting<'a> {
        GroupLighting {
            lights: self.lights,
            material,
            group,
            colors,
            reach,
        }
    }

    /// How much of each light reaches the group's fragments (at `scratch.points`), into
    /// `scratch.reach` (left empty when lights reach every fragment whole: no terminators).
    /// Shadows and terminators follow the geometric surface, not the bumps. `constant_normal` is
    /// every frame's normal, if they share one.
    pub(super) fn reach(
        &self,
        object_index: usize,
        constant_normal: Option<Vec3>,
        scratch: &mut ShadeScratch,
    ) {
        scratch.reach.clear();
        if !self.terminators || self.lights.lights.is_empty() {
            return;
        }
        let (points, normals) = (&scratch.points, &mut scratch.shadow_normals);
        normals.clear();
        let facing = |p: Vec3, n: Vec3| n * facing_sign(p, n);
        match constant_normal {
            Some(n) => normals.extend(points.iter().map(|&p| facing(p, n))),
            None => {
                let frames = points.iter().zip(scratch.frames.n.range(0..points.len()));
                normals.extend(frames.map(|(&p, n)| facing(p, n)));
            }
        }
        let count = points.len();
        scratch.reach.resize(self.lights.lights.len() * count, 1.0);
        let per_light = scratch.reach.chunks_mut(count.max(1));
        for ((index, light), reach) in self.lights.lights.iter().enumerate().zip(per_light) {
            let shadows = self.shadows.as_ref().filter(|s| s.casts(index));
            if let Some(shadows) = shadows {
                shadows.reaching(index, object_index, points, normals, reach);
            }
            stop_at_terminator(light, points, normals, reach);
        }
    }

    /// Facing (bumped) normals of the group at `scratch.points`, into `scratch.normals`
    /// (shading without a bump reads them from the frames instead). `constant_normal` is every
    /// frame's normal, if they share one.
    pub(super) fn normals(
        &self,
        object: &FrameObject,
        fragments: &[Fragment],
        group: &[u32],
        constant_normal: Option<Vec3>,
        scratch: &mut ShadeScratch,
    ) {
        let surface = &object.prepared.surface;
        let bumped = object.prepared.material.bump.is_some();
        // Every normal is written below: resized, not cleared.
        let (points, normals) = (&scratch.points, &mut scratch.normals);
        normals.resize(group.len(), Vec3::ZERO);
        let (frames, heights, gradients) = (&scratch.frames, &scratch.heights, &scratch.gradients);
        let blinn_when_flat =
            bumped && matches!(self.normal_form, NormalForm::Blinn | NormalForm::Full);
        if let (true, Some(frame), Some(n)) = (blinn_when_flat, frames.first(), constant_normal) {
            // On a flat surface the full normal is Blinn's (see `bumped_normal`).
            blinn_normals_on_flat(&frame, heights, gradients, normals);
            let facing = normals.iter_mut().zip(points);
            facing.for_each(|(normal, &p)| *normal *= facing_sign(p, n));
            return;
        }
        // Normals worked out as a batch (or `false`: one by one below).
        let batched = match self.normal_form {
            _ if !bumped => false,
            NormalForm::Blinn => {
                blinn_normals(frames, heights, gradients, normals);
                true
            }
            NormalForm::Full => {
                full_normals_in_closed_form(surface, frames, heights, gradients, normals)
            }
            NormalForm::Seed => false,
        };
        if batched || !bumped {
            let geometric = scratch.frames.n.range(0..group.len());
            for ((&p, normal), n) in points.iter().zip(normals.iter_mut()).zip(geometric) {
                let shown = if batched { *normal } else { n };
                *normal = shown * facing_sign(p, n);
            }
            return;
        }
        let frames = group.iter().zip(scratch.frames.iter());
        let outputs = points.iter().zip(normals);
        for (k, ((&i, frame), (&p, normal))) in frames.zip(outputs).enumerate() {
            let (b, gradient) = (scratch.heights[k], scratch.gradients[k]);
            let uv = fragments[i as usize].uv;
            let (form, (bu, bv)) = (self.normal_form, gradient.into());
            let n = bumped_normal(surface, uv, &frame, b, bu, bv, form);
            *normal = n * facing_sign(p, frame.n);
        }
    }
}

/// Zeroes `reach` where the light is behind the seen side of the geometric surface (facing
/// unit `normals` at camera-relative `points`), or the side cannot be told (a NaN normal).
fn stop_at_terminator(light: &RelativeLight, points: &[Vec3], normals: &[Vec3], reach: &mut [f32]) {
    // One loop per kind of light, compiled for the widest SIMD: with the light's kind matched
    // inside it, the loop stayed scalar.
    #[inline(always)]
    fn stop(points: &[Vec3], normals: &[Vec3], reach: &mut [f32], way: impl Fn(Vec3) -> Vec3) {
        for ((reach, &p), &n) in reach.iter_mut().zip(points).zip(normals) {
            *reach = if faces_light(n, way(p)) { *reach } else { 0.0 };
        }
    }
    crate::simd::widest(
        #[inline(always)]
        || match *light {
            RelativeLight::Point { position, .. } => stop(points, normals, reach, |p| position - p),
            RelativeLight::Directional { towards, .. } => stop(points, normals, reach, |_| towards),
        },
    );
}

/// What lighting one group takes: the lights, the material, the group's fragments and their
/// base colours.
pub(super) struct GroupLighting<'a> {
    lights: &'a FrameLights,
    material: &'a Material,
    group: &'a [u32],
    colors: &'a [Vec3],
    reach: Reach<'a>,
}

impl GroupLighting<'_> {
    /// Lights the group in one batch into `out`, from the points and normals `surface` gives:
    /// straight into `out` when the group's fragments are consecutive (as a one-object batch's
    /// are), else through `lit` and a scatter.
    pub(super) fn light<Pairs: Iterator<Item = (Vec3, Vec3)>>(
        &self,
        surface: impl Fn(Range<usize>) -> Pairs,
        lit: &mut Vec<Vec3>,
        out: &mut [Vec3],
    ) {
        let (lights, material, colors, reach) =
            (self.lights, self.material, self.colors, self.reach);
        if let Some(range) = consecutive(self.group) {
            blinn_phong_many(lights, material, colors, surface, reach, &mut out[range]);
            return;
        }
        lit.resize(self.group.len(), Vec3::ZERO);
        blinn_phong_many(lights, material, colors, surface, reach, lit);
        for (&i, &color) in self.group.iter().zip(lit.iter()) {
            out[i as usize] = color;
        }
    }
}

/// The range `group` lists, when its indices are consecutive. A group ascends without repeats
/// (`group_by_object` orders it so): then its ends alone tell.
fn consecutive(group: &[u32]) -> Option<Range<usize>> {
    debug_assert!(group.windows(2).all(|pair| pair[0] < pair[1]), "ascending");
    let (first, last) = (*group.first()? as usize, *group.last()? as usize);
    (last - first + 1 == group.len()).then_some(first..last + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_group_is_consecutive_when_its_ends_span_it() {
        assert_eq!(consecutive(&[3, 4, 5]), Some(3..6));
        assert_eq!(consecutive(&[7]), Some(7..8));
        assert_eq!(consecutive(&[3, 5, 6]), None);
        assert_eq!(consecutive(&[0, 1, 3]), None);
        assert_eq!(consecutive(&[]), None);
    }
}
