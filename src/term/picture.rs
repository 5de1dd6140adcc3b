//! The input of the encoders: an sRGB 8-bit picture, row-major.

/// A borrowed `width × height` sRGB picture (the caller converts the linear framebuffer to sRGB).
#[derive(Clone, Copy, Debug)]
pub struct Picture<'a> {
    pixels: &'a [[u8; 3]],
    width: usize,
    height: usize,
}

/// The pixel slice does not hold `width × height` pixels.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
#[error("picture of {width}×{height} needs {} pixels, got {len}", width * height)]
pub struct PictureSizeError {
    pub width: usize,
    pub height: usize,
    pub len: usize,
}

impl<'a> Picture<'a> {
    pub fn new(
        pixels: &'a [[u8; 3]],
        width: usize,
        height: usize,
    ) -> Result<Self, PictureSizeError> {
        if width.checked_mul(height) != Some(pixels.len()) {
            return Err(PictureSizeError {
                width,
                height,
                len: pixels.len(),
            });
        }
        Ok(Picture {
            pixels,
            width,
            height,
        })
    }

    pub fn width(&self) -> usize {
        self.width
    }

    pub fn height(&self) -> usize {
        self.height
    }

    /// The pixel at (x, y), or `None` outside the picture (the padding of a partial last cell).
    pub fn pixel(&self, x: usize, y: usize) -> Option<[u8; 3]> {
        (x < self.width && y < self.height).then(|| self.pixels[y * self.width + x])
    }
}
