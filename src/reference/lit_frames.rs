//! The two frames the error metrics compare: shaded as configured, and the normals view.

use super::metrics::{FrameError, frame_error};
use crate::raster::Framebuffer;
use crate::shade::{LitShader, ShaderMode};

/// The two frames the error metrics need from one renderer: as configured, and the normals view.
pub struct ShadedAndNormals {
    pub shaded: Framebuffer,
    pub normals: Framebuffer,
}

impl ShadedAndNormals {
    /// Renders with `render` (the rasterizer or the reference, any quality setting) once with the
    /// shader as it is and once in `ShaderMode::Normals`, then restores the shader's mode.
    pub fn render(
        shader: &mut LitShader,
        mut render: impl FnMut(&LitShader) -> Framebuffer,
    ) -> ShadedAndNormals {
        let shaded = render(shader);
        let mode = std::mem::replace(&mut shader.mode, ShaderMode::Normals);
        let normals = render(shader);
        shader.mode = mode;
        ShadedAndNormals { shaded, normals }
    }

    /// Every error figure of these frames against the reference's.
    pub fn error_against(&self, reference: &ShadedAndNormals) -> FrameError {
        frame_error(
            &self.shaded,
            &reference.shaded,
            &self.normals,
            &reference.normals,
        )
    }
}
