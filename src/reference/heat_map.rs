//! The error view's heat map: per-pixel difference to the reference, silhouettes apart.

use super::metrics::pixel_errors;
use crate::raster::Framebuffer;
use glam::Vec3;

/// Where coverage differs (a silhouette error), drawn apart from the colour-error ramp.
const SILHOUETTE_COLOR: Vec3 = Vec3::new(0.0, 0.6, 1.0);

/// The per-pixel difference of `frame` to `reference` as a heat map: black where equal, then red,
/// yellow and white as the error grows to `full_scale` 8-bit sRGB steps (and beyond, white);
/// blue where one frame covers a pixel the other does not. Depth is the frame's.
pub fn error_heat_map(
    frame: &Framebuffer,
    reference: &Framebuffer,
    full_scale: f32,
) -> Framebuffer {
    let scale = if full_scale > 0.0 && full_scale.is_finite() {
        full_scale
    } else {
        255.0
    };
    let color = pixel_errors(frame, reference)
        .into_iter()
        .enumerate()
        .map(|(i, error)| {
            if frame.depth()[i].is_finite() != reference.depth()[i].is_finite() {
                SILHOUETTE_COLOR
            } else {
                heat(error / scale)
            }
        })
        .collect();
    Framebuffer::from_parts(frame.width, frame.height, color, frame.depth().to_vec())
}

/// Black → red → yellow → white over [0, 1], in linear light; NaN shows as the worst.
fn heat(x: f32) -> Vec3 {
    let x = if x.is_nan() { 1.0 } else { x.clamp(0.0, 1.0) } * 3.0;
    Vec3::new(
        x.min(1.0),
        (x - 1.0).clamp(0.0, 1.0),
        (x - 2.0).clamp(0.0, 1.0),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ramp_runs_from_black_to_white() {
        assert_eq!(heat(0.0), Vec3::ZERO);
        assert_eq!(heat(1.0), Vec3::ONE);
        assert_eq!(heat(f32::NAN), Vec3::ONE);
        assert!(heat(0.5).x == 1.0 && heat(0.5).z == 0.0);
    }
}
