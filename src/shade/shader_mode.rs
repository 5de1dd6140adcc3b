//! What the shader outputs: the lit picture, or the height, normals, (u,v) or depth behind it.

/// What the shading stage shows: the lit picture, or one of the quantities behind it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, strum::VariantArray, strum::IntoStaticStr)]
#[strum(serialize_all = "lowercase")]
pub enum ShaderMode {
    #[default]
    Shaded,
    /// The bump height B as grey (mid-grey is 0; slope-only patterns have no height and show flat).
    Height,
    /// The (bumped) unit normal, world axes mapped to RGB.
    Normals,
    /// The surface parameters, repeating every 30 units (the seed's dimple period).
    Uv,
    /// Distance from the eye, near is bright.
    Depth,
}

impl ShaderMode {
    pub const ALL: &'static [ShaderMode] = <ShaderMode as strum::VariantArray>::VARIANTS;

    pub fn name(self) -> &'static str {
        self.into()
    }

    pub fn next(self) -> ShaderMode {
        let i = ShaderMode::ALL.iter().position(|&m| m == self).unwrap_or(0);
        ShaderMode::ALL[(i + 1) % ShaderMode::ALL.len()]
    }
}
