//! A fragment program from a function of one fragment and its object, for programs that need no
//! batching (tests, benchmarks, debugging views).

use super::frame_object::FrameObject;
use crate::raster::{Fragment, FragmentShader, SampleRays};
use glam::Vec3;

/// A program that colours each fragment by `self.0(object, fragment)`.
pub struct PerFragment<F>(pub F);

impl<F: Fn(&FrameObject, &Fragment) -> Vec3 + Sync> FragmentShader for PerFragment<F> {
    type Object<'o> = FrameObject<'o>;
    type Scratch = ();

    fn scratch(&self) {}

    fn shade(
        &self,
        objects: &[FrameObject],
        _: &SampleRays,
        fragments: &mut [Fragment],
        _: &mut (),
        out: &mut [Vec3],
    ) -> usize {
        for (fragment, out) in fragments.iter().zip(out) {
            *out = (self.0)(&objects[fragment.object as usize], fragment);
        }
        0
    }
}
