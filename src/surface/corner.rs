//! A corner of a model's triangle, as the rasterizer and the exact rays read it.

use glam::{Vec2, Vec3, Vec4};

/// One corner of a triangle: its point (relative to the anchor), unit normal, MikkTSpace tangent
/// (w: the bitangent's sign) and texture (u,v), the latter already scaled to pattern units.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Corner {
    pub p: Vec3,
    pub n: Vec3,
    pub tangent: Vec4,
    pub uv: Vec2,
}
