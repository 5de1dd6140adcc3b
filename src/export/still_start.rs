//! Where a still starts from: a scene by name (built-in, scene file, pattern, model), or a still
//! made before, whose recipe names its scene, files and settings. A still's files are read only
//! from its own directory unless the user trusts it to name its own: a crafted still must not
//! make bumpwork read, and quote in its errors, any file the user can read.

use super::metadata::{RECIPE, SCENE, read_png_text, text_of};
use crate::Error;
use crate::diagnostic::sanitize;
use crate::quality::Quality;
use crate::scene::{KnobSetting, Scene};
use crate::shade::ShaderMode;
use crate::still::{Recipe, ResolveFilter, StillSettings};
use std::path::{Path, PathBuf};

/// A scene with its source and text, and the settings a still of it has before any option.
#[derive(Clone, Debug)]
pub struct StillStart {
    /// The scene's name or path, as recipes record it.
    pub source: String,
    pub scene_text: String,
    pub scene: Scene,
    pub settings: StillSettings,
    /// The scene file's `[quality]` settings, for a `--quality` preset to take (none from a
    /// still: its recipe's quality has them already).
    pub quality_table: Vec<KnobSetting>,
    /// What the user should hear before the render: files changed since the still was made, a
    /// still made by another version.
    pub warnings: Vec<String>,
}

impl StillStart {
    /// The scene `name` names, at 800 × 600, shaded, at the scene's time, with the default
    /// quality and the scene file's `[quality]` settings over it.
    pub fn from_source(name: &str) -> Result<StillStart, Error> {
        StillStart::of_scene(name, crate::scene::load_source(name)?)
    }

    /// As [`StillStart::from_source`], for `scene` already loaded from `name` (a reload).
    pub fn of_scene(name: &str, scene: Scene) -> Result<StillStart, Error> {
        let settings = StillSettings {
            size: (800, 600),
            quality: Quality::default()
                .with_settings(&scene.quality)
                .map_err(Error::Diagnostic)?,
            resolve: ResolveFilter::default(),
            time: scene.time,
            mode: ShaderMode::Shaded,
        };
        Ok(StillStart {
            source: name.to_string(),
            scene_text: crate::scene::source_text(name)?,
            quality_table: scene.quality.clone(),
            settings,
            scene,
            warnings: Vec::new(),
        })
    }

    /// The scene and settings `still`'s recipe records. Its files are looked for in the still's
    /// directory and must lie there (links followed), unless `read_outside` trusts the recipe's
    /// own paths.
    pub fn from_still(still: &Path, read_outside: bool) -> Result<StillStart, Error> {
        let texts = read_png_text(still)?;
        let origin = format!("{} ({RECIPE})", still.display());
        let recipe = Recipe::parse(text_of(&texts, RECIPE, still)?, &origin)?;
        let scene_text = text_of(&texts, SCENE, still)?.to_string();
        let base = match read_outside {
            true => recipe.source_directory(),
            false => {
                let base = still_directory(still)?;
                confine_to_directory(&recipe.files_read(&scene_text, &base)?, still, &base)?;
                base
            }
        };
        let mut warnings: Vec<String> = (recipe.changed_files(&base).into_iter())
            .map(|change| format!("{change}; the picture may differ"))
            .collect();
        if recipe.program != crate::PROGRAM {
            warnings.push(format!(
                "the still was made by {}, this is {}",
                sanitize(&recipe.program),
                crate::PROGRAM
            ));
        }
        let settings = (recipe.settings())
            .map_err(|m| Error::Diagnostic(format!("{}: {m}", sanitize(&origin))))?;
        Ok(StillStart {
            scene: recipe.scene(&scene_text, &base)?,
            source: recipe.source,
            scene_text,
            settings,
            quality_table: Vec::new(),
            warnings,
        })
    }
}

/// The still's directory, links resolved.
fn still_directory(still: &Path) -> Result<PathBuf, Error> {
    let parent = still.parent().filter(|p| !p.as_os_str().is_empty());
    std::fs::canonicalize(parent.unwrap_or(Path::new(".")))
        .map_err(|e| Error::read(still, crate::bounded_read::io_words(&e)))
}

/// Refuses a file outside the still's `directory` (links followed, `directory` itself resolved).
fn confine_to_directory(files: &[PathBuf], still: &Path, directory: &Path) -> Result<(), Error> {
    for file in files {
        let resolved = std::fs::canonicalize(file).unwrap_or_else(|_| file.clone());
        if !resolved.starts_with(directory) {
            return Err(Error::InvalidArgument(format!(
                "the still {} names {}, outside its directory {}; add --read-outside to read it",
                sanitize(&still.display().to_string()),
                sanitize(&file.display().to_string()),
                sanitize(&directory.display().to_string()),
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn directory() -> tempfile::TempDir {
        tempfile::tempdir().expect("a temporary directory")
    }

    #[test]
    fn files_in_the_still_directory_or_below_it_are_allowed() {
        let dir = directory();
        let base = std::fs::canonicalize(dir.path()).unwrap();
        std::fs::create_dir(base.join("sub")).unwrap();
        std::fs::write(base.join("sub/d.pat"), "").unwrap();
        let files = [base.join("a.pat"), base.join("sub/d.pat")];
        assert!(confine_to_directory(&files, &base.join("s.png"), &base).is_ok());
    }

    #[test]
    fn a_file_outside_or_reached_by_dot_dot_or_a_link_is_refused_and_named() {
        let dir = directory();
        let base = std::fs::canonicalize(dir.path()).unwrap().join("stills");
        std::fs::create_dir(&base).unwrap();
        let outside = base.parent().unwrap().join("secret.pat");
        std::fs::write(&outside, "").unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink(&outside, base.join("link.pat")).unwrap();
        let still = base.join("s.png");
        for file in [
            outside.clone(),
            base.join("../secret.pat"),
            #[cfg(unix)]
            base.join("link.pat"),
        ] {
            let error = confine_to_directory(std::slice::from_ref(&file), &still, &base)
                .expect_err(&format!("{} is outside", file.display()))
                .to_string();
            assert!(error.contains("outside its directory"), "{error}");
            assert!(error.contains("--read-outside"), "{error}");
        }
    }

    #[test]
    fn a_still_with_no_directory_part_is_in_the_current_one() {
        let here = std::fs::canonicalize(".").unwrap();
        assert_eq!(still_directory(Path::new("s.png")).unwrap(), here);
    }
}
