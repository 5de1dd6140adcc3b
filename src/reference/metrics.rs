//! Error of a frame against the reference frame of the same scene and camera.
//!
//! Colour errors are measured on what is displayed: 8-bit sRGB, in steps of 1/255. Normal errors
//! come from two frames rendered with `ShaderMode::Normals` (n·0.5 + 0.5 in linear light, decoded
//! exactly). Coverage is a finite depth.

use crate::raster::{Framebuffer, linear_to_srgb8};
use glam::Vec3;

/// Every figure the bench reports for one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameError {
    /// Peak signal-to-noise ratio in dB over all pixels and channels; +∞ for identical frames.
    pub psnr_db: f64,
    /// The largest difference of any channel of any pixel, in 8-bit sRGB steps (0–255).
    pub max_pixel_error: f32,
    /// Angle between the shaded normals, over pixels covered in both frames, in degrees.
    pub mean_normal_angle_degrees: f64,
    pub max_normal_angle_degrees: f64,
    /// Pixels covered in one frame and not the other.
    pub silhouette_mismatch: usize,
}

/// All figures at once: `shaded` frames for colour and coverage, `normals` frames (rendered with
/// `ShaderMode::Normals`) for the normal angles.
pub fn frame_error(
    shaded: &Framebuffer,
    shaded_reference: &Framebuffer,
    normals: &Framebuffer,
    normals_reference: &Framebuffer,
) -> FrameError {
    let angles = normal_angle_error(normals, normals_reference);
    FrameError {
        psnr_db: psnr(shaded, shaded_reference),
        max_pixel_error: max_pixel_error(shaded, shaded_reference),
        mean_normal_angle_degrees: angles.mean_degrees,
        max_normal_angle_degrees: angles.max_degrees,
        silhouette_mismatch: silhouette_mismatch(shaded, shaded_reference),
    }
}

/// Per pixel, the largest channel difference in 8-bit sRGB steps.
pub fn pixel_errors(frame: &Framebuffer, reference: &Framebuffer) -> Vec<f32> {
    assert_same_size(frame, reference);
    frame
        .color()
        .iter()
        .zip(reference.color())
        .map(|(a, b)| {
            let (a, b) = (display(*a), display(*b));
            (a - b).abs().max_element()
        })
        .collect()
}

pub fn psnr(frame: &Framebuffer, reference: &Framebuffer) -> f64 {
    assert_same_size(frame, reference);
    let squared: f64 = frame
        .color()
        .iter()
        .zip(reference.color())
        .map(|(a, b)| (display(*a) - display(*b)).length_squared() as f64)
        .sum();
    let samples = (frame.color().len() * 3).max(1) as f64;
    let mse = squared / samples;
    10.0 * (255.0 * 255.0 / mse).log10()
}

pub fn max_pixel_error(frame: &Framebuffer, reference: &Framebuffer) -> f32 {
    pixel_errors(frame, reference)
        .into_iter()
        .fold(0.0, f32::max)
}

/// Mean and largest angle between normals, in degrees.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NormalAngles {
    pub mean_degrees: f64,
    pub max_degrees: f64,
    /// Pixels covered in both frames, over which the angles are taken.
    pub pixels: usize,
}

pub fn normal_angle_error(normals: &Framebuffer, reference: &Framebuffer) -> NormalAngles {
    assert_same_size(normals, reference);
    let angles: Vec<f64> = (0..normals.color().len())
        .filter(|&i| normals.depth()[i].is_finite() && reference.depth()[i].is_finite())
        .map(|i| {
            angle_degrees(
                decode_normal(normals.color()[i]),
                decode_normal(reference.color()[i]),
            )
        })
        .collect();
    NormalAngles {
        // A fold from +0: an empty sum of f64 is −0.
        mean_degrees: angles.iter().fold(0.0, |sum, a| sum + a) / angles.len().max(1) as f64,
        max_degrees: angles.iter().copied().fold(0.0, f64::max),
        pixels: angles.len(),
    }
}

pub fn silhouette_mismatch(frame: &Framebuffer, reference: &Framebuffer) -> usize {
    assert_same_size(frame, reference);
    frame
        .depth()
        .iter()
        .zip(reference.depth())
        .filter(|(a, b)| a.is_finite() != b.is_finite())
        .count()
}

/// The inverse of the normals view's n·0.5 + 0.5.
pub fn decode_normal(color: Vec3) -> Vec3 {
    color * 2.0 - Vec3::ONE
}

/// The angle between two directions, accurate near 0 (atan2 of the cross and dot products).
fn angle_degrees(a: Vec3, b: Vec3) -> f64 {
    let (a, b) = (a.as_dvec3(), b.as_dvec3());
    let angle = a.cross(b).length().atan2(a.dot(b)).to_degrees();
    if angle.is_finite() { angle } else { 180.0 }
}

fn display(linear: Vec3) -> Vec3 {
    Vec3::from_array(linear.to_array().map(|c| linear_to_srgb8(c) as f32))
}

fn assert_same_size(a: &Framebuffer, b: &Framebuffer) {
    assert!(
        a.width == b.width && a.height == b.height,
        "frames of different sizes: {}x{} and {}x{}",
        a.width,
        a.height,
        b.width,
        b.height
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(colors: &[Vec3], depths: &[f32]) -> Framebuffer {
        Framebuffer::from_parts(colors.len() as u32, 1, colors.to_vec(), depths.to_vec())
    }

    #[test]
    fn identical_frames_have_no_error() {
        let a = frame(&[Vec3::splat(0.3), Vec3::ONE], &[1.0, f32::INFINITY]);
        let e = frame_error(&a, &a, &a, &a);
        assert_eq!(e.psnr_db, f64::INFINITY);
        assert_eq!(e.max_pixel_error, 0.0);
        assert_eq!(e.silhouette_mismatch, 0);
        assert_eq!(e.max_normal_angle_degrees, 0.0);
    }

    #[test]
    fn one_full_scale_channel_in_two_pixels() {
        let a = frame(&[Vec3::ZERO, Vec3::ZERO], &[1.0, 1.0]);
        let b = frame(
            &[Vec3::new(1.0, 0.0, 0.0), Vec3::ZERO],
            &[1.0, f32::INFINITY],
        );
        // MSE = 255² / 6 samples: PSNR = 10·log10(6).
        assert!((psnr(&a, &b) - 10.0 * 6f64.log10()).abs() < 1e-9);
        assert_eq!(max_pixel_error(&a, &b), 255.0);
        assert_eq!(silhouette_mismatch(&a, &b), 1);
    }

    #[test]
    fn normal_angles_decode_the_normals_view() {
        let up = Vec3::Y * 0.5 + Vec3::splat(0.5);
        let right = Vec3::X * 0.5 + Vec3::splat(0.5);
        let a = frame(&[up, up, up], &[1.0, 1.0, f32::INFINITY]);
        let b = frame(&[up, right, right], &[1.0, 1.0, 1.0]);
        let angles = normal_angle_error(&a, &b);
        assert_eq!(angles.pixels, 2);
        assert!((angles.max_degrees - 90.0).abs() < 1e-4);
        assert!((angles.mean_degrees - 45.0).abs() < 1e-4);
    }
}
