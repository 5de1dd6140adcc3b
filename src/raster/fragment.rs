//! What rasterisation hands to shading: the visible pixels' fragments, and the fragment program's
//! interface, generic over the program's own object type.

use super::placed_mesh::PlacedMesh;
use super::sample_rays::SampleRays;
use glam::{Vec2, Vec3};

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
    /// What the program knows of each of the frame's objects (which may borrow from the
    /// frame's data, for `'o`); the rasterizer reads its mesh.
    type Object<'o>: PlacedMesh;
    type Scratch;

    fn scratch(&self) -> Self::Scratch;

    /// Whether the program reads the (u,v) derivatives (`duv_dx`, `duv_dy`) of `object`'s
    /// fragments; where it does not, the rasterizer leaves them zero and saves their
    /// arithmetic at every pixel of that object. A program that says false must not read them.
    fn reads_derivatives(&self, _object: &Self::Object<'_>) -> bool {
        true
    }

    /// Writes one linear RGB colour per fragment into `out` (same length as `fragments`), whose
    /// sample points' view rays are `rays`. The program may move a fragment onto the true
    /// surface its ray meets: its depth (written to the framebuffer) and object change with it.
    /// Returns how many fragments were drawn flat because a pattern gave no finite value there.
    fn shade(
        &self,
        objects: &[Self::Object<'_>],
        rays: &SampleRays,
        fragments: &mut [Fragment],
        scratch: &mut Self::Scratch,
        out: &mut [Vec3],
    ) -> usize;
}
