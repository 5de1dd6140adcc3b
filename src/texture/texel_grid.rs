//! A plain 2-D grid of texels, row-major, row 0 at the TOP of the image.

/// Row-major texels; `texels[y * width + x]`, `y = 0` is the image's top row.
#[derive(Debug, Clone, PartialEq)]
pub struct TexelGrid<T> {
    width: u32,
    height: u32,
    texels: Vec<T>,
}

impl<T: Copy> TexelGrid<T> {
    /// `None` if a side is zero or `texels` does not hold exactly `width * height` texels.
    pub fn new(width: u32, height: u32, texels: Vec<T>) -> Option<Self> {
        let expected = (width as usize).checked_mul(height as usize)?;
        (width > 0 && height > 0 && texels.len() == expected).then_some(Self {
            width,
            height,
            texels,
        })
    }

    /// Fills the raster from `texel(x, y)`; panics only on a zero-sized request.
    pub fn from_fn(width: u32, height: u32, mut texel: impl FnMut(u32, u32) -> T) -> Self {
        assert!(width > 0 && height > 0, "a raster needs at least one texel");
        let texels = (0..height)
            .flat_map(|y| (0..width).map(move |x| (x, y)))
            .map(|(x, y)| texel(x, y))
            .collect();
        Self {
            width,
            height,
            texels,
        }
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    pub fn height(&self) -> u32 {
        self.height
    }

    pub fn texels(&self) -> &[T] {
        &self.texels
    }

    /// The texel at column `x`, row `y` (callers keep indices in range).
    #[inline(always)]
    pub fn at(&self, x: u32, y: u32) -> T {
        self.texels[y as usize * self.width as usize + x as usize]
    }

    /// Row `y` (callers keep it in range).
    #[inline(always)]
    pub fn row(&self, y: u32) -> &[T] {
        let start = y as usize * self.width as usize;
        &self.texels[start..start + self.width as usize]
    }

    pub fn map<U: Copy>(&self, f: impl Fn(T) -> U) -> TexelGrid<U> {
        TexelGrid {
            width: self.width,
            height: self.height,
            texels: self.texels.iter().map(|&t| f(t)).collect(),
        }
    }
}
