//! A colour texture: linear texels and their mip chain.

use std::path::Path;

use glam::Vec2;

use super::encoding::Encoding;
use super::error::TextureError;
use super::load::{ImageInfo, Limits, LoadedImage, load_image};
use super::mip::MipChain;
use super::sampler::{Footprint, Sampler};
use super::texel::Texel;
use super::texel_grid::TexelGrid;

/// A colour image ready for sampling.
#[derive(Debug, Clone)]
pub struct Texture {
    chain: MipChain<Texel>,
    info: Option<ImageInfo>,
}

impl Texture {
    /// Loads a colour image (sRGB-decoded) and builds its mip chain.
    pub fn load(path: impl AsRef<Path>, limits: &Limits) -> Result<Self, TextureError> {
        let image = load_image(path.as_ref(), limits, Encoding::Srgb)?;
        Ok(Self {
            chain: MipChain::build(image.texels),
            info: Some(image.info),
        })
    }

    /// A decoded image's texture, keeping the file's description.
    pub fn from_image(image: LoadedImage) -> Self {
        Self {
            chain: MipChain::build(image.texels),
            info: Some(image.info),
        }
    }

    /// A texture from texels already in linear light.
    pub fn from_raster(texels: TexelGrid<Texel>) -> Self {
        Self {
            chain: MipChain::build(texels),
            info: None,
        }
    }

    /// The file's description, if it came from a file.
    pub fn info(&self) -> Option<&ImageInfo> {
        self.info.as_ref()
    }

    pub fn width(&self) -> u32 {
        self.chain.base().width()
    }

    /// The memory the texels and their mip chain take.
    pub fn bytes(&self) -> u64 {
        self.chain.bytes()
    }

    pub fn height(&self) -> u32 {
        self.chain.base().height()
    }

    pub fn mip_chain(&self) -> &MipChain<Texel> {
        &self.chain
    }

    /// The filtered colour at `st` (`[0,1)²` spans the image, t = 0 at the top row).
    #[inline]
    pub fn sample(&self, sampler: &Sampler, st: Vec2, footprint: Footprint) -> Texel {
        sampler.sample(&self.chain, st, footprint)
    }

    /// Samples every point of a batch (see `Sampler::sample_many`).
    pub fn sample_many(
        &self,
        sampler: &Sampler,
        st: &[Vec2],
        footprints: &[Footprint],
        out: &mut [Texel],
    ) {
        sampler.sample_many(&self.chain, st, footprints, out);
    }

    /// The mip level `footprint` selects, in `[0, levels − 1]`, never NaN.
    pub fn level_of_detail(&self, footprint: Footprint) -> f32 {
        footprint.level_of_detail(&self.chain)
    }
}
