//! Named trades of speed for accuracy: tessellation density and samples per picture pixel.

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Quality {
    /// Coarse meshes, one sample per pixel: for slow machines and huge terminals.
    Draft,
    #[default]
    Normal,
    /// Fine meshes and 2×2 samples per pixel: smooth silhouettes and bump detail.
    Fine,
}

impl Quality {
    pub fn name(self) -> &'static str {
        match self {
            Quality::Draft => "draft",
            Quality::Normal => "normal",
            Quality::Fine => "fine",
        }
    }

    pub fn next(self) -> Quality {
        match self {
            Quality::Draft => Quality::Normal,
            Quality::Normal => Quality::Fine,
            Quality::Fine => Quality::Draft,
        }
    }

    /// Cells per half turn of curved surfaces.
    pub fn tessellation_density(self) -> u32 {
        match self {
            Quality::Draft => 16,
            Quality::Normal => 64,
            Quality::Fine => 128,
        }
    }

    /// Samples per picture pixel along each axis.
    pub fn supersampling(self) -> usize {
        match self {
            Quality::Draft | Quality::Normal => 1,
            Quality::Fine => 2,
        }
    }
}
