//! What the lighting asks of shadows: how much of a light reaches each fragment. The
//! rasterizer's shadow maps and the reference's exact shadow rays both answer it.

use glam::Vec3;

/// How much of each light reaches points of the scene.
pub trait Shadowing: Send + Sync {
    /// Whether light `light` may be blocked anywhere; where not, it reaches every point whole.
    fn casts(&self, light: usize) -> bool;

    /// For fragments of object `object` at camera-relative `points` with unit geometric normals
    /// `normals` (turned to the side the viewer sees; bumps do not move geometry, so they cast no
    /// shadow), writes into `out` the fraction of light `light` that reaches each, in [0, 1].
    /// Where a point's seen side faces away from the light the shader stops the light itself
    /// (`LitShader::terminators`), whatever the answer there.
    fn reaching(
        &self,
        light: usize,
        object: usize,
        points: &[Vec3],
        normals: &[Vec3],
        out: &mut [f32],
    );
}
