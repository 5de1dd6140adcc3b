//! Why an image could not be loaded, always naming the file.

use std::fmt;
use std::path::Path;

/// A load failure: the file (printable, control characters escaped) and the reason.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{file}: {reason}")]
pub struct TextureError {
    pub file: PrintableName,
    pub reason: Reason,
}

impl TextureError {
    pub fn new(path: &Path, reason: Reason) -> Self {
        Self {
            file: PrintableName::from_path(path),
            reason,
        }
    }
}

/// What went wrong, one variant per cause a user can act on.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Reason {
    #[error("file not found")]
    Missing,
    #[error("cannot read the file: {0}")]
    Unreadable(String),
    #[error("unsupported image format ({0}); expected PNG, JPEG, PPM/PGM, BMP or TGA")]
    Unsupported(String),
    #[error("corrupt image data: {0}")]
    Corrupt(String),
    #[error("truncated image: the data ends before the image does")]
    Truncated,
    #[error("image has zero size ({width}×{height})")]
    ZeroSize { width: u32, height: u32 },
    #[error("image too large: {detail}")]
    Oversized { detail: String },
}

/// A file name safe to print on a terminal: control characters are shown escaped
/// (`\n`, `\e`), so a hostile name cannot move the cursor or fake a message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PrintableName(String);

impl PrintableName {
    pub fn from_path(path: &Path) -> Self {
        Self(crate::term::sanitize(&path.to_string_lossy()).into_owned())
    }

    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl fmt::Display for PrintableName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_in_names_are_escaped() {
        let err = TextureError::new(Path::new("evil\n\u{1b}[2J.png"), Reason::Missing);
        let text = err.to_string();
        assert_eq!(text, "evil\\n\\e[2J.png: file not found");
        assert!(!text.chars().any(char::is_control));
    }
}
