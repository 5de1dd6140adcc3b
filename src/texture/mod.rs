//! Image textures: loading (with limits), linear texels, mip chains, samplers,
//! wrap modes, images as bump maps, and the mappings from surfaces to texture space.
//!
//! Conventions: texture coordinates `(s, t)` in `[0, 1)` span the image, `s` across
//! from the left edge, `t` down from the TOP row (as images are stored).
//!
//! The path of a textured fragment:
//! 1. [`ImageCache`] for a scene's bindings (each file decoded once), [`Texture::load`] /
//!    [`HeightMap::load`] for one file, or [`check_image`] to validate only, bounded by
//!    [`Limits`]; failures are a [`TextureError`] naming the file.
//! 2. A [`Mapping`] turns a [`SurfacePoint`] into [`Mapped`] `st` and ∂(s,t)/∂(u,v).
//! 3. [`Mapped::footprint`] chains that with the pixel's ∂(u,v)/∂x, ∂(u,v)/∂y.
//! 4. [`Texture::sample`] with a [`Sampler`] (filter + per-axis [`Wrap`]) gives a
//!    linear premultiplied [`Texel`]; [`HeightMap::sample_gradient`] gives the height
//!    and ∂h/∂s, ∂h/∂t, and [`HeightSample::surface_gradient`] Blinn's (B_u, B_v).

#[cfg(test)]
mod batch_test_points;
mod colour;
mod encoding;
mod error;
mod height;
mod height_batch;
mod image_cache;
mod load;
mod mapping;
mod mip;
mod normal_map;
mod plain_pnm;
mod sample_batch;
mod sampler;
mod shipped_images;
mod texel;
mod texel_grid;
mod wrap;

pub use colour::Texture;
pub use encoding::{Encoding, linear_to_srgb, srgb_to_linear};
pub use error::{PrintableName, Reason, TextureError};
pub use height::{HeightMap, HeightSample};
pub use image_cache::ImageCache;
pub use load::{
    IMAGE_EXTENSIONS, ImageInfo, Limits, LoadedImage, check_image, decode_image, is_image_name,
    load_image,
};
pub use mapping::{
    Cylindrical, Mapped, Mapping, Planar, PlanarLayout, Scroll, Spherical, SurfacePoint, SurfaceUv,
    TextureMapping, TriangleMap,
};
pub use mip::{Averageable, MipChain};
pub use normal_map::{NormalConvention, NormalMap};
pub use sampler::{Filter, Footprint, Sampler};
pub use shipped_images::BUILTIN_IMAGES;
pub use texel::Texel;
pub use texel_grid::TexelGrid;
pub use wrap::Wrap;
