//! Where a workbench scene comes from: a built-in name, a scene file, or a pattern file shown on
//! the sphere-on-plane scene; files come with a hot reloader watching them.

use crate::Error;
use crate::pattern::{OutputKind, Pattern};
use crate::scene::{BumpSource, PatternBinding, Scene, Texturing};
use crate::watch::{FileSetSource, Reloader, SceneFileSource};
use std::path::{Path, PathBuf};

/// The scene a pattern file is shown on: both a plane and a sphere, the pattern on each.
const PATTERN_STAGE: &str = "sphere-on-plane-dimples";

/// Loads the scene `name` names: a `.pat` file goes on the stage scene, anything else is a
/// built-in scene or a scene file.
pub fn load_source(name: &str) -> Result<Scene, Error> {
    if !name.ends_with(".pat") {
        return crate::scene::resolve(name);
    }
    let pattern = Pattern::load(Path::new(name)).map_err(|e| Error::Diagnostic(e.to_string()))?;
    let mut scene = crate::scene::resolve(PATTERN_STAGE)?;
    let file_name = Path::new(name).file_name().map(|n| n.to_string_lossy());
    scene.name = file_name.map_or_else(|| name.to_string(), |n| n.into_owned());
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
    Ok(scene)
}

/// Loads the scene `name` names and, for files, starts watching them (the scene file and every
/// pattern and image it names, or the pattern file). If watching cannot start, the scene still
/// opens, without hot reload. With `watch` off nothing is watched.
pub fn open_source(name: &str, watch: bool) -> Result<(Scene, Option<Reloader>), Error> {
    let started = if !watch {
        return Ok((load_source(name)?, None));
    } else if name.ends_with(".pat") {
        let owned = name.to_string();
        let source = FileSetSource::new(vec![PathBuf::from(name)], move || load_source(&owned));
        Reloader::start(source)
    } else if crate::scene::preset(name).is_none() {
        Reloader::start(SceneFileSource::new(name))
    } else {
        return Ok((load_source(name)?, None));
    };
    match started {
        Ok((reloader, first)) => {
            let scene = first.map_err(|e| Error::Diagnostic(e.message))?;
            Ok((scene, Some(reloader)))
        }
        Err(_) => Ok((load_source(name)?, None)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pattern_file_is_shown_on_every_bumped_object_and_errors_name_the_place() {
        let dir = std::env::temp_dir().join(format!("bumpwork-source-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
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
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
