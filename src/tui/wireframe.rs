//! The tessellation drawn over a rendered frame: the visible edges of the screen triangles.

use crate::raster::{Framebuffer, RenderTarget, ScreenTriangle, screen_triangles};
use crate::scene::PreparedScene;
use crate::shade::frame_objects;
use glam::{Vec2, Vec3};

const LINE_COLOR: Vec3 = Vec3::new(1.0, 0.85, 0.2);
/// Pixels closer than this to an edge (in pixels) are part of the line.
const HALF_WIDTH: f32 = 0.6;
/// A triangle's depth at a pixel within this fraction of the visible depth is the visible one.
const DEPTH_TOLERANCE: f32 = 2e-3;

/// Draws the edges of every triangle of `prepared` seen through `target` onto `framebuffer`,
/// where the triangle is the visible surface; with `only`, those of that object alone.
pub fn draw_wireframe(
    prepared: &PreparedScene,
    target: &RenderTarget,
    only: Option<usize>,
    framebuffer: &mut Framebuffer,
) {
    let objects = frame_objects(prepared, target.camera);
    let wanted = |t: &ScreenTriangle| only.is_none_or(|o| t.object as usize == o);
    for triangle in screen_triangles(&objects, target)
        .into_iter()
        .filter(wanted)
    {
        draw_triangle_edges(&triangle, framebuffer);
    }
}

fn draw_triangle_edges(triangle: &ScreenTriangle, framebuffer: &mut Framebuffer) {
    let b = triangle.bounds;
    let width = framebuffer.width as usize;
    let lengths = triangle
        .edges
        .map(|e| ((e.step_x as f64).hypot(e.step_y as f64)).max(1.0));
    for y in b.y0..=b.y1 {
        for x in b.x0..=b.x1 {
            let (dx, dy) = ((x - b.x0) as i64, (y - b.y0) as i64);
            let values = triangle
                .edges
                .map(|e| e.at_origin + e.step_x * dx + e.step_y * dy);
            if values.iter().any(|&v| v < 0) {
                continue;
            }
            let distance = (0..3)
                .map(|i| values[i] as f64 / lengths[i])
                .fold(f64::INFINITY, f64::min);
            if distance > HALF_WIDTH as f64 {
                continue;
            }
            let index = y as usize * width + x as usize;
            let offset = Vec2::new(x as f32 + 0.5, y as f32 + 0.5) - triangle.origin;
            let depth = 1.0 / triangle.inv_w.at(offset);
            let (color, depths) = framebuffer.parts_mut();
            let visible = depths[index];
            if (depth - visible).abs() <= DEPTH_TOLERANCE * visible.abs().max(1e-6) {
                color[index] = LINE_COLOR;
            }
        }
    }
}
