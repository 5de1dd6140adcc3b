//! What a surface looks like: a Blinn-Phong material, optionally with a texture (a colour pattern
//! or an image) and a bump map (a height or slope pattern, or a grey image).

use crate::pattern::Pattern;
use crate::texture::{HeightMap, Mapping, Sampler, Texture, Wrap};
use glam::{Mat2, Vec2, Vec3};
use std::sync::Arc;

/// Blinn-Phong material: diffuse colour (linear RGB), white specular weight and exponent.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub color: Vec3,
    pub specular: f32,
    pub shininess: f32,
    /// Replaces `color` where present.
    pub texture: Option<Texturing>,
    pub bump: Option<Bump>,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            color: Vec3::splat(0.6),
            specular: 0.3,
            shininess: 40.0,
            texture: None,
            bump: None,
        }
    }
}

/// A bump map on a surface: the height B(u,v) whose gradient tilts the normal (Blinn 1978).
/// Higher is raised along the outward normal; `invert` sinks it instead.
#[derive(Clone, Debug, PartialEq)]
pub struct Bump {
    pub source: BumpSource,
    pub strength: f32,
    pub invert: bool,
}

impl Bump {
    /// The factor applied to B: strength, negated when inverted.
    pub fn scale(&self) -> f32 {
        if self.invert {
            -self.strength
        } else {
            self.strength
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum BumpSource {
    Pattern(PatternBinding),
    Image(ImageHeight),
}

#[derive(Clone, Debug, PartialEq)]
pub enum Texturing {
    Pattern(PatternBinding),
    Image(ImageTexture),
}

/// A compiled pattern with its live parameter values and its placement on the surface.
#[derive(Clone, Debug)]
pub struct PatternBinding {
    /// As written in the scene: a built-in name or a file path.
    pub name: String,
    pub pattern: Pattern,
    /// One value per `pattern.params()`, in order.
    pub params: Vec<f32>,
    pub placement: Placement,
}

impl PartialEq for PatternBinding {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name && self.params == other.params && self.placement == other.placement
    }
}

/// A grey image as a height field, lighter is higher.
#[derive(Clone, Debug)]
pub struct ImageHeight {
    pub name: String,
    pub map: Arc<HeightMap>,
    pub mapping: Mapping,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    /// Put on by the workbench's keys with the default placement, not as a scene file says.
    pub chosen_live: bool,
}

impl PartialEq for ImageHeight {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
            && self.mapping == other.mapping
            && (self.wrap_s, self.wrap_t) == (other.wrap_s, other.wrap_t)
            && self.chosen_live == other.chosen_live
    }
}

#[derive(Clone, Debug)]
pub struct ImageTexture {
    pub name: String,
    pub texture: Arc<Texture>,
    pub mapping: Mapping,
    pub sampler: Sampler,
    /// Put on by the workbench's keys with the default placement, not as a scene file says.
    pub chosen_live: bool,
}

impl PartialEq for ImageTexture {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
            && self.mapping == other.mapping
            && self.sampler == other.sampler
            && self.chosen_live == other.chosen_live
    }
}

/// Where a pattern sits on the surface: pattern coordinates q = R(rotate)·((u,v) / scale) + offset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub scale: Vec2,
    pub rotate_degrees: f32,
    pub offset: Vec2,
}

impl Default for Placement {
    fn default() -> Self {
        Placement {
            scale: Vec2::ONE,
            rotate_degrees: 0.0,
            offset: Vec2::ZERO,
        }
    }
}

impl Placement {
    /// ∂q/∂(u,v): columns are ∂q/∂u and ∂q/∂v.
    pub fn jacobian(&self) -> Mat2 {
        Mat2::from_angle(self.rotate_degrees.to_radians()) * Mat2::from_diagonal(self.scale.recip())
    }

    pub fn apply(&self, uv: Vec2, jacobian: Mat2) -> Vec2 {
        jacobian * uv + self.offset
    }
}
