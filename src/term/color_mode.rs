//! Which colours the terminal can show, from the environment or an explicit `--colors` choice.

use std::str::FromStr;

/// The colour capability the encoders target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorMode {
    /// 24-bit colour.
    TrueColor,
    /// xterm's 256-colour palette (cube and grey ramp), dithered.
    Ansi256,
    /// The 16 ANSI colours, dithered.
    Ansi16,
    /// No colour at all: a dithered 1-bit picture in block glyphs, in the terminal's default colours.
    Monochrome,
}

/// The `--colors` argument: a fixed mode, or `auto` to detect it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ColorChoice {
    #[default]
    Auto,
    Fixed(ColorMode),
}

/// A `--colors` value that is none of the accepted names.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
#[error("unknown colour mode {0:?}: expected truecolor, 256, 16, none or auto")]
pub struct UnknownColorMode(pub String);

impl FromStr for ColorChoice {
    type Err = UnknownColorMode;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let mode = match s.to_ascii_lowercase().as_str() {
            "auto" => return Ok(ColorChoice::Auto),
            "truecolor" | "24bit" | "full" => ColorMode::TrueColor,
            "256" => ColorMode::Ansi256,
            "16" => ColorMode::Ansi16,
            "none" | "mono" | "2" => ColorMode::Monochrome,
            _ => return Err(UnknownColorMode(s.to_string())),
        };
        Ok(ColorChoice::Fixed(mode))
    }
}

impl ColorChoice {
    /// The mode to use: the fixed one, or the one the environment (read through `var`) advertises.
    /// An explicit choice wins over NO_COLOR, as no-color.org asks.
    pub fn resolve(self, var: impl Fn(&str) -> Option<String>) -> ColorMode {
        match self {
            ColorChoice::Fixed(mode) => mode,
            ColorChoice::Auto => detect_color_mode(var),
        }
    }
}

/// The colour mode the environment advertises; `var` looks a variable up (a map in tests,
/// `|k| std::env::var(k).ok()` for real).
///
/// NO_COLOR (non-empty) → monochrome; TERM=dumb → monochrome; COLORTERM=truecolor|24bit → truecolor;
/// TERM containing `256color` (xterm-256color, tmux-256color, screen-256color) → 256; anything else → 16.
pub fn detect_color_mode(var: impl Fn(&str) -> Option<String>) -> ColorMode {
    let set = |name: &str| var(name).filter(|v| !v.is_empty());
    let term = set("TERM").unwrap_or_default();
    if set("NO_COLOR").is_some() || term == "dumb" {
        return ColorMode::Monochrome;
    }
    let colorterm = set("COLORTERM").unwrap_or_default().to_ascii_lowercase();
    if colorterm == "truecolor" || colorterm == "24bit" {
        ColorMode::TrueColor
    } else if term.contains("256color") {
        ColorMode::Ansi256
    } else {
        ColorMode::Ansi16
    }
}

/// [`detect_color_mode`] on this process's environment.
pub fn detect_from_process_env() -> ColorMode {
    detect_color_mode(|name| std::env::var(name).ok())
}
