//! The files a scene file reads, so that a watcher knows what to look at.

use super::binding_file::BindingFile;
use super::file::{MAX_SCENE_FILE_BYTES, SceneFile, SurfaceFile};
use crate::Error;
use std::path::{Path, PathBuf};

/// The scene file itself, then every model, pattern and image file its objects name (built-ins are not
/// files), each once, in order of appearance. Paths are as the loader opens them: relative names
/// joined to the scene file's directory. Only the TOML is read, so this works even when a
/// pattern or image it names is missing or broken.
pub fn scene_file_dependencies(path: &Path) -> Result<Vec<PathBuf>, Error> {
    let text = crate::read_text_limited(path, MAX_SCENE_FILE_BYTES)?;
    let base = path.parent().unwrap_or(Path::new("."));
    let mut files = vec![path.to_path_buf()];
    for file in scene_text_dependencies(&text, &path.display().to_string(), base)? {
        if !files.contains(&file) {
            files.push(file);
        }
    }
    Ok(files)
}

/// The pattern and image files scene text names, joined to `base`; `origin` names the text in
/// messages.
pub fn scene_text_dependencies(
    text: &str,
    origin: &str,
    base: &Path,
) -> Result<Vec<PathBuf>, Error> {
    let file: SceneFile = toml::from_str(text).map_err(|e| {
        let offset = e.span().map_or(0, |s| s.start);
        let message = super::user_words::in_user_words(e.message());
        Error::Diagnostic(crate::diagnostic::render(origin, text, offset, &message))
    })?;
    let models = file.objects.iter().filter_map(|o| match &o.surface {
        SurfaceFile::Mesh { file, .. } if crate::model::builtin_model(file).is_none() => {
            Some(base.join(file))
        }
        _ => None,
    });
    let bindings = file
        .objects
        .iter()
        .flat_map(|o| [&o.texture, &o.bump])
        .flatten()
        .flat_map(|b| binding_files(b, base));
    Ok(models.chain(bindings).collect())
}

pub(crate) fn binding_files(binding: &BindingFile, base: &Path) -> Vec<PathBuf> {
    let pattern = binding
        .pattern
        .as_deref()
        .filter(|name| crate::pattern::builtin(name).is_none());
    let image = binding
        .image
        .as_deref()
        .filter(|name| !is_builtin_image(name));
    let normal_map = binding
        .normal_map
        .as_deref()
        .filter(|name| !is_builtin_image(name));
    pattern
        .into_iter()
        .chain(image)
        .chain(normal_map)
        .map(|name| base.join(name))
        .collect()
}

fn is_builtin_image(name: &str) -> bool {
    crate::texture::BUILTIN_IMAGES
        .iter()
        .any(|(n, _)| *n == name)
}
