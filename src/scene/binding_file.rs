//! The `bump = {…}` and `texture = {…}` tables of a scene file's objects, and how they load:
//! patterns and images by built-in name or by path relative to the scene file.

use super::checked_values::{Finite, Positive};
use super::exact_arrays::{exact_nested_optional, exact_optional};
use super::material::{
    Bump, BumpSource, ImageHeight, ImageTexture, NormalMapBump, PatternBinding, Placement,
    Texturing,
};
use crate::pattern::{OutputKind, Pattern};
use crate::surface::{Parametric, Surface};
use crate::texture::{
    Cylindrical, Filter, ImageCache, Mapping, NormalConvention, Sampler, Scroll, Spherical,
    SurfaceUv, TriangleMap, Wrap,
};
use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// The `bump = {…}` or `texture = {…}` table of an object: exactly one of `pattern` and `image`,
/// and where it sits. One type for both (rather than a shared part flattened into two) so serde
/// keeps every field's line and column for error messages.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct BindingFile {
    /// A built-in pattern name or a `.pat` file (bump: `height` or `slope`; texture: `color`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pattern: Option<String>,
    /// A built-in image name or an image file (bump: grey, lighter is higher).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub image: Option<String>,
    /// Bumps only: a tangent-space normal map (an RGB image file, as `bumpwork bake` writes).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_map: Option<String>,
    /// Normal maps only: which way green points (default `opengl`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub convention: Option<NormalConvention>,
    /// Bumps only: the factor on the height (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strength: Option<Finite>,
    /// Bumps only: sink what the pattern raises.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub invert: Option<bool>,
    /// Image textures only (default trilinear).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub filter: Option<FilterFile>,
    /// Images: what lies past the image's edges (default: repeat; clamp for spherical and
    /// cylindrical mappings).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wrap: Option<WrapFile>,
    /// Pattern parameters by name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub params: BTreeMap<String, f64>,
    /// Patterns: feature size multiplier along u and v. Images with the `uv` mapping: the (u,v)
    /// extent one copy of the image covers (default: the whole surface).
    #[serde(
        default,
        deserialize_with = "exact_optional",
        skip_serializing_if = "Option::is_none"
    )]
    pub scale: Option<[Positive; 2]>,
    /// Patterns: degrees.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotate: Option<Finite>,
    #[serde(
        default,
        deserialize_with = "exact_optional",
        skip_serializing_if = "Option::is_none"
    )]
    pub offset: Option<[Finite; 2]>,
    /// Images: how the surface maps to the image (default `uv`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mapping: Option<MappingKind>,
    /// Images with the `triangle` mapping: the image points (s, t in 0..1, t down) at the
    /// triangle's corners a, b, c.
    #[serde(
        default,
        deserialize_with = "exact_nested_optional",
        skip_serializing_if = "Option::is_none"
    )]
    pub image_points: Option<[[Finite; 2]; 3]>,
    /// Images: images per second the picture moves by (the seed's "Mona Scroll").
    #[serde(
        default,
        deserialize_with = "exact_optional",
        skip_serializing_if = "Option::is_none"
    )]
    pub scroll: Option<[Finite; 2]>,
}

#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq)]
#[serde(rename_all = "kebab-case")]
pub enum MappingKind {
    /// The surface's own (u,v), scaled so one copy covers `scale` units.
    Uv,
    /// Longitude and latitude around the surface's centre (atan2: continuous across the seam).
    Spherical,
    /// Angle around and height along the surface's axis (cones, paraboloids).
    Cylindrical,
    /// The image's `image-points` to the triangle's corners, by barycentric coordinates.
    Triangle,
}

#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq)]
#[serde(rename_all = "kebab-case")]
pub enum WrapFile {
    Repeat,
    Clamp,
    Mirror,
}

#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq)]
#[serde(rename_all = "kebab-case")]
pub enum FilterFile {
    Nearest,
    Bilinear,
    Trilinear,
}

impl BindingFile {
    /// Image `name` at the default placement, as a scene file's `image = "NAME"` alone.
    pub fn image(name: &str) -> BindingFile {
        BindingFile {
            image: Some(name.to_string()),
            ..BindingFile::default()
        }
    }

    pub fn load_bump(
        &self,
        surface: &Surface,
        base: &Path,
        images: &mut ImageCache,
    ) -> Result<Bump, String> {
        if self.filter.is_some() {
            return Err("`filter` applies to image textures, not bumps".into());
        }
        if self.convention.is_some() && self.normal_map.is_none() {
            return Err("`convention` applies to `normal-map` bumps".into());
        }
        let source = match (&self.pattern, &self.image, &self.normal_map) {
            (Some(name), None, None) => {
                let binding = self.bind_pattern(name, base)?;
                if binding.pattern.output() == OutputKind::Color {
                    return Err(format!(
                        "bump pattern '{name}' is a colour pattern; a bump needs `height` or `slope`"
                    ));
                }
                BumpSource::Pattern(binding)
            }
            (None, Some(name), None) => {
                let map = images.height_map(name, base).map_err(|e| e.to_string())?;
                let mapping = self.image_mapping(surface)?;
                let (wrap_s, wrap_t) = self.wrap_for(&mapping);
                BumpSource::Image(ImageHeight {
                    name: name.clone(),
                    map,
                    mapping,
                    wrap_s,
                    wrap_t,
                    chosen_live: false,
                })
            }
            (None, None, Some(name)) => {
                let map = images.normal_map(name, base).map_err(|e| e.to_string())?;
                let mapping = self.image_mapping(surface)?;
                let (wrap_s, wrap_t) = self.wrap_for(&mapping);
                BumpSource::NormalMap(NormalMapBump {
                    name: name.clone(),
                    map,
                    mapping,
                    wrap_s,
                    wrap_t,
                    convention: self.convention.unwrap_or_default(),
                })
            }
            _ => {
                return Err(
                    "a bump needs exactly one of `pattern`, `image` and `normal-map`".into(),
                );
            }
        };
        Ok(Bump {
            source,
            strength: self.strength.map_or(1.0, |s| s.0),
            invert: self.invert.unwrap_or(false),
        })
    }

    pub fn load_texture(
        &self,
        surface: &Surface,
        base: &Path,
        images: &mut ImageCache,
    ) -> Result<Texturing, String> {
        if self.strength.is_some() || self.invert.is_some() {
            return Err("`strength` and `invert` apply to bumps, not textures".into());
        }
        if self.normal_map.is_some() || self.convention.is_some() {
            return Err("`normal-map` and `convention` apply to bumps, not textures".into());
        }
        match (&self.pattern, &self.image) {
            (Some(name), None) => {
                let binding = self.bind_pattern(name, base)?;
                if binding.pattern.output() != OutputKind::Color {
                    return Err(format!(
                        "texture pattern '{name}' is a bump pattern; a texture needs `color`"
                    ));
                }
                Ok(Texturing::Pattern(binding))
            }
            (None, Some(name)) => {
                let texture = images.texture(name, base).map_err(|e| e.to_string())?;
                let mapping = self.image_mapping(surface)?;
                let filter = match self.filter.unwrap_or(FilterFile::Trilinear) {
                    FilterFile::Nearest => Filter::Nearest,
                    FilterFile::Bilinear => Filter::Bilinear,
                    FilterFile::Trilinear => Filter::Trilinear,
                };
                let (wrap_s, wrap_t) = self.wrap_for(&mapping);
                let sampler = Sampler {
                    filter,
                    wrap_s,
                    wrap_t,
                };
                Ok(Texturing::Image(ImageTexture {
                    name: name.clone(),
                    texture,
                    mapping,
                    sampler,
                    chosen_live: false,
                }))
            }
            _ => Err("a texture needs exactly one of `pattern` and `image`".into()),
        }
    }
}

impl BindingFile {
    /// The wrap along s and t: as asked, else images repeat, except that around spheres and
    /// cylinders t clamps at the poles and ends (s still wraps across the seam).
    fn wrap_for(&self, mapping: &Mapping) -> (Wrap, Wrap) {
        let asked = |w: WrapFile| match w {
            WrapFile::Repeat => Wrap::Repeat,
            WrapFile::Clamp => Wrap::Clamp,
            WrapFile::Mirror => Wrap::Mirror,
        };
        match (self.wrap, mapping) {
            (Some(w), _) => (asked(w), asked(w)),
            (None, Mapping::Spherical(_) | Mapping::Cylindrical(_)) => (Wrap::Repeat, Wrap::Clamp),
            (None, _) => (Wrap::Repeat, Wrap::Repeat),
        }
    }
}

impl BindingFile {
    fn bind_pattern(&self, name: &str, base: &Path) -> Result<PatternBinding, String> {
        let pattern = load_pattern(name, base)?;
        let mut params: Vec<f32> = pattern.params().iter().map(|p| p.default).collect();
        for (key, value) in &self.params {
            let index = pattern
                .params()
                .iter()
                .position(|p| &p.name == key)
                .ok_or_else(|| {
                    let known: Vec<&str> =
                        pattern.params().iter().map(|p| p.name.as_str()).collect();
                    format!(
                        "pattern '{name}' has no parameter '{key}' (it has: {})",
                        known.join(", ")
                    )
                })?;
            let p = &pattern.params()[index];
            if !(*value as f32 >= p.min && *value as f32 <= p.max) {
                return Err(format!(
                    "parameter '{key}' = {value} is outside its range {}..{}",
                    p.min, p.max
                ));
            }
            params[index] = *value as f32;
        }
        let placement = Placement {
            scale: self.scale.map_or(Vec2::ONE, |[a, b]| Vec2::new(a.0, b.0)),
            rotate_degrees: self.rotate.map_or(0.0, |r| r.0),
            offset: self.offset.map_or(Vec2::ZERO, |[a, b]| Vec2::new(a.0, b.0)),
        };
        Ok(PatternBinding {
            name: name.to_string(),
            pattern,
            params,
            placement,
        })
    }

    fn image_mapping(&self, surface: &Surface) -> Result<Mapping, String> {
        let mapping = match self.mapping.unwrap_or(MappingKind::Uv) {
            MappingKind::Uv => {
                let domain = surface.domain();
                let extent = self
                    .scale
                    .map_or(domain.max - domain.min, |[a, b]| Vec2::new(a.0, b.0));
                let offset = self.offset.map_or(Vec2::ZERO, |[a, b]| Vec2::new(a.0, b.0));
                // v grows up a plane but t grows down an image: flip so pictures stand upright.
                let scale = Vec2::new(1.0 / extent.x, -1.0 / extent.y);
                Mapping::SurfaceUv(SurfaceUv {
                    scale,
                    offset: Vec2::new(0.0, 1.0) + offset,
                })
            }
            MappingKind::Spherical => Mapping::Spherical(Spherical::new(Vec3::ZERO)),
            MappingKind::Cylindrical => Mapping::Cylindrical(cylinder_around(surface)?),
            MappingKind::Triangle => Mapping::Triangle(triangle_map(surface, self.image_points)?),
        };
        Ok(match self.scroll {
            Some([a, b]) => Mapping::Scroll(Scroll {
                inner: Box::new(mapping),
                velocity: Vec2::new(a.0, b.0),
            }),
            None => mapping,
        })
    }
}

fn cylinder_around(surface: &Surface) -> Result<Cylindrical, String> {
    let (axis, height) = match surface {
        Surface::Cone(c) => (c.basis.axis, c.height),
        Surface::Paraboloid(p) => (p.basis.axis, p.curvature * p.radius * p.radius),
        _ => return Err("the cylindrical mapping needs a cone or a paraboloid".into()),
    };
    let front = axis.any_orthonormal_vector();
    Cylindrical::oriented(Vec3::ZERO, axis, front, height)
        .ok_or_else(|| "degenerate cylinder axis".to_string())
}

fn triangle_map(
    surface: &Surface,
    image_points: Option<[[Finite; 2]; 3]>,
) -> Result<TriangleMap, String> {
    let Surface::Triangle(t) = surface else {
        return Err("the triangle mapping needs a triangle surface".into());
    };
    let points = image_points.map_or(
        [
            Vec2::new(0.0, 1.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(0.5, 0.0),
        ],
        |p| p.map(|[s, t]| Vec2::new(s.0, t.0)),
    );
    let corners = t.corners_uv.map(|uv| t.frame(uv.x, uv.y).p);
    TriangleMap::new(corners, points)
        .ok_or_else(|| "the image points must not be collinear".to_string())
}

/// A pattern by built-in name, or a `.pat` file relative to `base` (a scene file's directory).
pub fn load_pattern(name: &str, base: &Path) -> Result<Pattern, String> {
    match crate::pattern::builtin(name) {
        Some(source) => Pattern::compile(source, &format!("{name}.pat")),
        None => Pattern::load(&base.join(name)),
    }
    .map_err(|e| e.to_string())
}
