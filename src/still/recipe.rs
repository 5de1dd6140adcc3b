//! What a still was made from, carried in its own PNG so `render --from` can make it again: the
//! scene's source and text, every object's live bump and texture patterns with their parameter
//! values, the camera and lights, the render settings, and a content hash of each file the scene reads.

use super::samples::{ResolveFilter, Supersampling};
use crate::Error;
use crate::content_hash::{fnv1a64, hash_file};
use crate::quality::Quality;
use crate::quality::check_quality;
use crate::scene::Camera;
use crate::scene::exact_arrays::exact;
use crate::scene::{
    BindingFile, BumpSource, CameraFile, Direction, FieldOfView, Finite, LightFile, Material,
    PatternBinding, Point, Positive, Scene, Texturing,
};
use crate::shade::ShaderMode;
use crate::texture::ImageCache;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The largest still side in pixels.
pub const MAX_SIDE: u32 = 16384;
pub use crate::scene::MAX_TIME_SECONDS;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct Recipe {
    /// The program and version that made the still, e.g. "bumpwork 0.1.0".
    pub program: String,
    /// A built-in scene name, or the absolute path of the scene or pattern file.
    pub source: String,
    pub width: u32,
    pub height: u32,
    /// How samples are resolved: "box" or "tent".
    pub filter: String,
    /// Scene time in seconds (animated patterns, scrolling images).
    pub time: f64,
    pub mode: String,
    /// Every speed/accuracy knob, samples per pixel included.
    pub quality: Quality,
    pub camera: RecipeCamera,
    /// Whether the lights cast shadows (`--set shadows` and the workbench change it).
    #[serde(default = "shadows_by_default")]
    pub shadows: bool,
    /// The lights as they were (the workbench moves them).
    #[serde(default, rename = "light")]
    pub lights: Vec<LightFile>,
    #[serde(default, rename = "object")]
    pub objects: Vec<ObjectState>,
    #[serde(default, rename = "file")]
    pub files: Vec<FileHash>,
}

fn shadows_by_default() -> bool {
    true
}

/// The camera exactly: f64 eye and target, f32 the rest (TOML round-trips both exactly).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct RecipeCamera {
    #[serde(deserialize_with = "exact")]
    pub eye: [f64; 3],
    #[serde(deserialize_with = "exact")]
    pub target: [f64; 3],
    #[serde(deserialize_with = "exact")]
    pub up: [f32; 3],
    pub fov: f32,
    pub near: f32,
    pub far: f32,
}

/// One object's live material edits: its bump and texture bindings where they are patterns
/// (name, parameter values, placement), and its bump's strength and sign whatever the source.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct ObjectState {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bump: Option<BindingFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<BindingFile>,
}

/// A file the scene reads and its FNV-1a 64-bit content hash, to tell whether it changed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct FileHash {
    pub path: String,
    pub fnv1a64: String,
}

/// The render settings a recipe records besides the scene and camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StillSettings {
    pub size: (u32, u32),
    /// Tessellation, samples per pixel and the shading knobs.
    pub quality: Quality,
    /// How the samples of a pixel are resolved.
    pub resolve: ResolveFilter,
    pub time: f64,
    pub mode: ShaderMode,
}

impl StillSettings {
    /// The scene tessellated (and texture filters set) as the quality asks, for this camera at
    /// this size.
    pub fn prepare(
        &self,
        scene: Scene,
        camera: &Camera,
    ) -> Result<crate::scene::PreparedScene, crate::memory_budget::OverBudget> {
        let (width, height) = self.size;
        self.prepare_with_output(scene, camera, super::bands::band_bytes(width, height))
    }

    /// As `prepare`, for a still whose buffers take `output_bytes` rather than a band's.
    pub fn prepare_with_output(
        &self,
        scene: Scene,
        camera: &Camera,
        output_bytes: u64,
    ) -> Result<crate::scene::PreparedScene, crate::memory_budget::OverBudget> {
        let (width, height) = self.size;
        let full = crate::raster::Viewport { width, height };
        // The scene at the moment the still shows: a displaced surface is cut as it is then.
        let scene = Scene {
            time: self.time,
            ..scene
        };
        self.quality.prepare(scene, camera, full, output_bytes)
    }

    /// The supersampling these settings ask for.
    pub fn supersampling(&self) -> Supersampling {
        Supersampling {
            samples: self.quality.samples,
            filter: self.resolve,
        }
    }
}

impl Recipe {
    /// The recipe of `scene` (as live, edits included) loaded from `source` and seen by `camera`.
    pub fn capture(
        source: &str,
        scene: &Scene,
        camera: &Camera,
        settings: &StillSettings,
    ) -> Recipe {
        let base = source_directory(source);
        let objects = scene
            .objects
            .iter()
            .map(|o| object_state(&o.material, &base))
            .collect();
        Recipe {
            program: crate::PROGRAM.into(),
            source: absolute_source(source),
            width: settings.size.0,
            height: settings.size.1,
            filter: settings.resolve.name().into(),
            quality: settings.quality,
            time: settings.time,
            mode: settings.mode.name().into(),
            camera: RecipeCamera::of(camera),
            shadows: scene.shadows,
            lights: scene.lights.iter().map(LightFile::of).collect(),
            files: file_hashes(scene, &base),
            objects,
        }
    }

    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("a recipe holds only TOML values")
    }

    /// Parses and checks a recipe; `origin` names where it came from in messages.
    pub fn parse(text: &str, origin: &str) -> Result<Recipe, Error> {
        let recipe: Recipe = toml::from_str(text).map_err(|e| {
            let offset = e.span().map_or(0, |s| s.start);
            let message = format!(
                "{}{}",
                crate::scene::user_words::in_user_words(e.message()),
                other_program_note(text)
            );
            Error::Diagnostic(crate::diagnostic::render(origin, text, offset, &message))
        })?;
        recipe
            .settings()
            .map(|_| recipe.clone())
            .map_err(|m| Error::Diagnostic(format!("{}: {m}", crate::diagnostic::sanitize(origin))))
    }

    /// The checked render settings.
    pub fn settings(&self) -> Result<StillSettings, String> {
        let side = |v: u32| (1..=MAX_SIDE).contains(&v);
        if !side(self.width) || !side(self.height) {
            return Err(format!(
                "size {}x{} is outside 1..={MAX_SIDE}",
                self.width, self.height
            ));
        }
        check_quality(&self.quality)?;
        if !(self.time.is_finite() && self.time.abs() <= MAX_TIME_SECONDS) {
            return Err(format!(
                "time {:e} is outside ±{MAX_TIME_SECONDS:e} seconds",
                self.time
            ));
        }
        let filter = ResolveFilter::parse(&self.filter)
            .ok_or_else(|| format!("unknown filter '{}'", self.filter))?;
        let mode = ShaderMode::ALL
            .iter()
            .copied()
            .find(|m| m.name() == self.mode)
            .ok_or_else(|| format!("unknown view mode '{}'", self.mode))?;
        Ok(StillSettings {
            size: (self.width, self.height),
            quality: self.quality,
            resolve: filter,
            time: self.time,
            mode,
        })
    }

    /// The directory the recorded scene named its files from: the scene file's, or the working
    /// directory for a built-in scene or a pattern file.
    pub fn source_directory(&self) -> PathBuf {
        source_directory(&self.source)
    }

    /// `source_directory` with links resolved, as recorded names are.
    fn resolved_source_directory(&self) -> PathBuf {
        let source = self.source_directory();
        std::fs::canonicalize(&source).unwrap_or(source)
    }

    /// Rebuilds the scene from its text (as recorded) with the recorded edits and camera, its
    /// relative file names read from `base` (the still's own directory, or `source_directory`).
    pub fn scene(&self, scene_text: &str, base: &Path) -> Result<Scene, Error> {
        let origin = if Path::new(&self.source).is_absolute() && !self.source.ends_with(".pat") {
            self.source.clone()
        } else {
            "scene".to_string()
        };
        let mut scene = crate::scene::parse_scene_in(scene_text, &origin, base)?;
        if scene.objects.len() != self.objects.len() {
            return Err(Error::Diagnostic(format!(
                "the recorded scene has {} objects but the recipe describes {}",
                scene.objects.len(),
                self.objects.len()
            )));
        }
        for (index, (object, state)) in scene.objects.iter_mut().zip(&self.objects).enumerate() {
            apply_state(object, &self.rebased(state, base), base)
                .map_err(|e| Error::Diagnostic(format!("recipe object {}: {}", index + 1, e)))?;
        }
        scene.camera = self.camera.to_camera()?;
        scene.lights = self.lights.iter().map(LightFile::to_light).collect();
        scene.shadows = self.shadows;
        Ok(scene)
    }

    /// Every pattern and image file rebuilding the scene from `scene_text` would read, relative
    /// names taken from `base`.
    pub fn files_read(&self, scene_text: &str, base: &Path) -> Result<Vec<PathBuf>, Error> {
        let mut files =
            crate::scene::dependencies::scene_text_dependencies(scene_text, "scene", base)?;
        let states: Vec<ObjectState> = self.objects.iter().map(|o| self.rebased(o, base)).collect();
        let bindings = states.iter().flat_map(|o| [&o.bump, &o.texture]).flatten();
        files.extend(bindings.flat_map(|b| crate::scene::dependencies::binding_files(b, base)));
        Ok(files)
    }

    /// `state` with the file names it recorded under the source directory moved under `base`.
    fn rebased(&self, state: &ObjectState, base: &Path) -> ObjectState {
        let source = self.resolved_source_directory();
        let move_name = |name: &Option<String>| {
            name.as_ref()
                .map(|name| match Path::new(name).strip_prefix(&source) {
                    Ok(within) => base.join(within).display().to_string(),
                    Err(_) => name.clone(),
                })
        };
        let move_binding = |binding: &Option<BindingFile>| {
            binding.as_ref().map(|b| BindingFile {
                pattern: move_name(&b.pattern),
                image: move_name(&b.image),
                normal_map: move_name(&b.normal_map),
                ..b.clone()
            })
        };
        ObjectState {
            bump: move_binding(&state.bump),
            texture: move_binding(&state.texture),
        }
    }

    /// Files whose content is no longer what the still was made from, as messages. Each recorded
    /// file under the source directory is looked for under `base` instead; with another `base`
    /// than the source directory, files recorded elsewhere are not read at all.
    pub fn changed_files(&self, base: &Path) -> Vec<String> {
        let source = self.resolved_source_directory();
        self.files
            .iter()
            .filter_map(|f| {
                let recorded = Path::new(&f.path);
                let path = match recorded.strip_prefix(&source) {
                    Ok(within) => base.join(within),
                    Err(_) if base == source.as_path() => recorded.to_path_buf(),
                    Err(_) => return None,
                };
                let shown = path.display();
                match hash_file(&path) {
                    Ok(hash) if hex(hash) == f.fnv1a64 => None,
                    Ok(_) => Some(format!("{shown} has changed since the still was made")),
                    Err(e) => Some(format!("{shown} cannot be read: {e}")),
                }
            })
            .map(|m| crate::diagnostic::sanitize(&m).into_owned())
            .collect()
    }
}

impl RecipeCamera {
    fn of(camera: &Camera) -> RecipeCamera {
        RecipeCamera {
            eye: camera.eye.to_array(),
            target: camera.target.to_array(),
            up: camera.up.to_array(),
            fov: camera.vfov_degrees,
            near: camera.near,
            far: camera.far,
        }
    }

    /// The camera checked exactly as a scene file's `[camera]` is.
    fn to_camera(&self) -> Result<Camera, Error> {
        let refuse = |m: String| Error::Diagnostic(format!("the recipe's camera: {m}"));
        let widen = |v: [f32; 3]| v.map(f64::from).to_vec();
        let file = CameraFile {
            eye: Point::try_from(self.eye.to_vec()).map_err(refuse)?,
            target: Point::try_from(self.target.to_vec()).map_err(refuse)?,
            up: Direction::try_from(widen(self.up)).map_err(refuse)?,
            fov: FieldOfView::try_from(f64::from(self.fov)).map_err(refuse)?,
            near: Some(Positive::try_from(f64::from(self.near)).map_err(refuse)?),
            far: Some(Positive::try_from(f64::from(self.far)).map_err(refuse)?),
        };
        file.to_camera().map_err(refuse)
    }
}

/// A recipe this version cannot read may simply be from another version: say so.
fn other_program_note(text: &str) -> String {
    let table: Option<toml::Table> = text.parse().ok();
    match table.as_ref().and_then(|t| t.get("program")?.as_str()) {
        Some(program) if program != crate::PROGRAM => {
            format!(
                " (the still was made by {program}, this is {})",
                crate::PROGRAM
            )
        }
        _ => String::new(),
    }
}

/// A built-in name stays as it is; a file becomes an absolute path.
fn absolute_source(source: &str) -> String {
    if crate::scene::preset(source).is_some() {
        return source.to_string();
    }
    std::fs::canonicalize(source).map_or_else(|_| source.to_string(), |p| p.display().to_string())
}

/// The directory a source's relative pattern and image names are resolved against.
pub fn source_directory(source: &str) -> PathBuf {
    let path = Path::new(source);
    if crate::scene::preset(source).is_some() || source.ends_with(".pat") {
        return PathBuf::from(".");
    }
    path.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

/// A pattern or image name as an absolute path when it names a file, else (built-in) as it is.
pub(super) fn absolute_name(name: &str, base: &Path) -> String {
    let path = base.join(name);
    if path.is_file() {
        std::fs::canonicalize(&path).map_or_else(|_| name.to_string(), |p| p.display().to_string())
    } else {
        name.to_string()
    }
}

pub(super) fn object_state(material: &Material, base: &Path) -> ObjectState {
    let bump = material.bump.as_ref().map(|bump| {
        let mut state = match &bump.source {
            BumpSource::Pattern(binding) => pattern_state(binding, base),
            BumpSource::Image(image) if image.chosen_live => live_image_state(&image.name, base),
            BumpSource::Image(_) | BumpSource::NormalMap(_) => BindingFile::default(),
        };
        state.strength = Some(Finite(bump.strength));
        state.invert = Some(bump.invert);
        state
    });
    let texture = match &material.texture {
        Some(Texturing::Pattern(binding)) => Some(pattern_state(binding, base)),
        Some(Texturing::Image(image)) if image.chosen_live => {
            Some(live_image_state(&image.name, base))
        }
        _ => None,
    };
    ObjectState { bump, texture }
}

/// An image the workbench's keys put on: its name alone, so it is placed by default again.
fn live_image_state(name: &str, base: &Path) -> BindingFile {
    BindingFile {
        image: Some(absolute_name(name, base)),
        ..BindingFile::default()
    }
}

fn pattern_state(binding: &PatternBinding, base: &Path) -> BindingFile {
    let p = &binding.placement;
    BindingFile {
        pattern: Some(absolute_name(&binding.name, base)),
        params: binding
            .pattern
            .params()
            .iter()
            .zip(&binding.params)
            .map(|(param, &value)| (param.name.clone(), crate::scene::shortest(value)))
            .collect(),
        scale: Some([Positive(p.scale.x), Positive(p.scale.y)]),
        rotate: Some(Finite(p.rotate_degrees)),
        offset: Some([Finite(p.offset.x), Finite(p.offset.y)]),
        ..BindingFile::default()
    }
}

fn apply_state(
    object: &mut crate::scene::Object,
    state: &ObjectState,
    base: &Path,
) -> Result<(), String> {
    let surface = &object.surface;
    let material = &mut object.material;
    // Patterns and images put on live are bound again here; the file's images keep the scene's
    // decoded copies.
    let mut images = ImageCache::new(crate::memory_budget::budget_bytes());
    if let Some(bump) = &state.bump {
        if bump.pattern.is_some() || bump.image.is_some() {
            let mut loaded = bump.load_bump(surface, base, &mut images)?;
            if let BumpSource::Image(image) = &mut loaded.source {
                image.chosen_live = true;
            }
            material.bump = Some(loaded);
        } else if let Some(live) = &mut material.bump {
            live.strength = bump.strength.map_or(live.strength, |s| s.0);
            live.invert = bump.invert.unwrap_or(live.invert);
        }
    }
    if let Some(texture) = &state.texture {
        let mut loaded = texture.load_texture(surface, base, &mut images)?;
        if let Texturing::Image(image) = &mut loaded {
            image.chosen_live = true;
        }
        material.texture = Some(loaded);
    }
    Ok(())
}

/// Every pattern and image file the live scene reads, hashed.
fn file_hashes(scene: &Scene, base: &Path) -> Vec<FileHash> {
    let mut names: Vec<String> = scene
        .objects
        .iter()
        .flat_map(|o| file_names(&o.material))
        .map(|name| absolute_name(&name, base))
        .filter(|name| Path::new(name).is_absolute())
        .collect();
    names.sort();
    names.dedup();
    names
        .into_iter()
        .filter_map(|path| {
            let hash = hash_file(Path::new(&path)).ok()?;
            Some(FileHash {
                path,
                fnv1a64: hex(hash),
            })
        })
        .collect()
}

fn file_names(material: &Material) -> Vec<String> {
    let bump = material.bump.as_ref().map(|b| match &b.source {
        BumpSource::Pattern(p) => p.name.clone(),
        BumpSource::Image(i) => i.name.clone(),
        BumpSource::NormalMap(n) => n.name.clone(),
    });
    let texture = material.texture.as_ref().map(|t| match t {
        Texturing::Pattern(p) => p.name.clone(),
        Texturing::Image(i) => i.name.clone(),
    });
    bump.into_iter().chain(texture).collect()
}

/// A recipe's text by its hash, `fnv1a64:` and 16 hex digits: stills with the same hash were
/// made from the same scene, settings and file contents.
pub fn recipe_hash(recipe_text: &str) -> String {
    format!("fnv1a64:{}", hex(fnv1a64(recipe_text.as_bytes())))
}

fn hex(value: u64) -> String {
    format!("{value:016x}")
}
