//! What one frame cost.

/// What one frame cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Triangles of the tessellated scene.
    pub triangles: usize,
    /// Screen triangles after culling and clipping that reached scan conversion.
    pub rasterized_triangles: usize,
    /// Pixels shaded (each visible pixel exactly once).
    pub fragments: usize,
    /// Fragments drawn flat because a pattern gave no finite value there (division by zero…).
    pub flattened: usize,
}
