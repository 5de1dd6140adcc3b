//! `--bump NAME|FILE` and `--texture NAME|FILE`: a shipped pattern or image, a pattern file or an
//! image file, put on every object of a scene in place of what it has.

use super::{BindingFile, Bump, BumpSource, Finite, PatternBinding, Scene, Texturing};
use crate::Error;
use crate::pattern::{OutputKind, Pattern};
use crate::texture::{BUILTIN_IMAGES, ImageCache};
use std::path::Path;

/// How much an image's grey (0..1) raises a surface when it is put on as a bump: as the shipped
/// image scenes.
pub const IMAGE_BUMP_STRENGTH: f32 = 30.0;

/// The bump and texture chosen on the command line, if any.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MaterialChoice {
    pub bump: Option<String>,
    pub texture: Option<String>,
}

impl MaterialChoice {
    /// Puts the chosen bump and texture on every object of `scene`; names are read from the
    /// working directory.
    pub fn apply(&self, scene: &mut Scene) -> Result<(), Error> {
        if let Some(name) = &self.bump {
            put_bump(scene, name).map_err(|e| refused("--bump", name, &e))?;
        }
        if let Some(name) = &self.texture {
            put_texture(scene, name).map_err(|e| refused("--texture", name, &e))?;
        }
        Ok(())
    }
}

fn refused(option: &str, name: &str, why: &str) -> Error {
    let name = crate::diagnostic::shown_input(name);
    Error::InvalidArgument(format!("{option} {name}: {why}"))
}

/// Whether `name` is an image: a shipped one or a file by its ending.
fn is_image(name: &str) -> bool {
    BUILTIN_IMAGES.iter().any(|(n, _)| *n == name) || crate::texture::is_image_name(name)
}

/// A shipped pattern or a pattern file; anything else is said to be neither.
fn pattern(name: &str) -> Result<Pattern, String> {
    let known = crate::pattern::builtin(name).is_some() || Path::new(name).exists();
    if !known {
        let patterns: Vec<&str> = crate::pattern::BUILTINS.iter().map(|(n, _)| *n).collect();
        let images: Vec<&str> = BUILTIN_IMAGES.iter().map(|(n, _)| *n).collect();
        return Err(format!(
            "expected a shipped pattern ({}), a shipped image ({}) or a file",
            patterns.join(", "),
            images.join(", ")
        ));
    }
    super::load_pattern(name, Path::new("."))
}

/// `name` (a shipped pattern or image, or a file) as the bump of every object of `scene`.
pub(super) fn put_bump(scene: &mut Scene, name: &str) -> Result<(), String> {
    let mut cache = ImageCache::new(crate::memory_budget::budget_bytes());
    if is_image(name) {
        let binding = BindingFile {
            strength: Some(Finite(IMAGE_BUMP_STRENGTH)),
            ..BindingFile::image(name)
        };
        for object in &mut scene.objects {
            let bump = binding.load_bump(&object.surface, Path::new("."), &mut cache)?;
            object.material.bump = Some(recorded_bump(bump));
        }
        return Ok(());
    }
    let pattern = pattern(name)?;
    if pattern.output() == OutputKind::Color {
        return Err("a colour pattern is a texture (--texture takes it)".into());
    }
    for object in &mut scene.objects {
        let strength = match object.material.bump.as_ref() {
            Some(Bump {
                source: BumpSource::Pattern(_),
                strength,
                ..
            }) => *strength,
            _ => 1.0,
        };
        object.material.bump = Some(Bump {
            source: BumpSource::Pattern(binding(name, &pattern)),
            strength,
            invert: false,
        });
    }
    Ok(())
}

/// `name` (a shipped colour pattern or image, or a file) as the texture of every object.
pub(super) fn put_texture(scene: &mut Scene, name: &str) -> Result<(), String> {
    let mut cache = ImageCache::new(crate::memory_budget::budget_bytes());
    if is_image(name) {
        let binding = BindingFile::image(name);
        for object in &mut scene.objects {
            let texture = binding.load_texture(&object.surface, Path::new("."), &mut cache)?;
            object.material.texture = Some(recorded_texture(texture));
        }
        return Ok(());
    }
    let pattern = pattern(name)?;
    if pattern.output() != OutputKind::Color {
        return Err("a height or slope pattern is a bump (--bump takes it)".into());
    }
    for object in &mut scene.objects {
        object.material.texture = Some(Texturing::Pattern(binding(name, &pattern)));
    }
    Ok(())
}

/// An image bump marked as put on by name, so a still's recipe records it.
fn recorded_bump(mut bump: Bump) -> Bump {
    if let BumpSource::Image(image) = &mut bump.source {
        image.chosen_live = true;
    }
    bump
}

/// An image texture marked as put on by name, so a still's recipe records it.
fn recorded_texture(mut texture: Texturing) -> Texturing {
    if let Texturing::Image(image) = &mut texture {
        image.chosen_live = true;
    }
    texture
}

/// `pattern`, called `name`, at its default parameters and placement.
fn binding(name: &str, pattern: &Pattern) -> PatternBinding {
    PatternBinding {
        name: name.to_string(),
        params: pattern.params().iter().map(|p| p.default).collect(),
        pattern: pattern.clone(),
        placement: Default::default(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plane() -> Scene {
        crate::scene::preset("plane-dimples").unwrap()
    }

    #[test]
    fn a_shipped_pattern_or_image_goes_on_every_object_and_kinds_are_checked() {
        let mut scene = crate::scene::preset("sphere-on-plane-dimples").unwrap();
        let choice = MaterialChoice {
            bump: Some("stucco".into()),
            texture: Some("chelsea".into()),
        };
        choice.apply(&mut scene).unwrap();
        for object in &scene.objects {
            let bump = object.material.bump.as_ref().unwrap();
            assert!(matches!(&bump.source, BumpSource::Pattern(b) if b.name == "stucco"));
            assert!(
                matches!(&object.material.texture, Some(Texturing::Image(i)) if i.name == "chelsea")
            );
        }
        let image_bump = MaterialChoice {
            bump: Some("gravel".into()),
            ..Default::default()
        };
        let mut scene = plane();
        image_bump.apply(&mut scene).unwrap();
        let bump = scene.objects[0].material.bump.as_ref().unwrap();
        assert!(matches!(bump.source, BumpSource::Image(_)));
        assert_eq!(bump.strength, IMAGE_BUMP_STRENGTH);
    }

    #[test]
    fn a_wrong_kind_or_unknown_name_is_one_line_naming_the_option() {
        let cases = [
            (
                Some("no-such"),
                None,
                "--bump no-such: expected a shipped pattern",
            ),
            (
                None,
                Some("stucco"),
                "--texture stucco: a height or slope pattern is a bump",
            ),
            (
                Some("/nonexistent/x.png"),
                None,
                "--bump /nonexistent/x.png:",
            ),
        ];
        for (bump, texture, says) in cases {
            let choice = MaterialChoice {
                bump: bump.map(String::from),
                texture: texture.map(String::from),
            };
            let e = choice.apply(&mut plane()).unwrap_err().to_string();
            assert!(e.starts_with(says) && !e.contains('\n'), "{e}");
        }
    }
}
