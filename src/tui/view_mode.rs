//! What the picture shows: the scene's own lighting, or one of the quantities behind it, each as
//! its own fragment program so the pipeline compiles a tight loop for it.

use crate::raster::{
    FrameStats, Framebuffer, PerFragment, PreparedScene, RenderTarget, render_into,
};
use crate::shade::LitShader;
use glam::Vec3;

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ViewMode {
    #[default]
    Shaded,
    /// The bump height B(u,v) as grey.
    Height,
    /// The surface normal, each component mapped from −1..1 to 0..1.
    Normals,
    /// (u,v) over the surface's domain as red and green, with a checker to show distortion.
    Uv,
    /// Distance from the eye, near bright, normalised over the visible range.
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
            ViewMode::Shaded => "shaded",
            ViewMode::Height => "height",
            ViewMode::Normals => "normals",
            ViewMode::Uv => "uv",
            ViewMode::Depth => "depth",
            ViewMode::Wireframe => "wireframe",
        }
    }

    pub fn cycled(self, step: i32) -> ViewMode {
        let index = Self::ALL.iter().position(|&m| m == self).unwrap_or(0) as i32;
        Self::ALL[(index + step).rem_euclid(Self::ALL.len() as i32) as usize]
    }
}

/// Renders `prepared` as `mode` into `framebuffer` (linear colour and depth).
pub fn render_view_mode(
    mode: ViewMode,
    prepared: &PreparedScene,
    target: &RenderTarget,
    framebuffer: &mut Framebuffer,
) -> FrameStats {
    match mode {
        ViewMode::Shaded | ViewMode::Wireframe => {
            let shader = LitShader::new(&prepared.scene, target.camera);
            render_into(prepared, target, &shader, framebuffer)
        }
        ViewMode::Height => render_into(prepared, target, &height_shader(), framebuffer),
        ViewMode::Normals => render_into(prepared, target, &normal_shader(), framebuffer),
        ViewMode::Uv => render_into(prepared, target, &uv_shader(), framebuffer),
        ViewMode::Depth => {
            let stats = render_into(prepared, target, &depth_only_shader(), framebuffer);
            shade_by_depth(framebuffer);
            stats
        }
    }
}

fn normal_shader() -> impl crate::raster::FragmentShader {
    PerFragment(
        |object: &crate::raster::FrameObject, f: &crate::raster::Fragment| {
            let frame = object.prepared.surface.frame(f.uv.x, f.uv.y);
            frame.n * 0.5 + Vec3::splat(0.5)
        },
    )
}

/// Without a bump pattern the surface is flat: mid grey.
fn height_shader() -> impl crate::raster::FragmentShader {
    PerFragment(|_: &crate::raster::FrameObject, _: &crate::raster::Fragment| Vec3::splat(0.5))
}

/// Colour is replaced afterwards from the depth buffer, so the program does nothing.
fn depth_only_shader() -> impl crate::raster::FragmentShader {
    PerFragment(|_: &crate::raster::FrameObject, _: &crate::raster::Fragment| Vec3::ZERO)
}

const UV_CHECKS: f32 = 8.0;

fn uv_shader() -> impl crate::raster::FragmentShader {
    PerFragment(
        |object: &crate::raster::FrameObject, f: &crate::raster::Fragment| {
            let domain = object.prepared.surface.domain();
            let size = (domain.max - domain.min).max(glam::Vec2::splat(1e-6));
            let uv = ((f.uv - domain.min) / size).clamp(glam::Vec2::ZERO, glam::Vec2::ONE);
            let check = ((uv.x * UV_CHECKS).floor() + (uv.y * UV_CHECKS).floor()) as i32 & 1;
            let brightness = if check == 0 { 1.0 } else { 0.7 };
            Vec3::new(uv.x, uv.y, 0.15) * brightness
        },
    )
}

/// Replaces colour by depth, nearest visible pixel white and farthest dark; background stays.
fn shade_by_depth(framebuffer: &mut Framebuffer) {
    let finite = framebuffer.depth.iter().copied().filter(|d| d.is_finite());
    let (near, far) = finite.fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), d| {
        (lo.min(d), hi.max(d))
    });
    let range = (far - near).max(1e-6);
    for (color, &depth) in framebuffer.color.iter_mut().zip(&framebuffer.depth) {
        if depth.is_finite() {
            let nearness = 1.0 - (depth - near) / range;
            *color = Vec3::splat(0.05 + 0.95 * nearness * nearness);
        }
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
        assert_eq!(ViewMode::Shaded.cycled(-1), ViewMode::Wireframe);
    }
}
