//! The reference's fragment program: the `exact` preset's shading, with exact shadow rays.

use crate::quality::Quality;
use crate::scene::Camera;
use crate::scene::PreparedScene;
use crate::shade::{LitShader, Shadowing};
use crate::shadow::ShadowRays;
use std::sync::Arc;

/// The reference's fragment program: the `exact` preset's shading, and exact shadow rays where
/// the scene has shadows.
pub fn exact_shader(prepared: &PreparedScene, camera: &Camera, time: f64) -> LitShader {
    let mut shader = LitShader::new(&prepared.scene, camera);
    shader.time = time;
    Quality::exact().configure(&mut shader, prepared);
    shader.shadows =
        ShadowRays::new(prepared, camera).map(|rays| Arc::new(rays) as Arc<dyn Shadowing>);
    shader
}
