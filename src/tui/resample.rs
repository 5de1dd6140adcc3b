//! Linear-light framebuffer → sRGB picture of another size, by area averaging: the renderer works
//! in square pixels, while quadrant and sextant cells have tall sub-pixels, and fine quality
//! supersamples.

use crate::area_average::area_weights;
use crate::raster::{Framebuffer, encode_srgb8};
use glam::Vec3;

/// Linear colours as 8-bit sRGB.
pub fn to_srgb8(linear: &[Vec3]) -> Vec<[u8; 3]> {
    let mut rgb = vec![[0; 3]; linear.len()];
    encode_srgb8(
        bytemuck::cast_slice(linear),
        bytemuck::cast_slice_mut(&mut rgb),
    );
    rgb
}

/// The framebuffer's colours averaged over the area of each of `width` × `height` pixels, in
/// linear light.
pub fn resample_linear(framebuffer: &Framebuffer, width: usize, height: usize) -> Vec<Vec3> {
    let (src_w, src_h) = (framebuffer.width as usize, framebuffer.height as usize);
    if (src_w, src_h) == (width, height) {
        return framebuffer.color().to_vec();
    }
    let columns = area_weights(src_w, width);
    let rows = area_weights(src_h, height);
    let mut horizontal = vec![Vec3::ZERO; width * src_h];
    for y in 0..src_h {
        let source = &framebuffer.color()[y * src_w..(y + 1) * src_w];
        for (x, weights) in columns.iter().enumerate() {
            horizontal[y * width + x] = weights.iter().map(|&(i, w)| source[i] * w).sum();
        }
    }
    let mut out = Vec::with_capacity(width * height);
    for weights in &rows {
        for x in 0..width {
            out.push(
                weights
                    .iter()
                    .map(|&(j, w)| horizontal[j * width + x] * w)
                    .sum(),
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averaging_two_rows_mixes_in_linear_light() {
        let mut fb = Framebuffer::new(1, 2, Vec3::ZERO);
        fb.color_mut()[0] = Vec3::ONE;
        let out = to_srgb8(&resample_linear(&fb, 1, 1));
        // Half of linear white is sRGB 188, not 128.
        assert_eq!(out, vec![[188, 188, 188]]);
    }
}
