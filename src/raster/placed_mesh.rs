//! What the rasterizer needs of an object for one frame: its mesh, where the mesh sits relative
//! to the eye, and whether its back faces can be dropped. A fragment program's own object type
//! provides it (`FragmentShader::Object`), so the rasterizer knows meshes, not scenes.

use crate::surface::Mesh;
use glam::Vec3;

/// An object as the rasterizer sees it for one frame.
pub trait PlacedMesh: Sync {
    fn mesh(&self) -> &Mesh;

    /// The mesh's anchor relative to the eye, subtracted in f64 before narrowing to f32 so that
    /// scenes far from the origin keep their precision.
    fn origin(&self) -> Vec3;

    /// Whether the mesh's back faces cannot be seen (it bounds a volume the eye is outside of),
    /// so they are dropped before setup.
    fn cull_back_faces(&self) -> bool;
}
