//! Clipping triangles in homogeneous clip space against the near plane and the frustum sides.

use glam::{Vec2, Vec4};

/// A vertex in homogeneous clip space with the surface parameters it carries.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    pub position: Vec4,
    pub uv: Vec2,
}

impl ClipVertex {
    fn lerp(self, other: ClipVertex, t: f32) -> ClipVertex {
        ClipVertex {
            position: self.position.lerp(other.position, t),
            uv: self.uv.lerp(other.uv, t),
        }
    }
}

/// Room for a triangle clipped by up to six planes (each plane adds at most one vertex).
pub const MAX_CLIPPED_VERTICES: usize = 9;

/// A convex polygon in clip space, stored inline (no allocation per triangle).
#[derive(Clone, Copy, Debug)]
pub struct ClippedPolygon {
    pub vertices: [ClipVertex; MAX_CLIPPED_VERTICES],
    pub len: usize,
}

impl ClippedPolygon {
    pub fn as_slice(&self) -> &[ClipVertex] {
        &self.vertices[..self.len]
    }
}

/// Clips a triangle against the near plane (z ≥ 0), the far plane (z ≤ w) and the guard band
/// |x|, |y| ≤ guard·w, in homogeneous space, so triangles through or behind the camera come out
/// right. The guard band keeps snapped screen coordinates inside the fixed-point range; triangles
/// inside it (nearly all) are passed through untouched. Returns `None` when nothing is left.
pub fn clip_triangle(triangle: [ClipVertex; 3], guard: f32) -> Option<ClippedPolygon> {
    let mut polygon = ClippedPolygon {
        vertices: [triangle[0]; MAX_CLIPPED_VERTICES],
        len: 3,
    };
    polygon.vertices[..3].copy_from_slice(&triangle);
    let mut untouched = true;
    for plane in CLIP_PLANES {
        if untouched && wholly_inside(&triangle, plane, guard) {
            continue; // the common case costs three comparisons
        }
        polygon = clip_polygon(&polygon, |p| plane(p, guard))?;
        untouched = false;
    }
    Some(polygon)
}

/// Whether clipping would return the triangle unchanged (as nearly all triangles are): callers
/// can then skip building a polygon.
pub fn needs_no_clipping(triangle: &[ClipVertex; 3], guard: f32) -> bool {
    triangle
        .iter()
        .all(|v| inside_clip_volume(v.position, guard))
}

/// Whether a clip-space point lies inside every clip plane: a triangle of three such points
/// needs no clipping.
#[inline(always)]
pub fn inside_clip_volume(position: Vec4, guard: f32) -> bool {
    CLIP_PLANES
        .iter()
        .all(|&plane| plane(position, guard) >= 0.0)
}

/// Signed distances of a clip-space point to the planes, non-negative inside; `guard` is the
/// guard band's half-width.
const CLIP_PLANES: [fn(Vec4, f32) -> f32; 6] = [
    |p, _| p.z,
    |p, _| p.w - p.z,
    |p, g| g * p.w - p.x,
    |p, g| g * p.w + p.x,
    |p, g| g * p.w - p.y,
    |p, g| g * p.w + p.y,
];

fn wholly_inside(triangle: &[ClipVertex; 3], plane: fn(Vec4, f32) -> f32, guard: f32) -> bool {
    triangle.iter().all(|v| plane(v.position, guard) >= 0.0)
}

/// One Sutherland–Hodgman pass: keeps the part of the polygon where `distance ≥ 0`.
fn clip_polygon(input: &ClippedPolygon, distance: impl Fn(Vec4) -> f32) -> Option<ClippedPolygon> {
    let mut out = ClippedPolygon {
        vertices: input.vertices,
        len: 0,
    };
    let vertices = input.as_slice();
    for (i, &current) in vertices.iter().enumerate() {
        let next = vertices[(i + 1) % vertices.len()];
        let (d_current, d_next) = (distance(current.position), distance(next.position));
        if !(d_current.is_finite() && d_next.is_finite()) {
            return None;
        }
        if d_current >= 0.0 {
            out.vertices[out.len] = current;
            out.len += 1;
        }
        if (d_current >= 0.0) != (d_next >= 0.0) {
            let t = d_current / (d_current - d_next);
            out.vertices[out.len] = current.lerp(next, t);
            out.len += 1;
        }
    }
    (out.len >= 3).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vertex(x: f32, y: f32, z: f32, w: f32) -> ClipVertex {
        ClipVertex {
            position: Vec4::new(x, y, z, w),
            uv: Vec2::new(x, y),
        }
    }

    #[test]
    fn inside_triangles_pass_untouched() {
        let tri = [
            vertex(0.0, 0.0, 0.5, 1.0),
            vertex(0.5, 0.0, 0.5, 1.0),
            vertex(0.0, 0.5, 0.5, 1.0),
        ];
        let p = clip_triangle(tri, 4.0).unwrap();
        assert_eq!(p.as_slice(), &tri);
        assert!(needs_no_clipping(&tri, 4.0));
    }

    #[test]
    fn a_triangle_through_the_near_plane_keeps_its_front_part() {
        let tri = [
            vertex(0.0, 0.0, -1.0, 0.5),
            vertex(0.5, 0.0, 1.0, 2.0),
            vertex(0.0, 0.5, 1.0, 2.0),
        ];
        assert!(!needs_no_clipping(&tri, 4.0));
        let p = clip_triangle(tri, 4.0).unwrap();
        assert_eq!(p.len, 4);
        for v in p.as_slice() {
            assert!(v.position.z >= -1e-6, "{v:?}");
        }
    }

    #[test]
    fn a_triangle_behind_the_camera_vanishes() {
        let tri = [
            vertex(0.0, 0.0, -1.0, -1.0),
            vertex(1.0, 0.0, -1.0, -1.0),
            vertex(0.0, 1.0, -2.0, -2.0),
        ];
        assert!(clip_triangle(tri, 4.0).is_none());
    }

    #[test]
    fn all_six_planes_at_once_stay_within_capacity() {
        let big = 1e3;
        let tri = [
            vertex(-big, -big, -5.0, 1.0),
            vertex(big, -big, 5.0, 1.0),
            vertex(0.0, big, 0.5, 1.0),
        ];
        let p = clip_triangle(tri, 2.0).unwrap();
        assert!(p.len <= MAX_CLIPPED_VERTICES);
        for v in p.as_slice() {
            let q = v.position;
            assert!(q.z >= -1e-4 && q.z <= q.w + 1e-4 && q.x.abs() <= 2.0 * q.w + 1e-3);
        }
    }
}
