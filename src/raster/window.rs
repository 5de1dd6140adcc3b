//! Which part of a larger image a frame covers, and where in each pixel it samples: lets a big
//! still be rendered in bands (bounded memory) and supersampled by shifted passes, with every
//! band and pass seeing exactly the projection of the whole image.

use super::setup::Viewport;
use glam::{Mat4, Vec2, Vec4};

/// A `viewport`-sized window at (`x0`, `y0`) of a `full` image, sampled at `offset` pixels from
/// each pixel's centre. The projection places the window; the rasteriser moves the samples by
/// the offset (`SampleShift`), so shifted passes share their set-up triangles. f32 suffices:
/// positions stay under 2^24.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageWindow {
    pub full: Viewport,
    pub x0: u32,
    pub y0: u32,
    pub offset: Vec2,
}

impl ImageWindow {
    /// The whole of `full`, sampled at pixel centres.
    pub fn whole(full: Viewport) -> ImageWindow {
        ImageWindow {
            full,
            x0: 0,
            y0: 0,
            offset: Vec2::ZERO,
        }
    }

    /// Maps the full image's clip space to the window's: window pixel (i, j) has its centre at
    /// the full image's (x0 + i + ½, y0 + j + ½). The identity for the whole image.
    pub fn clip_transform(&self, window: Viewport) -> Mat4 {
        let (w, h) = (window.width.max(1) as f32, window.height.max(1) as f32);
        let (full_w, full_h) = (self.full.width as f32, self.full.height as f32);
        let (x, y) = (self.x0 as f32, self.y0 as f32);
        let scale = Vec2::new(full_w / w, full_h / h);
        let translate = Vec2::new((full_w - 2.0 * x) / w - 1.0, 1.0 - full_h / h + 2.0 * y / h);
        Mat4::from_cols(
            Vec4::new(scale.x, 0.0, 0.0, 0.0),
            Vec4::new(0.0, scale.y, 0.0, 0.0),
            Vec4::Z,
            Vec4::new(translate.x, translate.y, 0.0, 1.0),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pixel_of(clip: Vec4, viewport: Viewport) -> Vec2 {
        let ndc = clip / clip.w;
        Vec2::new(
            (ndc.x * 0.5 + 0.5) * viewport.width as f32,
            (0.5 - ndc.y * 0.5) * viewport.height as f32,
        )
    }

    #[test]
    fn the_whole_image_at_centres_is_the_identity() {
        let full = Viewport {
            width: 640,
            height: 360,
        };
        let m = ImageWindow::whole(full).clip_transform(full);
        assert!(m.abs_diff_eq(Mat4::IDENTITY, 1e-6), "{m}");
    }

    #[test]
    fn a_window_pixel_sees_its_point_of_the_full_image() {
        let full = Viewport {
            width: 1000,
            height: 600,
        };
        let band = Viewport {
            width: 300,
            height: 64,
        };
        let window = ImageWindow {
            full,
            x0: 500,
            y0: 128,
            offset: Vec2::new(0.25, -0.375),
        };
        let m = window.clip_transform(band);
        // A clip-space point that lands on full-image pixel position (x, y), with w = 3.
        let (x, y) = (612.75_f32, 150.125_f32);
        let ndc = Vec2::new(2.0 * x / 1000.0 - 1.0, 1.0 - 2.0 * y / 600.0);
        let clip = Vec4::new(ndc.x * 3.0, ndc.y * 3.0, 1.0, 3.0);
        let seen = pixel_of(m * clip, band);
        // The offset is the rasteriser's to apply, not the projection's.
        let expected = Vec2::new(x - 500.0, y - 128.0);
        assert!(
            (seen - expected).abs().max_element() < 1e-3,
            "{seen} vs {expected}"
        );
    }
}
