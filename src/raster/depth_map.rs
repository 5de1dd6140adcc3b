//! Depth maps: the distance to the nearest surface seen from a point of view other than the
//! camera's (a light), drawn by the frames' own clipping, fixed-point setup and top-left scan
//! conversion, so a shadow map covers exactly the pixels a frame would.

use super::bin::{TILE_SIZE, TileBins};
use super::clip::{ClipVertex, clip_triangle, needs_no_clipping};
use super::interpolation::Interpolation;
use super::scan::{EdgeWalk, triangle_rows};
use super::screen_triangles::join_in_order;
use super::setup::{SampleShift, ScreenTriangle, ShiftSpan, TrianglePlanes, Viewport};
use crate::surface::Mesh;
use glam::{DVec3, Mat4, Vec2, Vec3};
use rayon::prelude::*;

/// A square view of the scene to take depths in.
#[derive(Clone, Copy, Debug)]
pub struct DepthView {
    /// The world point `view_projection` is relative to (in f64, as the camera's eye is).
    pub origin: DVec3,
    /// Origin-relative world positions to clip space, depth z in [0, w].
    pub view_projection: Mat4,
    /// The unit axis depth is measured along: depth = forward · (point − origin).
    pub forward: Vec3,
    /// Texels on a side.
    pub size: u32,
}

/// Per texel (row-major, row 0 at the top), the depth along the view's `forward` of the nearest
/// surface whose triangles cover the texel's centre; infinity where none does. Numerics: f32,
/// interpolated from each triangle's exact planes, so a texel's depth is the triangle's own
/// depth at its centre to f32 rounding.
#[derive(Clone, Debug)]
pub struct DepthMap {
    pub size: u32,
    pub depth: Vec<f32>,
}

impl DepthMap {
    pub const BYTES_PER_TEXEL: u64 = 4;

    pub fn at(&self, x: u32, y: u32) -> f32 {
        self.depth[(y * self.size + x) as usize]
    }
}

/// The depth map of `meshes`, each with the world point its positions are relative to (its
/// anchor), seen through `view`. No faces are culled: open surfaces cast shadows from either
/// side.
pub fn render_depth(meshes: &[(DVec3, &Mesh)], view: &DepthView) -> DepthMap {
    let viewport = Viewport {
        width: view.size,
        height: view.size,
    };
    let triangles = depth_triangles(meshes, view, viewport);
    let bins = TileBins::new(viewport, &triangles);
    // On huge pages where the kernel has them: a 1024² map is a thousand small pages to fault.
    let mut depth: Vec<f32> = crate::huge_pages::zeroed_huge((view.size as usize).pow(2));
    let strip = (TILE_SIZE * view.size.max(1)) as usize;
    depth
        .par_chunks_mut(strip)
        .enumerate()
        .for_each(|(ty, rows)| {
            rows.fill(f32::INFINITY);
            for tx in 0..bins.tiles_x {
                let rect = TileBins::tile_rect(viewport, tx, ty as u32);
                let y0 = rect.y0;
                for &index in bins.bin(tx, ty as u32) {
                    let t = &triangles[index as usize];
                    triangle_rows(t, &rect, &SampleShift::NONE, |row| {
                        let Some(run) = covered_run(&row.edges, row.x1 - row.x0 + 1) else {
                            return;
                        };
                        let start = ((row.y - y0) * view.size + row.x0) as usize;
                        let slots = &mut rows[start + run.start..start + run.end];
                        for (slot, x) in slots.iter_mut().zip(row.x0 + run.start as u32..) {
                            *slot = slot.min(depth_at(t, x, row.y));
                        }
                    });
                }
            }
        });
    DepthMap {
        size: view.size,
        depth,
    }
}

/// The pixels of a row (counted from its first, `width` of them) whose centres all three edge
/// functions hold non-negative, solved from the integer edge functions directly: the same
/// pixels as testing each, in time for the covered ones alone. Long thin triangles, as a light
/// sees a strip of a wave, cover little of their bounds.
fn covered_run(edges: &EdgeWalk, width: u32) -> Option<std::ops::Range<usize>> {
    let (mut first, mut last) = (0i64, i64::from(width) - 1);
    for (&at, &step) in edges.at.iter().zip(&edges.steps) {
        match step.signum() {
            // at + k·step ≥ 0 ⇔ k ≥ ⌈−at / step⌉.
            1 => first = first.max(-(at.div_euclid(step))),
            // ⇔ k ≤ ⌊at / −step⌋.
            -1 => last = last.min(at.div_euclid(-step)),
            _ if at < 0 => return None,
            _ => {}
        }
    }
    (first <= last).then(|| first as usize..last as usize + 1)
}

/// The triangle's depth at the centre of pixel (x, y). Depth rides in the u attribute, which
/// perspective-correct interpolation carries exactly, being affine over the triangle's plane.
#[inline]
fn depth_at(t: &ScreenTriangle, x: u32, y: u32) -> f32 {
    let offset = Vec2::new(x as f32 + 0.5, y as f32 + 0.5) - t.origin;
    t.u_over_w.at(offset) / t.inv_w.at(offset)
}

/// Every object's triangles clipped and set up for the view, their depth as attribute u.
/// Triangles wholly outside one side of the view are dropped before any setup: a cube face
/// sees a sixth of the scene.
fn depth_triangles(
    meshes: &[(DVec3, &Mesh)],
    view: &DepthView,
    viewport: Viewport,
) -> Vec<ScreenTriangle> {
    let guard = viewport.guard_band();
    let pieces = meshes
        .iter()
        .enumerate()
        .flat_map(|(index, &(anchor, mesh))| {
            let origin = (anchor - view.origin).as_vec3();
            let vertices: Vec<(ClipVertex, u8)> = mesh
                .positions
                .par_iter()
                .map(|&p| {
                    let relative = origin + p;
                    let position = view.view_projection * relative.extend(1.0);
                    let vertex = ClipVertex {
                        position,
                        uv: Vec2::new(view.forward.dot(relative), 0.0),
                    };
                    (vertex, outside_sides(position))
                })
                .collect();
            mesh.indices
                .par_iter()
                .fold(Vec::new, |mut out, corners| {
                    let [a, b, c] = corners.map(|i| vertices[i as usize]);
                    if a.1 & b.1 & c.1 == 0 {
                        set_up([a.0, b.0, c.0], viewport, guard, index as u32, &mut out);
                    }
                    out
                })
                .collect::<Vec<_>>()
        })
        .collect();
    join_in_order(pieces)
}

/// One bit for each side of the view volume a clip-space point lies beyond.
fn outside_sides(p: glam::Vec4) -> u8 {
    let beyond = [
        p.x > p.w,
        p.x < -p.w,
        p.y > p.w,
        p.y < -p.w,
        p.z < 0.0,
        p.z > p.w,
    ];
    beyond
        .iter()
        .enumerate()
        .fold(0, |bits, (i, &b)| bits | (u8::from(b) << i))
}

fn set_up(
    triangle: [ClipVertex; 3],
    viewport: Viewport,
    guard: f32,
    object: u32,
    out: &mut Vec<ScreenTriangle>,
) {
    let Some(planes) = TrianglePlanes::new(&triangle, viewport, Interpolation::PerspectiveCorrect)
    else {
        return;
    };
    let screen =
        |v: [ClipVertex; 3]| ScreenTriangle::new(v, viewport, &planes, object, &ShiftSpan::NONE);
    if needs_no_clipping(&triangle, guard) {
        out.extend(screen(triangle));
    } else if let Some(polygon) = clip_triangle(triangle, guard) {
        let v = polygon.as_slice();
        out.extend((1..v.len() - 1).filter_map(|k| screen([v[0], v[k], v[k + 1]])));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{Plane, Surface, Tessellation};

    /// A floor from −5 to 5 in x and z (v runs along N × U = −z), and its anchor.
    fn floor() -> (DVec3, Mesh) {
        let corner = DVec3::new(-5.0, 0.0, 5.0);
        let floor = Surface::Plane(Plane::new(
            corner,
            Vec3::Y,
            Vec3::X,
            glam::Vec2::splat(10.0),
        ));
        (
            floor.origin(),
            floor.tessellate(Tessellation { density: 4 }),
        )
    }

    #[test]
    fn a_row_run_is_the_pixels_each_edge_test_passes() {
        let mut seed = 1u64;
        let mut next = |range: i64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) as i64 % (2 * range + 1) - range
        };
        for _ in 0..5000 {
            let edges = EdgeWalk {
                at: [next(5000), next(5000), next(5000)],
                steps: [next(400), next(400), next(3)],
            };
            let width = 1 + next(40).unsigned_abs() as u32;
            let mut walk = edges;
            let each: Vec<usize> = (0..width as usize)
                .filter(|_| {
                    let inside = walk.inside();
                    walk.advance();
                    inside
                })
                .collect();
            let run: Vec<usize> = covered_run(&edges, width).into_iter().flatten().collect();
            assert_eq!(run, each, "{edges:?} over {width}");
        }
    }

    #[test]
    fn an_orthographic_view_straight_down_sees_the_floor_at_its_height() {
        let (anchor, mesh) = floor();
        // From 3 units above, looking down, a 4-unit-wide box: the floor is 3 units away.
        let forward = -Vec3::Y;
        let view = glam::camera::rh::view::look_to_mat4(Vec3::ZERO, forward, -Vec3::Z);
        let projection =
            glam::camera::rh::proj::directx::orthographic(-2.0, 2.0, -2.0, 2.0, 0.5, 9.0);
        let map = render_depth(
            &[(anchor, &mesh)],
            &DepthView {
                origin: DVec3::new(0.0, 3.0, 0.0),
                view_projection: projection * view,
                forward,
                size: 32,
            },
        );
        assert!(
            map.depth.iter().all(|&d| (d - 3.0).abs() < 1e-5),
            "{:?}",
            &map.depth[..4]
        );
    }

    #[test]
    fn a_perspective_view_sees_depth_along_its_axis_and_nothing_past_the_floor() {
        let (anchor, mesh) = floor();
        let forward = Vec3::new(0.0, -1.0, -1.0).normalize();
        let view = glam::camera::rh::view::look_to_mat4(Vec3::ZERO, forward, Vec3::Y);
        let projection = glam::camera::rh::proj::directx::perspective(1.2, 1.0, 0.1, 50.0);
        let origin = DVec3::new(0.0, 2.0, 3.0);
        let map = render_depth(
            &[(anchor, &mesh)],
            &DepthView {
                origin,
                view_projection: projection * view,
                forward,
                size: 48,
            },
        );
        let (mut seen, mut sky) = (0, 0);
        let inverse = (projection * view).inverse();
        for y in 0..48 {
            for x in 0..48 {
                let d = map.at(x, y);
                // The ray through the texel centre meets the floor y = 0 at this depth.
                let ndc = glam::Vec4::new(
                    (x as f32 + 0.5) / 24.0 - 1.0,
                    1.0 - (y as f32 + 0.5) / 24.0,
                    0.5,
                    1.0,
                );
                let p = inverse * ndc;
                let direction = (p.truncate() / p.w).normalize();
                let t = -2.0 / direction.y;
                let hit = direction * t;
                let world = hit + origin.as_vec3();
                let on_floor = direction.y < 0.0 && world.x.abs() < 5.0 && world.z.abs() < 5.0;
                let inside = world.x.abs() < 4.9 && world.z.abs() < 4.9;
                if on_floor && inside {
                    let want = forward.dot(hit);
                    assert!((d - want).abs() < 1e-3 * t, "texel {x},{y}: {d} vs {want}");
                    seen += 1;
                } else if !on_floor {
                    assert_eq!(d, f32::INFINITY, "texel {x},{y}");
                    sky += 1;
                }
            }
        }
        assert!(seen > 500 && sky > 100, "{seen} floor texels, {sky} sky");
    }
}
