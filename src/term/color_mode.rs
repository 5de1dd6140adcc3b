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
        self.resolve_with_reason(var, || None).mode
    }

    /// As `resolve`, with why: what the user or the environment said. Inside tmux (`TMUX` is
    /// set), `tmux_features` is asked what tmux knows of the terminal outside it (see
    /// `detect_colors_in_tmux`).
    pub fn resolve_with_reason(
        self,
        var: impl Fn(&str) -> Option<String>,
        tmux_features: impl FnOnce() -> Option<String>,
    ) -> DetectedColors {
        match self {
            ColorChoice::Fixed(mode) => DetectedColors {
                mode,
                reason: "--colors".into(),
            },
            ColorChoice::Auto => detect_colors_in_tmux(var, tmux_features),
        }
    }
}

/// A colour mode and what it was chosen from, for the user to see (`TERM=xterm-kitty`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DetectedColors {
    pub mode: ColorMode,
    pub reason: String,
}

/// The colour mode the environment advertises; `var` looks a variable up (a map in tests,
/// `|k| std::env::var(k).ok()` for real).
pub fn detect_color_mode(var: impl Fn(&str) -> Option<String>) -> ColorMode {
    detect_colors(var).mode
}

/// Terminals that show 24-bit colour, by the `TERM` they set (SSH forwards `TERM` but not
/// `COLORTERM`, so over SSH this is often the only sign).
const DIRECT_COLOUR_TERMS: &[&str] = &[
    "xterm-kitty",
    "alacritty",
    "alacritty-direct",
    "foot",
    "foot-extra",
    "foot-direct",
    "wezterm",
    "xterm-ghostty",
    "ghostty",
    "contour",
    "contour-latest",
    "iterm2",
    "mintty",
    "rio",
];

/// Terminals by `TERM_PROGRAM` (set by the terminal; forwarded by common SSH set-ups).
const TERM_PROGRAMS: &[(&str, ColorMode)] = &[
    ("iTerm.app", ColorMode::TrueColor),
    ("WezTerm", ColorMode::TrueColor),
    ("vscode", ColorMode::TrueColor),
    ("ghostty", ColorMode::TrueColor),
    ("Hyper", ColorMode::TrueColor),
    ("Tabby", ColorMode::TrueColor),
    ("rio", ColorMode::TrueColor),
    ("Apple_Terminal", ColorMode::Ansi256),
];

/// Variables only 24-bit terminals set.
const DIRECT_COLOUR_VARIABLES: &[&str] = &[
    "KITTY_WINDOW_ID",
    "WT_SESSION",
    "KONSOLE_VERSION",
    "ALACRITTY_WINDOW_ID",
    "WEZTERM_PANE",
    "GHOSTTY_RESOURCES_DIR",
];

/// In order: NO_COLOR (non-empty) or TERM=dumb → monochrome; COLORTERM=truecolor|24bit → 24-bit;
/// a `TERM` of a known 24-bit terminal or ending in `-direct`/`-truecolor` → 24-bit;
/// `TERM_PROGRAM` (iTerm.app, WezTerm, vscode… 24-bit; Apple_Terminal 256); LC_TERMINAL=iTerm2,
/// VTE_VERSION ≥ 3600, or a variable only 24-bit terminals set (KITTY_WINDOW_ID, WT_SESSION,
/// KONSOLE_VERSION…) → 24-bit; a terminfo entry for `TERM` that sets `RGB` or `Tc` → 24-bit; a
/// `TERM` with `256color` → 256; anything else → 16.
pub fn detect_colors(var: impl Fn(&str) -> Option<String>) -> DetectedColors {
    let set = |name: &str| var(name).filter(|v| !v.is_empty());
    let found = |mode, reason: String| DetectedColors { mode, reason };
    let term = set("TERM").unwrap_or_default();
    if set("NO_COLOR").is_some() {
        return found(ColorMode::Monochrome, "NO_COLOR is set".into());
    }
    if term == "dumb" {
        return found(ColorMode::Monochrome, "TERM=dumb".into());
    }
    if let Some(colorterm) = set("COLORTERM")
        .filter(|c| matches!(c.to_ascii_lowercase().as_str(), "truecolor" | "24bit"))
    {
        return found(ColorMode::TrueColor, format!("COLORTERM={colorterm}"));
    }
    let shown_term = || format!("TERM={}", super::sanitize(&term));
    if DIRECT_COLOUR_TERMS.contains(&term.as_str())
        || term.ends_with("-direct")
        || term.ends_with("-truecolor")
        || term.ends_with("-24bit")
    {
        return found(ColorMode::TrueColor, shown_term());
    }
    if let Some(program) = set("TERM_PROGRAM")
        && let Some(&(name, mode)) = TERM_PROGRAMS.iter().find(|(name, _)| *name == program)
    {
        return found(mode, format!("TERM_PROGRAM={name}"));
    }
    if set("LC_TERMINAL").as_deref() == Some("iTerm2") {
        return found(ColorMode::TrueColor, "LC_TERMINAL=iTerm2".into());
    }
    if let Some(version) = set("VTE_VERSION").and_then(|v| v.parse::<u32>().ok())
        && version >= 3600
    {
        return found(ColorMode::TrueColor, format!("VTE_VERSION={version}"));
    }
    if let Some(name) = DIRECT_COLOUR_VARIABLES
        .iter()
        .find(|name| set(name).is_some())
    {
        return found(ColorMode::TrueColor, format!("{name} is set"));
    }
    if let Some(flag) = super::terminfo::direct_colour_flag(&term, &var) {
        return found(
            ColorMode::TrueColor,
            format!("the terminfo entry of {} sets {flag}", shown_term()),
        );
    }
    if term.contains("256color") {
        return found(ColorMode::Ansi256, shown_term());
    }
    let reason = match term.is_empty() {
        true => "no TERM".to_string(),
        false => format!("{}, nothing more known", shown_term()),
    };
    found(ColorMode::Ansi16, reason)
}

/// As `detect_colors`, but inside tmux (`TMUX` set) the colours are those of the terminal outside
/// it, as tmux knows them: `tmux_features` gives `#{client_termfeatures}` (`RGB,title,…`), and
/// tmux passes 24-bit colour on only where the list has `RGB`; else it turns every colour into
/// one of its 256 and, for a terminal with fewer, into the nearest of those itself.
/// Where tmux says nothing (no client, tmux before 3.2), the environment decides as outside tmux
/// (where `TERM` is tmux's own, usually `tmux-256color`). NO_COLOR and TERM=dumb win still.
pub fn detect_colors_in_tmux(
    var: impl Fn(&str) -> Option<String>,
    tmux_features: impl FnOnce() -> Option<String>,
) -> DetectedColors {
    let plain = detect_colors(&var);
    if plain.mode == ColorMode::Monochrome || !super::in_tmux(&var) {
        return plain;
    }
    let Some(features) = tmux_features() else {
        return plain;
    };
    let (mode, what) = if features.split(',').any(|f| f.trim() == "RGB") {
        (ColorMode::TrueColor, "has RGB")
    } else {
        (
            ColorMode::Ansi256,
            "lacks RGB, so tmux shows at most its 256",
        )
    };
    DetectedColors {
        mode,
        reason: format!("tmux says the terminal outside it {what}"),
    }
}

/// [`detect_color_mode`] on this process's environment.
pub fn detect_from_process_env() -> ColorMode {
    detect_color_mode(|name| std::env::var(name).ok())
}
