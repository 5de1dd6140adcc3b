//! A scene opened by name with its files watched: a built-in name, a scene file, a pattern file
//! shown on the sphere-on-plane scene, or a model file (and a pattern file on it); files come
//! with a hot reloader watching them (the workbench and `render --watch`).

use super::{FileSetSource, Reloader, SceneFileSource};
use crate::Error;
use crate::scene::{Scene, load_source};
use std::path::PathBuf;

/// Loads the scene `name` names and, for files, starts watching them (the scene file and every
/// pattern and image it names, or the pattern file). If watching cannot start, the scene still
/// opens, without hot reload. With `watch` off nothing is watched.
pub fn open_watched(name: &str, watch: bool) -> Result<(Scene, Option<Reloader>), Error> {
    if let Some(error) = crate::scene::unknown_scene(name) {
        return Err(error);
    }
    let started = if !watch {
        return Ok((load_source(name)?, None));
    } else if let Some(model) = crate::scene::ModelSource::parse(name) {
        let owned = name.to_string();
        let source = FileSetSource::new(model.files(), move || load_source(&owned));
        Reloader::start(source)
    } else if name.ends_with(".pat") || crate::texture::is_image_name(name) {
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
