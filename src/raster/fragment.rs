//! What rasterisation hands to shading: the frame's objects and the visible pixels' fragments.

use super::sample_rays::SampleRays;
use crate::scene::{Camera, PreparedObject, PreparedScene};
use glam::{DVec3, Vec2, Vec3};

/// Per-object state for one frame, in camera-relative space.
pub struct FrameObject<'a> {
    pub prepared: &'a PreparedObject,
    /// The surface's anchor relative to the eye, subtracted in f64 before narrowing to f32.
    pub origin: Vec3,
    /// The eye relative to the surface's anchor in f64, for exact ray casts.
    pub eye: DVec3,
}

/// What the shading stage knows about a visible pixel: plain data, so a tile's fragments can be
/// shaded as one batch.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Fragment {
    /// Index into the frame's objects; one past the last (set by a shader resolving coverage
    /// exactly) for a pixel whose ray meets no surface, shown as background at infinite depth.
    pub object: u32,
    pub uv: Vec2,
    /// Screen-space derivatives of (u,v) per pixel, from the same interpolants (for mip levels).
    pub duv_dx: Vec2,
    pub duv_dy: Vec2,
    /// Distance along the view direction.
    pub depth: f32,
    /// The pixel, in the full image.
    pub x: u32,
    pub y: u32,
}

/// The per-fragment program, run on batches of fragments (a tile's visible pixels, any objects).
/// Generic, so each program's loop is compiled for it; `Scratch` is per-thread working memory.
pub trait FragmentShader: Sync {
    type Scratch;

    fn scratch(&self) -> Self::Scratch;

    /// Whether the program reads the (u,v) derivatives (`duv_dx`, `duv_dy`) of `object`'s
    /// fragments; where it does not, the rasterizer leaves them zero and saves their
    /// arithmetic at every pixel of that object. A program that says false must not read them.
    fn reads_derivatives(&self, _object: &FrameObject) -> bool {
        true
    }

    /// Writes one linear RGB colour per fragment into `out` (same length as `fragments`), whose
    /// sample points' view rays are `rays`. The program may move a fragment onto the true
    /// surface its ray meets: its depth (written to the framebuffer) and object change with it.
    /// Returns how many fragments were drawn flat because a pattern gave no finite value there.
    fn shade(
        &self,
        objects: &[FrameObject],
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut Self::Scratch,
        out: &mut [Vec3],
    ) -> usize;
}

/// A shader from a function of one fragment, for programs that need no batching.
pub struct PerFragment<F>(pub F);

impl<F: Fn(&FrameObject, &Fragment) -> Vec3 + Sync> FragmentShader for PerFragment<F> {
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

/// The objects of a prepared scene placed relative to the camera for one frame.
pub fn frame_objects<'a>(prepared: &'a PreparedScene, camera: &Camera) -> Vec<FrameObject<'a>> {
    prepared
        .objects
        .iter()
        .map(|o| FrameObject {
            prepared: o,
            origin: (o.surface.origin() - camera.eye).as_vec3(),
            eye: camera.eye - o.surface.origin(),
        })
        .collect()
}
