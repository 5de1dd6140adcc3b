//! The images the pattern and texture keys offer besides patterns: the shipped ones and every
//! image the scene uses, decoded once each, put on an object with the default placement (over
//! the whole surface, the `uv` mapping).

use crate::scene::{BindingFile, BumpSource, ImageHeight, ImageTexture, Scene, Texturing};
use crate::surface::Surface;
use crate::texture::{BUILTIN_IMAGES, ImageCache};
use std::path::PathBuf;

pub struct ImageShelf {
    names: Vec<String>,
    /// Where the scene's relative image names are read from.
    base: PathBuf,
    cache: ImageCache,
}

impl ImageShelf {
    /// The shipped images, then the scene's own (named as its file names them, relative to
    /// `base`), each once.
    pub fn of(scene: &Scene, base: PathBuf) -> ImageShelf {
        let mut names: Vec<String> = BUILTIN_IMAGES.iter().map(|(n, _)| n.to_string()).collect();
        for material in scene.objects.iter().map(|o| &o.material) {
            if let Some(Texturing::Image(image)) = &material.texture {
                names.push(image.name.clone());
            }
            if let Some(BumpSource::Image(image)) = material.bump.as_ref().map(|b| &b.source) {
                names.push(image.name.clone());
            }
        }
        let mut seen = std::collections::HashSet::new();
        names.retain(|n| seen.insert(n.clone()));
        let budget = crate::memory_budget::budget_bytes().saturating_sub(scene.image_bytes());
        ImageShelf {
            names,
            base,
            cache: ImageCache::new(budget),
        }
    }

    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Image `name` as a colour texture on `surface`.
    pub fn texture(&mut self, name: &str, surface: &Surface) -> Result<ImageTexture, String> {
        match BindingFile::image(name).load_texture(surface, &self.base, &mut self.cache)? {
            Texturing::Image(image) => Ok(ImageTexture {
                chosen_live: true,
                ..image
            }),
            Texturing::Pattern(_) => unreachable!("an image binding loads an image"),
        }
    }

    /// Image `name` as a height map on `surface` (grey, lighter is higher).
    pub fn height(&mut self, name: &str, surface: &Surface) -> Result<ImageHeight, String> {
        let bump = BindingFile::image(name).load_bump(surface, &self.base, &mut self.cache)?;
        match bump.source {
            BumpSource::Image(image) => Ok(ImageHeight {
                chosen_live: true,
                ..image
            }),
            BumpSource::Pattern(_) | BumpSource::NormalMap(_) => {
                unreachable!("an image binding loads an image")
            }
        }
    }
}
