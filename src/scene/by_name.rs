//! Where a scene comes from: a built-in name, a scene file, a pattern file or an image shown on
//! the sphere-on-plane scene, or a model file (with a pattern file, `model.obj+my.pat`) on its stage;
//! and the scene's text, as a file would hold it.

use super::{BumpSource, MAX_SCENE_FILE_BYTES, PatternBinding, Scene, Texturing};
use crate::Error;
use crate::pattern::{OutputKind, Pattern};
use std::path::Path;

/// The scene a pattern file is shown on: both a plane and a sphere, the pattern on each.
const PATTERN_STAGE: &str = "sphere-on-plane-dimples";

/// Loads the scene `name` names: a `.pat` file goes on the stage scene, anything else is a
/// built-in scene or a scene file.
pub fn load_source(name: &str) -> Result<Scene, Error> {
    if let Some(model) = super::ModelSource::parse(name) {
        let file = model.scene_file()?;
        return file
            .to_scene(name, Path::new("."))
            .map_err(|message| Error::Diagnostic(crate::diagnostic::sanitize(&message).into()));
    }
    if crate::texture::is_image_name(name) && !name.ends_with(".toml") {
        return image_on_stage(name);
    }
    if !name.ends_with(".pat") {
        return super::resolve(name);
    }
    let pattern = Pattern::load(Path::new(name)).map_err(|e| Error::Diagnostic(e.to_string()))?;
    let mut scene = super::resolve(PATTERN_STAGE)?;
    let file_name = Path::new(name).file_name().map(|n| n.to_string_lossy());
    scene.name = file_name.map_or_else(|| name.to_string(), |n| n.into_owned());
    put_pattern_on(&mut scene, name, &pattern);
    Ok(scene)
}

/// The image file `name` on the stage scene, as every object's texture and bump.
fn image_on_stage(name: &str) -> Result<Scene, Error> {
    let mut scene = super::resolve(PATTERN_STAGE)?;
    let file_name = Path::new(name).file_name().map(|n| n.to_string_lossy());
    scene.name = file_name.map_or_else(|| name.to_string(), |n| n.into_owned());
    let place = |e: String| Error::Diagnostic(crate::diagnostic::sanitize(&e).into());
    super::material_choice::put_texture(&mut scene, name).map_err(place)?;
    super::material_choice::put_bump(&mut scene, name).map_err(place)?;
    Ok(scene)
}

/// Puts `pattern` (called `name`, its parameters at their defaults) on every object of `scene`:
/// a colour pattern as its texture, a bump pattern as the source of its bump where it has one.
pub fn put_pattern_on(scene: &mut Scene, name: &str, pattern: &Pattern) {
    for object in &mut scene.objects {
        let binding = PatternBinding {
            name: name.to_string(),
            params: pattern.params().iter().map(|p| p.default).collect(),
            pattern: pattern.clone(),
            placement: Default::default(),
        };
        match (pattern.output(), &mut object.material.bump) {
            (OutputKind::Color, _) => object.material.texture = Some(Texturing::Pattern(binding)),
            (_, Some(bump)) => bump.source = BumpSource::Pattern(binding),
            (_, None) => {}
        }
    }
}

/// The text of the scene `name` names, as a scene file: the file itself, or a built-in scene
/// (the stage scene for a pattern file) printed as one.
pub fn source_text(name: &str) -> Result<String, Error> {
    if let Some(model) = super::ModelSource::parse(name) {
        return Ok(model.scene_file()?.to_toml());
    }
    let preset = if name.ends_with(".pat") || crate::texture::is_image_name(name) {
        PATTERN_STAGE
    } else {
        name
    };
    match super::preset_file(preset) {
        Some(file) => Ok(file.to_toml()),
        None => crate::read_text_limited(Path::new(name), MAX_SCENE_FILE_BYTES),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pattern_file_is_shown_on_every_bumped_object_and_errors_name_the_place() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let dir = dir.path();
        let good = dir.join("bumps.pat");
        std::fs::write(
            &good,
            "param period = 20 in 2..100\nheight = sin(u / period)\n",
        )
        .unwrap();
        let scene = load_source(good.to_str().unwrap()).unwrap();
        let bumped = scene
            .objects
            .iter()
            .filter_map(|o| o.material.bump.as_ref());
        assert!(bumped.count() > 0);
        let bad = dir.join("bad.pat");
        std::fs::write(&bad, "height = u + )\n").unwrap();
        let message = load_source(bad.to_str().unwrap()).unwrap_err().to_string();
        assert!(message.contains("bad.pat:1:"), "{message}");
    }
}
