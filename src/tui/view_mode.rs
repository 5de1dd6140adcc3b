//! What the picture shows: the scene shader's own view modes (shaded, height, normals, uv,
//! depth), the tessellation drawn over the shaded picture, and the error against the reference.

use super::error_view::render_error_view;
use crate::quality::Quality;
use crate::raster::{FrameStats, Framebuffer, RenderTarget};
use crate::render::render_scene_pass;
use crate::scene::PreparedScene;
use crate::shade::{ShaderMode, Showing};
use crate::shadow::ShadowCache;

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, strum::VariantArray)]
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
    /// The per-pixel difference to the exact reference as a heat map (PSNR in the status line).
    Error,
}

impl ViewMode {
    pub const ALL: &'static [ViewMode] = <ViewMode as strum::VariantArray>::VARIANTS;

    pub fn name(self) -> &'static str {
        match self {
            ViewMode::Wireframe => "wireframe",
            ViewMode::Error => "error",
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
            ViewMode::Shaded | ViewMode::Wireframe | ViewMode::Error => ShaderMode::Shaded,
            ViewMode::Height => ShaderMode::Height,
            ViewMode::Normals => ShaderMode::Normals,
            ViewMode::Uv => ShaderMode::Uv,
            ViewMode::Depth => ShaderMode::Depth,
        }
    }
}

/// What rendering a view mode produced besides the picture.
#[derive(Clone, Copy, Debug, Default)]
pub struct RenderedFrame {
    pub stats: FrameStats,
    /// The frame's PSNR against the reference, in the error view.
    pub psnr_db: Option<f64>,
}

/// Renders `prepared` as `mode` at scene time `time` (seconds), with `quality`'s shading, into
/// `framebuffer`.
pub fn render_view_mode(
    mode: ViewMode,
    time: f64,
    quality: &Quality,
    (prepared, shadows): (&PreparedScene, &ShadowCache),
    target: &RenderTarget,
    framebuffer: &mut Framebuffer,
) -> RenderedFrame {
    let maps = shadows.maps(
        prepared,
        target.camera,
        target.viewport,
        quality.shadow_settings(),
    );
    if mode == ViewMode::Error {
        let (stats, psnr_db) =
            render_error_view(time, quality, (prepared, maps), target, framebuffer);
        return RenderedFrame {
            stats,
            psnr_db: Some(psnr_db),
        };
    }
    let showing = Showing {
        mode: mode.shader_mode(),
        time,
    };
    let shader = quality.shader_with_maps(prepared, target.camera, maps, showing);
    RenderedFrame {
        stats: render_scene_pass(prepared, target, &shader, framebuffer),
        psnr_db: None,
    }
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
        assert_eq!(ViewMode::Shaded.cycled(-1), ViewMode::Error);
        assert_eq!(ViewMode::Height.name(), "height");
    }
}
