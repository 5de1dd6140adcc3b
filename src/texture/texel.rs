//! The texel every colour texture holds: linear RGB, premultiplied alpha, f32.

use glam::Vec4;

/// One texel: linear-light RGB with premultiplied alpha, `f32` per channel.
///
/// Why this type: shading and filtering add light, so texels are stored already
/// sRGB-decoded (linear). 8-bit sRGB needs ~12 bits once linear to keep its darks, so
/// `u8` is out; `u16` would fit but costs a conversion per tap in the hot path, while
/// `f32` in a `Vec4` makes a bilinear blend three SIMD lerps. Alpha is premultiplied
/// so averaging (mip levels, bilinear) never bleeds the colour of transparent texels
/// into their neighbours. The price is 16 bytes per texel, counted by `Limits`.
pub type Texel = Vec4;
