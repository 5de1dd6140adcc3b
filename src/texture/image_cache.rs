//! The images one scene binds, each decoded once: bindings of the same file, or of files with
//! the same bytes, share one decoded copy, and all of them together stay within the memory
//! budget (each is checked from its header against what is left before it is decoded).

use super::encoding::Encoding;
use super::error::TextureError;
use super::load::{Limits, LoadedImage, decode_image, read_file};
use super::shipped_images::builtin_bytes;
use super::{HeightMap, NormalMap, Texture};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Decoded images by their file's bytes, for the length of one scene's loading.
pub struct ImageCache {
    /// Each path read once: the bytes it held.
    files: HashMap<PathBuf, Arc<[u8]>>,
    textures: HashMap<Arc<[u8]>, Arc<Texture>>,
    height_maps: HashMap<Arc<[u8]>, Arc<HeightMap>>,
    normal_maps: HashMap<Arc<[u8]>, Arc<NormalMap>>,
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
            normal_maps: HashMap::new(),
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
        let decoded = Decoding {
            bytes,
            path: &path,
            encoding: Encoding::Srgb,
            left: &mut self.left,
        };
        decoded.shared(&mut self.textures, Texture::from_image, Texture::bytes)
    }

    /// A height map (grey values as stored, not sRGB-decoded): a built-in name, or a file path
    /// relative to `base`.
    pub fn height_map(
        &mut self,
        name_or_path: &str,
        base: &Path,
    ) -> Result<Arc<HeightMap>, TextureError> {
        let (bytes, path) = self.bytes(name_or_path, base)?;
        let decoded = Decoding {
            bytes,
            path: &path,
            encoding: Encoding::Linear,
            left: &mut self.left,
        };
        let from_image = |image: LoadedImage| HeightMap::from_texels(&image.texels);
        decoded.shared(&mut self.height_maps, from_image, HeightMap::bytes)
    }

    /// A tangent-space normal map (RGB as stored, not sRGB-decoded): a file path relative to
    /// `base` (or a built-in image's name).
    pub fn normal_map(
        &mut self,
        name_or_path: &str,
        base: &Path,
    ) -> Result<Arc<NormalMap>, TextureError> {
        let (bytes, path) = self.bytes(name_or_path, base)?;
        let decoded = Decoding {
            bytes,
            path: &path,
            encoding: Encoding::Linear,
            left: &mut self.left,
        };
        decoded.shared(
            &mut self.normal_maps,
            NormalMap::from_image,
            NormalMap::bytes,
        )
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
        let decoded = (self.textures.keys())
            .chain(self.height_maps.keys())
            .chain(self.normal_maps.keys());
        known
            .chain(decoded)
            .find(|key| **key == bytes)
            .cloned()
            .unwrap_or(bytes)
    }
}

/// One file's bytes on their way to a decoded image of one kind.
struct Decoding<'a> {
    bytes: Arc<[u8]>,
    path: &'a Path,
    encoding: Encoding,
    /// The budget not yet taken, lowered by what is decoded.
    left: &'a mut u64,
}

impl Decoding<'_> {
    /// The image these bytes already decoded to in `decoded`, else decoded now (checked from its
    /// header against the budget left), made into a `T` and kept there.
    fn shared<T>(
        self,
        decoded: &mut HashMap<Arc<[u8]>, Arc<T>>,
        make: impl FnOnce(LoadedImage) -> T,
        size: impl Fn(&T) -> u64,
    ) -> Result<Arc<T>, TextureError> {
        if let Some(image) = decoded.get(&self.bytes) {
            return Ok(image.clone());
        }
        let limits = Limits::within(*self.left);
        let image = Arc::new(make(decode_image(
            &self.bytes,
            self.path,
            &limits,
            self.encoding,
        )?));
        *self.left = self.left.saturating_sub(size(&image));
        decoded.insert(self.bytes, image.clone());
        Ok(image)
    }
}
