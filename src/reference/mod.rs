//! The exact reference renderer: one ray per pixel centre, intersected analytically (robust root
//! finding for the wave) with the scene's exact surfaces, producing the same `Fragment`s the
//! rasterizer does, shaded by the same `FragmentShader`. Only visibility and (u,v) interpolation
//! differ from the rasterizer, so the difference between the two is the tessellation's error.
//! It is the ground truth for accuracy, not fast.
//!
//! Numerics: rays are intersected in f64 relative to each surface's anchor, so a scene translated
//! by 1e6 loses nothing. The ray direction is scaled so that its component along the view
//! direction is 1: the ray parameter t is then the view depth, which the near and far planes bound.

mod caster;
mod exact_shader;
mod heat_map;
mod lit_frames;
pub mod metrics;

pub use caster::{
    ReferenceStats, cast_pixel, render_rays_into, render_reference, render_reference_into,
};
pub use exact_shader::exact_shader;
pub use heat_map::error_heat_map;
pub use lit_frames::ShadedAndNormals;
pub use metrics::{FrameError, frame_error};
