//! How (u,v) is interpolated across a triangle in screen space.

/// How (u,v) is interpolated across a triangle in screen space.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Interpolation {
    /// Exact for the triangle's plane: u/w, v/w and 1/w are affine in screen space.
    #[default]
    PerspectiveCorrect,
    /// Linear in screen space, as early hardware did: cheaper, wrong under perspective.
    Affine,
}
