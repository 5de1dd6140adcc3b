/// What the shading stage shows: the lit picture, or one of the quantities behind it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ViewMode {
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

impl ViewMode {
    pub const ALL: [ViewMode; 5] = [
        ViewMode::Shaded,
        ViewMode::Height,
        ViewMode::Normals,
        ViewMode::Uv,
        ViewMode::Depth,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ViewMode::Shaded => "shaded",
            ViewMode::Height => "height",
            ViewMode::Normals => "normals",
            ViewMode::Uv => "uv",
            ViewMode::Depth => "depth",
        }
    }

    pub fn next(self) -> ViewMode {
        let i = ViewMode::ALL.iter().position(|&m| m == self).unwrap_or(0);
        ViewMode::ALL[(i + 1) % ViewMode::ALL.len()]
    }
}
