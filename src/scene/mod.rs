//! What is drawn: surfaces with materials, lights and a camera, from a TOML file or a preset.

mod binding_file;
mod by_name;
mod checked_values;
pub mod dependencies;
mod displacement_requests;
pub(crate) mod exact_arrays;
mod file;
mod material;
mod material_choice;
mod model_stage;
mod prepared_scene;
mod presets;
mod quality_table;
mod torus_file;
pub(crate) mod user_words;

pub use binding_file::{BindingFile, FilterFile, MappingKind, WrapFile, load_pattern};
pub use by_name::{load_source, put_pattern_on, source_text};
pub use file::{
    CameraFile, Direction, FieldOfView, Finite, LightFile, MAX_SCENE_FILE_BYTES, MAX_TIME_SECONDS,
    Point, Positive, SceneFile, SceneTime, camera_looking, load_scene_file, parse_scene,
    parse_scene_in, shortest,
};
pub use material::{
    Bump, BumpSource, ImageHeight, ImageTexture, Material, NormalMapBump, PatternBinding,
    Placement, Texturing,
};
pub use material_choice::{IMAGE_BUMP_STRENGTH, MaterialChoice};
pub use model_stage::ModelSource;
pub use prepared_scene::{PreparedObject, PreparedScene};
pub use presets::{PRESET_NAMES, preset, preset_file};
pub use quality_table::{KnobPlace, KnobSetting, QualityTable, written_table};

pub use crate::camera::Camera;
use crate::surface::Surface;
use glam::{DVec3, Vec3};

/// A scene ready to render. Colours are linear RGB.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub name: String,
    pub camera: Camera,
    pub background: Vec3,
    pub ambient: Vec3,
    pub lights: Vec<Light>,
    pub objects: Vec<Object>,
    /// The time a still shows unless another is asked for, in seconds.
    pub time: f64,
    /// The scene file's `[quality]` settings, applied over the chosen preset.
    pub quality: Vec<KnobSetting>,
    /// Whether lights cast shadows (they do unless the scene file says `shadows = false`).
    pub shadows: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub surface: Surface,
    pub material: Material,
    /// Whether the object is drawn as the new surface P + B·n its bump height B describes
    /// (true displacement) rather than as the unmoved surface with Blinn's bumped normal.
    pub displace: bool,
}

impl Scene {
    /// Whether any object's look changes with time, so frames at different times differ.
    pub fn moves_with_time(&self) -> bool {
        self.objects.iter().any(|o| o.material.moves_with_time())
    }

    /// The memory its decoded images take, each shared image counted once.
    pub fn image_bytes(&self) -> u64 {
        let mut seen = std::collections::HashSet::new();
        let mut bytes = 0;
        for material in self.objects.iter().map(|o| &o.material) {
            if let Some(Texturing::Image(image)) = &material.texture
                && seen.insert(std::sync::Arc::as_ptr(&image.texture).cast::<()>())
            {
                bytes += image.texture.bytes();
            }
            if let Some(BumpSource::Image(image)) = material.bump.as_ref().map(|b| &b.source)
                && seen.insert(std::sync::Arc::as_ptr(&image.map).cast::<()>())
            {
                bytes += image.map.bytes();
            }
            if let Some(BumpSource::NormalMap(normals)) = material.bump.as_ref().map(|b| &b.source)
                && seen.insert(std::sync::Arc::as_ptr(&normals.map).cast::<()>())
            {
                bytes += normals.map.bytes();
            }
        }
        bytes
    }
}

/// Lights have no distance fall-off, like the seed's ray tracer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    Point { position: DVec3, color: Vec3 },
    Directional { towards: Vec3, color: Vec3 },
}

/// A scene named on the command line: a built-in name, or a path to a scene file.
pub fn resolve(name_or_path: &str) -> Result<Scene, crate::Error> {
    if let Some(scene) = preset(name_or_path) {
        return Ok(scene);
    }
    match unknown_scene(name_or_path) {
        Some(error) => Err(error),
        None => load_scene_file(std::path::Path::new(name_or_path)),
    }
}

/// The error for a name that is no built-in scene and no file that could be one (an existing
/// path, or a name ending in `.toml` or `.pat`), with the closest built-in name; `None` if the
/// name may be loaded.
pub fn unknown_scene(name: &str) -> Option<crate::Error> {
    let could_be_a_file = std::path::Path::new(name).exists()
        || name.ends_with(".toml")
        || name.ends_with(".pat")
        || crate::texture::is_image_name(name)
        || ModelSource::parse(name).is_some();
    (preset(name).is_none() && !could_be_a_file).then(|| crate::Error::UnknownScene {
        name: name.to_string(),
        suggestion: presets::closest_name(name),
    })
}
