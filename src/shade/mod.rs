//! Per-fragment shading: the surface's exact frame at the fragment's (u,v), then lighting.

mod lighting;
mod lit;

pub use lighting::{FrameLights, blinn_phong};
pub use lit::LitShader;
