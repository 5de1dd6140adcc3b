//! The images one scene binds, each decoded once: bindings of the same file, or of files with
//! the same bytes, share one decoded copy, and all of them together stay within the memory
//! budget (each is checked from its header against what is left before it is decoded).

use super::encoding::Encoding;
use super::error::TextureError;
use super::load::{Limits, decode_image, read_file};
use super::shipped_images::builtin_bytes;
use super::{HeightMap, Texture};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Decoded images by their file's bytes, for the length of one scene's loading.
pub struct ImageCache {
    /// Each path read once: the bytes it held.
    files: HashMap<PathBuf, Arc<[u8]>>,
    textures: HashMap<Arc<[u8]>, Arc<Texture>>,
    height_maps: HashMap<Arc<[u8]>, Arc<HeightMap>>,
    /// Bytes of the budget not yet taken by decoded images.
    left: u64,
}

impl ImageCache {
    /// A cache whose decoded images may take at most `budget` bytes in all.
    pub fn new(budget: u64) -> ImageCache {
        ImageCache {
            files: HashMap::new(),
            textures: HashMap::new(),
            height_maps: HashMap::new(),
            left: budget,
        }
    }

    /// A colour texture (sRGB-decoded): a built-in name, or a file path relative to `base`.
    pub fn texture(
        &mut self,
        name_or_path: &str,
        base: &Path,
    ) -> Result<Arc<Texture>, TextureError> {
        let (bytes, path) = self.bytes(name_or_path, base)?;
        if let Some(texture) = self.textures.get(&bytes) {
            return Ok(texture.clone());
        }
        let image = decode_image(&bytes, &path, &Limits::within(self.left), Encoding::Srgb)?;
        let texture = Arc::new(Texture::from_image(image));
        self.left = self.left.saturating_sub(texture.bytes());
        self.textures.insert(bytes, texture.clone());
        Ok(texture)
    }

    /// A height map (grey values as stored, not sRGB-decoded): a built-in name, or a file path
    /// relative to `base`.
    pub fn height_map(
        &mut self,
        name_or_path: &str,
        base: &Path,
    ) -> Result<Arc<HeightMap>, TextureError> {
        let (bytes, path) = self.bytes(name_or_path, base)?;
        if let Some(map) = self.height_maps.get(&bytes) {
            return Ok(map.clone());
        }
        let image = decode_image(&bytes, &path, &Limits::within(self.left), Encoding::Linear)?;
        let map = Arc::new(HeightMap::from_texels(&image.texels));
        self.left = self.left.saturating_sub(map.bytes());
        self.height_maps.insert(bytes, map.clone());
        Ok(map)
    }

    /// The bytes `name_or_path` names, and the path messages call it by. Files whose bytes
    /// equal ones already read share their key, so equal contents decode once.
    fn bytes(
        &mut self,
        name_or_path: &str,
        base: &Path,
    ) -> Result<(Arc<[u8]>, PathBuf), TextureError> {
        // A built-in is keyed by its bare name, which no joined path equals.
        let builtin = builtin_bytes(name_or_path);
        let path = match builtin {
            Some(_) => PathBuf::from(name_or_path),
            None => base.join(name_or_path),
        };
        if let Some(bytes) = self.files.get(&path) {
            return Ok((bytes.clone(), path));
        }
        let read = match builtin {
            Some(bytes) => bytes.into(),
            None => read_file(&path, &Limits::within(self.left))
                .map_err(|reason| TextureError::new(&path, reason))?
                .into(),
        };
        let bytes = self.shared(read);
        self.files.insert(path.clone(), bytes.clone());
        Ok((bytes, path))
    }

    /// The key already holding these bytes, if any, else `bytes` itself.
    fn shared(&self, bytes: Arc<[u8]>) -> Arc<[u8]> {
        let known = self.files.values();
        let decoded = self.textures.keys().chain(self.height_maps.keys());
        known
            .chain(decoded)
            .find(|key| **key == bytes)
            .cloned()
            .unwrap_or(bytes)
    }
}
