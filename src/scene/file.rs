//! The scene file: TOML, every field checked as it is read so that a bad value is reported at its
//! own line and column. Built-in presets are written in the same types, so any preset can be
//! printed as a file and edited.

use super::binding_file::BindingFile;
pub use super::checked_values::{
    Direction, FieldOfView, Finite, HalfAngle, MAX_TIME_SECONDS, NonNegative, Point, Positive, Rgb,
    SceneTime, shortest,
};
use super::checked_values::{down, up};
use super::exact_arrays::exact;
use super::quality_table::{QualityTable, knob_settings};
use super::torus_file::TorusFile;
use super::{Light, Material, Object, Scene};
use crate::Error;
use crate::scene::Camera;
use crate::surface::{
    AxisBasis, Cone, ModelSurface, Paraboloid, Plane, Sphere, Surface, Triangle, Wave,
};
use crate::texture::ImageCache;
use glam::{DVec3, Vec2, Vec3};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The nearest near plane, as a fraction of the eye-target distance.
const MIN_NEAR_FRACTION: f32 = 1e-6;

/// Scene files past this size are refused before parsing.
pub const MAX_SCENE_FILE_BYTES: u64 = 1 << 20;

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct SceneFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    pub camera: CameraFile,
    #[serde(default = "black")]
    pub background: Rgb,
    #[serde(default = "dim")]
    pub ambient: Rgb,
    #[serde(default, rename = "light")]
    pub lights: Vec<LightFile>,
    #[serde(rename = "object")]
    pub objects: Vec<ObjectFile>,
    /// The scene time a still shows when none is asked for, in seconds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time: Option<SceneTime>,
    /// Whether lights cast shadows; they do unless this is false.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shadows: Option<bool>,
    /// Quality knobs over the chosen preset, applied by the quality module.
    #[serde(default, skip_serializing_if = "QualityTable::is_empty")]
    pub quality: QualityTable,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct CameraFile {
    pub eye: Point,
    pub target: Point,
    #[serde(default = "up")]
    pub up: Direction,
    /// Vertical field of view in degrees.
    #[serde(default = "default_fov")]
    pub fov: FieldOfView,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub near: Option<Positive>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub far: Option<Positive>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub enum LightFile {
    Point {
        position: Point,
        #[serde(default = "white")]
        color: Rgb,
    },
    Directional {
        /// From the surface towards the light.
        towards: Direction,
        #[serde(default = "white")]
        color: Rgb,
    },
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct ObjectFile {
    pub surface: SurfaceFile,
    #[serde(default)]
    pub material: MaterialFile,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<BindingFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bump: Option<BindingFile>,
    /// Draw the bump's height as true displacement of the surface.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub displace: bool,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub enum SurfaceFile {
    Plane {
        origin: Point,
        normal: Direction,
        #[serde(rename = "u-axis")]
        u_axis: Direction,
        #[serde(deserialize_with = "exact")]
        size: [Positive; 2],
    },
    Sphere {
        center: Point,
        radius: Positive,
    },
    Paraboloid {
        apex: Point,
        #[serde(default = "up")]
        axis: Direction,
        curvature: Positive,
        radius: Positive,
    },
    Cone {
        apex: Point,
        /// From the apex towards the base.
        #[serde(default = "down")]
        axis: Direction,
        #[serde(rename = "half-angle")]
        half_angle: HalfAngle,
        height: Positive,
    },
    Wave {
        origin: Point,
        #[serde(deserialize_with = "exact")]
        size: [Positive; 2],
        amplitude: Finite,
        wavelength: Positive,
    },
    Triangle {
        a: Point,
        b: Point,
        c: Point,
    },
    Torus(TorusFile),
    /// A model read from a Wavefront OBJ file (relative to the scene file), scaled about its
    /// origin and moved to `position`; its texture (u,v) 0..1 cover `uv-scale` pattern units.
    Mesh {
        file: String,
        #[serde(default = "origin")]
        position: Point,
        #[serde(default = "unit")]
        scale: Positive,
        #[serde(rename = "uv-scale", default = "lecture_plane")]
        uv_scale: Positive,
    },
}

fn origin() -> Point {
    Point(DVec3::ZERO)
}

fn unit() -> Positive {
    Positive(1.0)
}

/// One texture unit is the lecture's 400-wide plane.
fn lecture_plane() -> Positive {
    Positive(400.0)
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct MaterialFile {
    #[serde(default = "grey")]
    pub color: Rgb,
    #[serde(default = "default_specular")]
    pub specular: NonNegative,
    #[serde(default = "default_shininess")]
    pub shininess: Positive,
}

impl Default for MaterialFile {
    fn default() -> Self {
        MaterialFile {
            color: grey(),
            specular: default_specular(),
            shininess: default_shininess(),
        }
    }
}

fn black() -> Rgb {
    Rgb(Vec3::ZERO)
}
fn dim() -> Rgb {
    Rgb(Vec3::splat(0.08))
}
fn white() -> Rgb {
    Rgb(Vec3::ONE)
}
fn grey() -> Rgb {
    Rgb(Vec3::splat(0.6))
}
fn default_fov() -> FieldOfView {
    FieldOfView(40.0)
}
fn default_specular() -> NonNegative {
    NonNegative(0.3)
}
fn default_shininess() -> Positive {
    Positive(40.0)
}

/// Parses and checks scene text; `origin` names the file in messages, and pattern and image
/// paths are relative to its directory.
pub fn parse_scene(text: &str, origin: &str) -> Result<Scene, Error> {
    let base = Path::new(origin).parent().unwrap_or(Path::new("."));
    parse_scene_in(text, origin, base)
}

/// As `parse_scene`, with pattern and image paths relative to `base`.
pub fn parse_scene_in(text: &str, origin: &str, base: &Path) -> Result<Scene, Error> {
    let file: SceneFile = toml::from_str(text).map_err(|e| {
        let offset = e.span().map_or(0, |s| s.start);
        let message = super::user_words::in_user_words(e.message());
        Error::Diagnostic(crate::diagnostic::render(origin, text, offset, &message))
    })?;
    let fallback_name = Path::new(origin)
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy());
    let mut scene = file.to_scene(&fallback_name, base).map_err(|message| {
        Error::Diagnostic(format!(
            "{}: {message}",
            crate::diagnostic::sanitize(origin)
        ))
    })?;
    scene.quality = knob_settings(&file.quality, origin, text);
    Ok(scene)
}

/// Reads a scene file, refusing files past `MAX_SCENE_FILE_BYTES` before reading them.
pub fn load_scene_file(path: &Path) -> Result<Scene, Error> {
    let text = crate::read_text_limited(path, MAX_SCENE_FILE_BYTES)?;
    parse_scene(&text, &path.display().to_string())
}

impl SceneFile {
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("scene files hold only TOML-representable values")
    }

    /// The checked scene, or a message naming the object that cannot be built. Pattern and image
    /// paths are relative to `base` (the scene file's directory).
    pub fn to_scene(&self, fallback_name: &str, base: &Path) -> Result<Scene, String> {
        let mut images = ImageCache::new(crate::memory_budget::budget_bytes());
        let objects = self
            .objects
            .iter()
            .enumerate()
            .map(|(i, o)| {
                o.to_object(base, &mut images)
                    .map_err(|e| format!("object {} ({}): {e}", i + 1, o.surface.kind()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if objects.is_empty() {
            return Err("a scene needs at least one [[object]]".into());
        }
        Ok(Scene {
            name: self
                .name
                .clone()
                .unwrap_or_else(|| fallback_name.to_string()),
            camera: self.camera.to_camera()?,
            background: self.background.0,
            ambient: self.ambient.0,
            lights: self.lights.iter().map(LightFile::to_light).collect(),
            objects,
            time: self.time.map_or(0.0, |t| t.0),
            quality: Vec::new(),
            shadows: self.shadows.unwrap_or(true),
        })
    }
}

/// A camera from an eye, a target, an up direction and a vertical field of view (degrees), each
/// checked as a scene file's `[camera]` checks it; near and far follow from the eye's distance.
pub fn camera_looking(
    eye: [f64; 3],
    target: [f64; 3],
    up: [f64; 3],
    fov_degrees: f64,
) -> Result<Camera, String> {
    CameraFile {
        eye: Point::try_from(eye.to_vec()).map_err(|e| format!("the eye: {e}"))?,
        target: Point::try_from(target.to_vec()).map_err(|e| format!("the target: {e}"))?,
        up: Direction::try_from(up.to_vec()).map_err(|e| format!("up: {e}"))?,
        fov: FieldOfView::try_from(fov_degrees).map_err(|e| format!("the field of view: {e}"))?,
        near: None,
        far: None,
    }
    .to_camera()
}

impl CameraFile {
    pub(crate) fn to_camera(&self) -> Result<Camera, String> {
        let distance = (self.target.0 - self.eye.0).length() as f32;
        if distance <= 0.0 {
            return Err("the camera's eye and target are the same point".into());
        }
        let near = self.near.map_or(distance * 1e-3, |n| n.0);
        let far = self.far.map_or(distance * 1e6, |f| f.0);
        // Nearer than this, f32 depth across the default range holds no precision at all.
        let nearest = distance * MIN_NEAR_FRACTION;
        if near < nearest {
            return Err(format!(
                "the camera's near ({near}) must be at least {MIN_NEAR_FRACTION:e} of the \
                 eye-target distance, {nearest}"
            ));
        }
        if near >= far {
            return Err(format!(
                "the camera's near ({near}) must be less than its far ({far})"
            ));
        }
        Ok(Camera {
            eye: self.eye.0,
            target: self.target.0,
            up: self.up.0,
            vfov_degrees: self.fov.0,
            near,
            far,
        })
    }
}

impl LightFile {
    /// The light as a scene file writes it.
    pub fn of(light: &Light) -> LightFile {
        match *light {
            Light::Point { position, color } => LightFile::Point {
                position: Point(position),
                color: Rgb(color),
            },
            Light::Directional { towards, color } => LightFile::Directional {
                towards: Direction(towards),
                color: Rgb(color),
            },
        }
    }

    pub fn to_light(&self) -> Light {
        match *self {
            LightFile::Point { position, color } => Light::Point {
                position: position.0,
                color: color.0,
            },
            LightFile::Directional { towards, color } => Light::Directional {
                towards: towards.0,
                color: color.0,
            },
        }
    }
}

impl ObjectFile {
    fn to_object(&self, base: &Path, images: &mut ImageCache) -> Result<Object, String> {
        let surface = self.surface.to_surface(base)?;
        let texture = self
            .texture
            .as_ref()
            .map(|t| t.load_texture(&surface, base, images))
            .transpose()?;
        let bump = self
            .bump
            .as_ref()
            .map(|b| b.load_bump(&surface, base, images))
            .transpose()?;
        Ok(Object {
            surface,
            material: Material {
                color: self.material.color.0,
                specular: self.material.specular.0,
                shininess: self.material.shininess.0,
                texture,
                bump,
            },
            displace: self.displace,
        })
    }
}

impl SurfaceFile {
    pub fn kind(&self) -> &'static str {
        match self {
            SurfaceFile::Plane { .. } => "plane",
            SurfaceFile::Sphere { .. } => "sphere",
            SurfaceFile::Paraboloid { .. } => "paraboloid",
            SurfaceFile::Cone { .. } => "cone",
            SurfaceFile::Wave { .. } => "wave",
            SurfaceFile::Triangle { .. } => "triangle",
            SurfaceFile::Torus(_) => "torus",
            SurfaceFile::Mesh { .. } => "mesh",
        }
    }

    fn to_surface(&self, base: &Path) -> Result<Surface, String> {
        Ok(match *self {
            SurfaceFile::Plane {
                origin,
                normal,
                u_axis,
                size,
            } => {
                if normal.0.normalize().cross(u_axis.0.normalize()).length() < 1e-6 {
                    return Err("u-axis must not be parallel to the normal".into());
                }
                Surface::Plane(Plane::new(
                    origin.0,
                    normal.0,
                    u_axis.0,
                    Vec2::new(size[0].0, size[1].0),
                ))
            }
            SurfaceFile::Sphere { center, radius } => Surface::Sphere(Sphere {
                center: center.0,
                radius: radius.0,
            }),
            SurfaceFile::Paraboloid {
                apex,
                axis,
                curvature,
                radius,
            } => Surface::Paraboloid(Paraboloid {
                apex: apex.0,
                basis: AxisBasis::from_axis(axis.0),
                curvature: curvature.0,
                radius: radius.0,
            }),
            SurfaceFile::Cone {
                apex,
                axis,
                half_angle,
                height,
            } => Surface::Cone(Cone {
                apex: apex.0,
                basis: AxisBasis::from_axis(axis.0),
                half_angle: half_angle.0.to_radians(),
                height: height.0,
            }),
            SurfaceFile::Wave {
                origin,
                size,
                amplitude,
                wavelength,
            } => Surface::Wave(Wave {
                origin: origin.0,
                size: Vec2::new(size[0].0, size[1].0),
                amplitude: amplitude.0,
                wavelength: wavelength.0,
            }),
            SurfaceFile::Triangle { a, b, c } => {
                let area2 = (b.0 - a.0).cross(c.0 - a.0).length();
                let scale = (b.0 - a.0).length().max((c.0 - a.0).length());
                if area2.is_nan() || area2 <= 1e-9 * scale * scale {
                    return Err("the corners a, b and c are collinear".into());
                }
                Surface::Triangle(Triangle::new(a.0, b.0, c.0))
            }
            SurfaceFile::Torus(torus) => Surface::Torus(torus.to_torus()),
            SurfaceFile::Mesh {
                ref file,
                position,
                scale,
                uv_scale,
            } => {
                let placement = crate::model::Placement {
                    scale: scale.0,
                    uv_scale: uv_scale.0,
                };
                model_surface(file, base, position.0, placement)?
            }
        })
    }
}

/// The model `file` names (relative to `base`), placed with its origin at `position`.
fn model_surface(
    file: &str,
    base: &Path,
    position: DVec3,
    placement: crate::model::Placement,
) -> Result<Surface, String> {
    let data = crate::model::load_named_model(file, base, placement).map_err(|e| e.to_string())?;
    Ok(Surface::Model(ModelSurface {
        file: file.into(),
        origin: position,
        data: std::sync::Arc::new(data),
    }))
}
