//! What a surface looks like: a Blinn-Phong material, optionally with a texture (a colour pattern
//! or an image) and a bump map (a height or slope pattern, a grey image, or a normal map).

use crate::pattern::Pattern;
use crate::texture::{
    HeightMap, Mapping, NormalConvention, NormalMap, Sampler, SurfacePoint, Texture,
    TextureMapping, Wrap,
};
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

impl Material {
    /// Whether the look can change with time: a pattern that moves with `t` at its parameter
    /// values, or an image that scrolls.
    pub fn moves_with_time(&self) -> bool {
        let texture = match &self.texture {
            Some(Texturing::Pattern(b)) => b.moves_with_time(),
            Some(Texturing::Image(image)) => image.mapping.moves_with_time(),
            None => false,
        };
        let bump = match self.bump.as_ref().map(|b| &b.source) {
            Some(BumpSource::Pattern(b)) => b.moves_with_time(),
            Some(BumpSource::Image(image)) => image.mapping.moves_with_time(),
            Some(BumpSource::NormalMap(map)) => map.mapping.moves_with_time(),
            None => false,
        };
        texture || bump
    }
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
    /// Whether it defines a height B (not only its slope: slope patterns and normal maps do
    /// not), which is what displacement moves the surface by.
    pub fn has_height(&self) -> bool {
        match &self.source {
            BumpSource::Pattern(binding) => {
                binding.pattern.output() == crate::pattern::OutputKind::Height
            }
            BumpSource::Image(_) => true,
            BumpSource::NormalMap(_) => false,
        }
    }

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
    NormalMap(NormalMapBump),
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

impl PatternBinding {
    pub fn moves_with_time(&self) -> bool {
        self.pattern.moves_with_time(&self.params)
    }
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

/// A tangent-space normal map as a bump: its red tilts the normal along +u, its green along +v
/// (OpenGL) or −v (DirectX), as `bumpwork bake` writes them. It has no height, so the full normal
/// form treats it as Blinn's.
#[derive(Clone, Debug)]
pub struct NormalMapBump {
    pub name: String,
    pub map: Arc<NormalMap>,
    pub mapping: Mapping,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    pub convention: NormalConvention,
}

impl PartialEq for NormalMapBump {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
            && self.mapping == other.mapping
            && (self.wrap_s, self.wrap_t) == (other.wrap_s, other.wrap_t)
            && self.convention == other.convention
    }
}

/// The steepest tilt a normal map gives: its normals' out-of-surface part is at least this, so
/// a texel lying in the surface plane cannot give an infinite slope.
const LEAST_OUTWARD: f32 = 1e-3;

impl NormalMapBump {
    /// The gradient (Bu, Bv) of a height whose Blinn normal is the map's at `point`: the normal
    /// (x, y, z) in the frame (unit Pu, unit Pv, n) is that of a slope (−x/z·|Pu|, −y/z·|Pv|).
    pub fn gradient(&self, point: &SurfacePoint) -> Vec2 {
        let st = self.mapping.map(point).st;
        let n = self
            .map
            .sample(st, (self.wrap_s, self.wrap_t), self.convention);
        let outward = n.z.max(LEAST_OUTWARD);
        let slope = Vec2::new(-n.x * point.pu.length(), -n.y * point.pv.length()) / outward;
        if slope.is_finite() { slope } else { Vec2::ZERO }
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
