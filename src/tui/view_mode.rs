//! What the picture shows: the scene shader's own view modes (shaded, height, normals, uv,
//! depth), plus the tessellation drawn over the shaded picture.

use crate::raster::{FrameStats, Framebuffer, PreparedScene, RenderTarget, render_into};
use crate::shade::{LitShader, ViewMode as ShaderMode};

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ViewMode {
    #[default]
    Shaded,
    /// The bump height B(u,v) as grey.
    Height,
    /// The bumped surface normal as colour.
    Normals,
    Uv,
    /// Distance from the eye, near bright.
    Depth,
    /// Shaded, with the tessellation's triangle edges drawn over it.
    Wireframe,
}

impl ViewMode {
    pub const ALL: [ViewMode; 6] = [
        ViewMode::Shaded,
        ViewMode::Height,
        ViewMode::Normals,
        ViewMode::Uv,
        ViewMode::Depth,
        ViewMode::Wireframe,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ViewMode::Wireframe => "wireframe",
            mode => mode.shader_mode().name(),
        }
    }

    pub fn cycled(self, step: i32) -> ViewMode {
        let index = Self::ALL.iter().position(|&m| m == self).unwrap_or(0) as i32;
        Self::ALL[(index + step).rem_euclid(Self::ALL.len() as i32) as usize]
    }

    /// The scene shader's mode that draws this view (the wireframe is drawn over shading).
    pub(crate) fn shader_mode(self) -> ShaderMode {
        match self {
            ViewMode::Shaded | ViewMode::Wireframe => ShaderMode::Shaded,
            ViewMode::Height => ShaderMode::Height,
            ViewMode::Normals => ShaderMode::Normals,
            ViewMode::Uv => ShaderMode::Uv,
            ViewMode::Depth => ShaderMode::Depth,
        }
    }
}

/// Renders `prepared` as `mode` at scene time `time` (seconds) into `framebuffer`.
pub fn render_view_mode(
    mode: ViewMode,
    time: f64,
    prepared: &PreparedScene,
    target: &RenderTarget,
    framebuffer: &mut Framebuffer,
) -> FrameStats {
    let mut shader = LitShader::new(&prepared.scene, target.camera);
    shader.mode = mode.shader_mode();
    shader.time = time;
    render_into(prepared, target, &shader, framebuffer)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycling_visits_every_mode_and_wraps() {
        let mut mode = ViewMode::Shaded;
        for _ in 0..ViewMode::ALL.len() {
            mode = mode.cycled(1);
        }
        assert_eq!(mode, ViewMode::Shaded);
        assert_eq!(ViewMode::Shaded.cycled(-1), ViewMode::Wireframe);
        assert_eq!(ViewMode::Height.name(), "height");
    }
}
