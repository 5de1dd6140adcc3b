//! Per-fragment shading: the surface's exact frame at the fragment's (u,v), the texture, the
//! bump-perturbed normal, then lighting.

mod bake;
mod bump;
mod bump_heights;
mod bump_stage;
mod colour_stage;
mod exact_coverage;
mod exact_hits;
mod exact_point;
mod frame_object;
mod gradient;
mod lanes;
mod light_stage;
mod lighting;
mod pattern_batch;
mod per_fragment;
mod scene_shader;
mod shade_scratch;
mod shader_mode;
mod shadowing;
mod showing;
mod vertex_normals;

pub use bake::{
    BakeGrid, BakedBump, bake_bump_on, bake_color, bake_color_on, bake_height, tangent_normal,
};
pub use bump::{NormalForm, bumped_normal};
pub use bump_heights::BumpHeights;
pub use exact_coverage::{Neighbours, Reach, ReachShape, nearest_true_hit};
pub use exact_hits::ExactScratch;
pub use exact_point::{ExactPoints, SurfacePointSource, exact_fragments};
pub use frame_object::{FrameObject, frame_objects};
pub use gradient::GradientMethod;
pub use lighting::{FrameLights, blinn_phong, facing_sign};
pub use per_fragment::PerFragment;
pub use scene_shader::LitShader;
pub use shade_scratch::ShadeScratch;
pub use shader_mode::ShaderMode;
pub use shadowing::Shadowing;
pub use showing::Showing;
pub use vertex_normals::{Interpolated, VertexNormals};
