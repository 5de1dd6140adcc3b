//! What a frame's program shows and at which moment: set when the program is built.

use super::ShaderMode;

/// The shading stage's output and the scene time, for one program.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Showing {
    pub mode: ShaderMode,
    /// Seconds, for animated patterns and scrolling images.
    pub time: f64,
}

impl Showing {
    /// The lit picture at `time`.
    pub fn at(time: f64) -> Showing {
        Showing {
            mode: ShaderMode::Shaded,
            time,
        }
    }
}
