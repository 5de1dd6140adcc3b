//! Colour mode detection, the `--colors` choice, sanitising untrusted text and the terminal restore
//! sequences, all without a real terminal.

use std::collections::HashMap;

use bumpwork::term::{
    ColorChoice, ColorMode, TerminalModes, detect_color_mode, sanitize, write_enter_sequence,
    write_restore_sequence,
};

fn detect(vars: &[(&str, &str)]) -> ColorMode {
    let env: HashMap<String, String> = vars
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    detect_color_mode(|name| env.get(name).cloned())
}

#[test]
fn colour_mode_follows_the_environment() {
    assert_eq!(
        detect(&[("COLORTERM", "truecolor"), ("TERM", "xterm-256color")]),
        ColorMode::TrueColor
    );
    assert_eq!(
        detect(&[("COLORTERM", "24bit"), ("TERM", "xterm")]),
        ColorMode::TrueColor
    );
    assert_eq!(detect(&[("TERM", "tmux-256color")]), ColorMode::Ansi256);
    assert_eq!(
        detect(&[("TERM", "screen-256color"), ("COLORTERM", "")]),
        ColorMode::Ansi256
    );
    assert_eq!(detect(&[("TERM", "xterm")]), ColorMode::Ansi16);
    assert_eq!(detect(&[("TERM", "linux")]), ColorMode::Ansi16);
    assert_eq!(detect(&[]), ColorMode::Ansi16);
    assert_eq!(detect(&[("TERM", "dumb")]), ColorMode::Monochrome);
}

#[test]
fn no_color_wins_over_detection_but_not_over_an_explicit_choice() {
    let env = [
        ("NO_COLOR", "1"),
        ("COLORTERM", "truecolor"),
        ("TERM", "xterm-256color"),
    ];
    assert_eq!(detect(&env), ColorMode::Monochrome);
    // An empty NO_COLOR does not count (no-color.org).
    assert_eq!(
        detect(&[("NO_COLOR", ""), ("COLORTERM", "truecolor")]),
        ColorMode::TrueColor
    );
    let lookup = |name: &str| {
        env.iter()
            .find(|(k, _)| *k == name)
            .map(|(_, v)| v.to_string())
    };
    let explicit: ColorChoice = "256".parse().unwrap();
    assert_eq!(explicit.resolve(lookup), ColorMode::Ansi256);
    assert_eq!(ColorChoice::Auto.resolve(lookup), ColorMode::Monochrome);
}

#[test]
fn colors_argument_parses() {
    let parse = |s: &str| s.parse::<ColorChoice>();
    assert_eq!(
        parse("truecolor"),
        Ok(ColorChoice::Fixed(ColorMode::TrueColor))
    );
    assert_eq!(parse("256"), Ok(ColorChoice::Fixed(ColorMode::Ansi256)));
    assert_eq!(parse("16"), Ok(ColorChoice::Fixed(ColorMode::Ansi16)));
    assert_eq!(parse("none"), Ok(ColorChoice::Fixed(ColorMode::Monochrome)));
    assert_eq!(parse("AUTO"), Ok(ColorChoice::Auto));
    let error = parse("8").unwrap_err().to_string();
    assert!(
        error.contains("\"8\"") && error.contains("truecolor"),
        "{error}"
    );
}

#[test]
fn sanitize_escapes_everything_that_steers_a_terminal() {
    assert!(matches!(
        sanitize("plain name.bump"),
        std::borrow::Cow::Borrowed(_)
    ));
    assert_eq!(sanitize("évolution ▀ ok"), "évolution ▀ ok");
    assert_eq!(sanitize("a\x1b[31mred\x1b[0m"), "a\\e[31mred\\e[0m");
    assert_eq!(sanitize("ding\x07"), "ding\\x07");
    assert_eq!(sanitize("line\nnext\r\tx"), "line\\nnext\\r\\tx");
    assert_eq!(sanitize("\x1b]0;title\x07"), "\\e]0;title\\x07");
    assert_eq!(sanitize("c1 \u{9b}2J csi"), "c1 \\u{9b}2J csi");
    assert_eq!(sanitize("del\x7f nul\0"), "del\\x7f nul\\x00");
    assert_eq!(sanitize("evil\u{202e}txt.exe"), "evil\\u{202e}txt.exe");
    for text in ["\x1b[2J\x1b[H", "x\u{85}y", "\u{1b}P q\u{1b}\\"] {
        assert!(!sanitize(text).chars().any(|c| c.is_control()), "{text:?}");
    }
}

#[test]
fn restore_sequence_leaves_the_alternate_screen_and_shows_the_cursor() {
    let mut out = Vec::new();
    write_restore_sequence(&mut out, TerminalModes::ALL).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("\x1b[?1049l"),
        "leave alternate screen: {text:?}"
    );
    assert!(text.contains("\x1b[?25h"), "show cursor: {text:?}");
    assert!(text.contains("\x1b[?1000l"), "mouse capture off: {text:?}");
    assert!(
        text.starts_with("\x1b[?2026l"),
        "end any open synchronized update first: {text:?}"
    );
    // Leaving the alternate screen comes last, so nothing else lands on the user's screen.
    assert!(text.ends_with("\x1b[?1049l"), "{text:?}");
}

#[test]
fn restore_undoes_only_what_was_entered() {
    let mut out = Vec::new();
    write_restore_sequence(
        &mut out,
        TerminalModes::ALTERNATE_SCREEN | TerminalModes::HIDDEN_CURSOR,
    )
    .unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(!text.contains("\x1b[?1000l"), "{text:?}");
    let mut enter = Vec::new();
    write_enter_sequence(
        &mut enter,
        TerminalModes::ALTERNATE_SCREEN | TerminalModes::HIDDEN_CURSOR,
    )
    .unwrap();
    let enter = String::from_utf8(enter).unwrap();
    assert!(
        enter.contains("\x1b[?1049h") && enter.contains("\x1b[?25l"),
        "{enter:?}"
    );
}

/// Environment variables, as names and values.
type Variables = &'static [(&'static str, &'static str)];

/// Environments as they arrive over SSH (only TERM and what the SSH set-up forwards), with the
/// colours and the reason detection gives.
const DIRECT_COLOUR_CASES: &[(Variables, ColorMode, &str)] = &[
    (
        &[("TERM", "xterm-kitty")],
        ColorMode::TrueColor,
        "TERM=xterm-kitty",
    ),
    (&[("TERM", "foot")], ColorMode::TrueColor, "TERM=foot"),
    (
        &[("TERM", "alacritty")],
        ColorMode::TrueColor,
        "TERM=alacritty",
    ),
    (
        &[("TERM", "xterm-ghostty")],
        ColorMode::TrueColor,
        "TERM=xterm-ghostty",
    ),
    (&[("TERM", "wezterm")], ColorMode::TrueColor, "TERM=wezterm"),
    (
        &[("TERM", "xterm-direct")],
        ColorMode::TrueColor,
        "TERM=xterm-direct",
    ),
    (
        &[("TERM", "xterm-256color"), ("TERM_PROGRAM", "iTerm.app")],
        ColorMode::TrueColor,
        "TERM_PROGRAM=iTerm.app",
    ),
    (
        &[
            ("TERM", "xterm-256color"),
            ("TERM_PROGRAM", "Apple_Terminal"),
        ],
        ColorMode::Ansi256,
        "TERM_PROGRAM=Apple_Terminal",
    ),
    (
        &[("TERM", "xterm-256color"), ("LC_TERMINAL", "iTerm2")],
        ColorMode::TrueColor,
        "LC_TERMINAL=iTerm2",
    ),
    (
        &[("TERM", "xterm-256color"), ("VTE_VERSION", "7600")],
        ColorMode::TrueColor,
        "VTE_VERSION=7600",
    ),
    (
        &[("TERM", "xterm-256color"), ("VTE_VERSION", "3405")],
        ColorMode::Ansi256,
        "TERM=xterm-256color",
    ),
    (
        &[("TERM", "xterm-256color"), ("KITTY_WINDOW_ID", "1")],
        ColorMode::TrueColor,
        "KITTY_WINDOW_ID is set",
    ),
    (
        &[("TERM", "tmux-256color")],
        ColorMode::Ansi256,
        "TERM=tmux-256color",
    ),
    (
        &[("TERM", "xterm")],
        ColorMode::Ansi16,
        "TERM=xterm, nothing more known",
    ),
    (
        &[("TERM", "xterm-kitty"), ("NO_COLOR", "1")],
        ColorMode::Monochrome,
        "NO_COLOR is set",
    ),
];

#[test]
fn direct_colour_terminals_are_known_without_colorterm_and_the_reason_is_given() {
    let detected = |vars: &[(&str, &str)]| {
        let env: HashMap<String, String> = vars
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        bumpwork::term::detect_colors(|name| env.get(name).cloned())
    };
    for &(vars, mode, reason) in DIRECT_COLOUR_CASES {
        let found = detected(vars);
        assert_eq!(
            (found.mode, found.reason.as_str()),
            (mode, reason),
            "{vars:?}"
        );
    }
    // A TERM with terminal controls in it is shown escaped.
    assert!(
        !detected(&[("TERM", "x\u{1b}[2J")])
            .reason
            .contains('\u{1b}')
    );
}

#[test]
fn inside_tmux_the_colours_are_those_tmux_knows_the_outer_terminal_has() {
    let tmux = [
        ("TERM", "tmux-256color"),
        ("TMUX", "/tmp/tmux-0/default,1,0"),
    ];
    let detected = |vars: &[(&str, &str)], features: Option<&str>| {
        let env: HashMap<String, String> = vars
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        let asked = std::cell::Cell::new(false);
        let found = bumpwork::term::detect_colors_in_tmux(
            |name| env.get(name).cloned(),
            || {
                asked.set(true);
                features.map(str::to_string)
            },
        );
        (found.mode, found.reason, asked.get())
    };
    let rgb = "256,RGB,bpaste,clipboard,ccolour,cstyle,extkeys,focus,margins,mouse,title";
    let (mode, reason, _) = detected(&tmux, Some(rgb));
    assert_eq!(mode, ColorMode::TrueColor);
    assert_eq!(reason, "tmux says the terminal outside it has RGB");
    let (mode, reason, _) = detected(&tmux, Some("256,bpaste,title"));
    assert_eq!(mode, ColorMode::Ansi256);
    assert!(reason.contains("lacks RGB"), "{reason}");
    // tmux lists `256` only where terminfo lacks it; tmux makes 256 colours fit the terminal.
    assert_eq!(detected(&tmux, Some("title")).0, ColorMode::Ansi256);
    // A feature whose name merely contains RGB is not RGB.
    assert_eq!(detected(&tmux, Some("256,xRGBx")).0, ColorMode::Ansi256);
    // tmux says nothing (no client, tmux before 3.2): the environment decides, as before.
    let (mode, reason, asked) = detected(&tmux, None);
    assert_eq!(
        (mode, reason.as_str(), asked),
        (ColorMode::Ansi256, "TERM=tmux-256color", true)
    );
    // Outside tmux, tmux is not asked; NO_COLOR wins inside it.
    let (_, _, asked) = detected(&[("TERM", "tmux-256color")], Some(rgb));
    assert!(!asked, "tmux was asked outside tmux");
    let no_colour = [tmux[0], tmux[1], ("NO_COLOR", "1")];
    assert_eq!(detected(&no_colour, Some(rgb)).0, ColorMode::Monochrome);
}
