//! A prepared object placed relative to the camera for one frame: the object type the scene's
//! fragment programs shade (`FragmentShader::Object`), whose mesh the rasterizer draws.

use crate::raster::PlacedMesh;
use crate::scene::{Camera, PreparedObject, PreparedScene};
use crate::surface::Mesh;
use glam::{DVec3, Vec3};

/// Per-object state for one frame, in camera-relative space.
pub struct FrameObject<'a> {
    pub prepared: &'a PreparedObject,
    /// The surface's anchor relative to the eye, subtracted in f64 before narrowing to f32.
    pub origin: Vec3,
    /// The eye relative to the surface's anchor in f64, for exact ray casts.
    pub eye: DVec3,
    /// The surface bounds a volume the eye is outside of.
    eye_outside_volume: bool,
}

impl PlacedMesh for FrameObject<'_> {
    fn mesh(&self) -> &Mesh {
        &self.prepared.mesh
    }

    fn origin(&self) -> Vec3 {
        self.origin
    }

    fn cull_back_faces(&self) -> bool {
        self.eye_outside_volume
    }
}

/// The objects of a prepared scene placed relative to `camera` for one frame.
pub fn frame_objects<'a>(prepared: &'a PreparedScene, camera: &Camera) -> Vec<FrameObject<'a>> {
    prepared
        .objects
        .iter()
        .map(|o| {
            let eye = camera.eye - o.surface.origin();
            FrameObject {
                prepared: o,
                origin: (-eye).as_vec3(),
                eye,
                eye_outside_volume: o.surface.encloses_eye_at(eye) == Some(true),
            }
        })
        .collect()
}
