use super::{FrameLights, blinn_phong};
use crate::raster::{Camera, Fragment, FragmentShader, FrameObject};
use crate::scene::Scene;
use glam::Vec3;

/// The default program: the surface's exact frame at the fragment's (u,v), lit by Blinn-Phong.
pub struct LitShader {
    pub lights: FrameLights,
}

impl LitShader {
    pub fn new(scene: &Scene, camera: &Camera) -> LitShader {
        LitShader {
            lights: FrameLights::new(scene.ambient, &scene.lights, camera.eye),
        }
    }
}

impl FragmentShader for LitShader {
    type Scratch = ();

    fn scratch(&self) {}

    fn shade(&self, objects: &[FrameObject], fragments: &[Fragment], _: &mut (), out: &mut [Vec3]) {
        for (fragment, out) in fragments.iter().zip(out) {
            let object = &objects[fragment.object as usize];
            let frame = object.prepared.surface.frame(fragment.uv.x, fragment.uv.y);
            let material = &object.prepared.material;
            *out = blinn_phong(&self.lights, material, object.origin + frame.p, frame.n);
        }
    }
}
