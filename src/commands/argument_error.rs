//! Argument errors in the program's one message form: clap's text becomes one line after
//! `bumpwork: error:`, and its usage and tips follow as hints.

/// The message line and the hints after it, from clap's rendered error (plain text).
pub fn one_line(rendered: &str) -> (String, String) {
    let text = rendered.trim_end();
    let text = text.strip_prefix("error: ").unwrap_or(text);
    let (first, hints) = text.split_once("\n\n").unwrap_or((text, ""));
    let mut lines = first.lines().map(str::trim);
    let mut line = lines.next().unwrap_or_default().to_string();
    let rest: Vec<&str> = lines.filter(|l| !l.is_empty()).collect();
    if !rest.is_empty() {
        line.push_str(if line.ends_with(':') { " " } else { "; " });
        line.push_str(&rest.join(", "));
    }
    let hints = hints
        .lines()
        .map(|hint| cut(hint.trim_start()))
        .collect::<Vec<_>>()
        .join("\n");
    (line, hints)
}

/// The most of a hint line shown: clap's tips repeat the argument they are about.
const HINT_CHARS: usize = 160;

fn cut(hint: &str) -> String {
    let mut shown: String = hint.chars().take(HINT_CHARS).collect();
    if hint.chars().nth(HINT_CHARS).is_some() {
        shown.push('…');
    }
    shown
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_list_of_missing_arguments_becomes_one_line_and_usage_a_hint() {
        let rendered = "error: the following required arguments were not provided:\n  \
                        --output <OUTPUT>\n  <SCENE>\n\nUsage: bumpwork render --output <OUTPUT> \
                        <SCENE>\n\nFor more information, try '--help'.\n";
        let (line, hints) = one_line(rendered);
        assert_eq!(
            line,
            "the following required arguments were not provided: --output <OUTPUT>, <SCENE>"
        );
        assert_eq!(
            hints,
            "Usage: bumpwork render --output <OUTPUT> <SCENE>\n\nFor more information, try '--help'."
        );
    }

    #[test]
    fn a_long_hint_is_cut() {
        let long = "a".repeat(10_000);
        let rendered = format!("error: unexpected argument '--a'\n\n  tip: to pass '--{long}'\n");
        let (_, hints) = one_line(&rendered);
        assert!(hints.chars().count() <= HINT_CHARS + 1, "{}", hints.len());
        assert!(hints.ends_with('…'));
    }

    #[test]
    fn a_tip_stays_a_hint() {
        let rendered = "error: unrecognized subcommand 'rendr'\n\n  tip: a similar subcommand \
                        exists: 'render'\n\nUsage: bumpwork [COMMAND]\n";
        let (line, hints) = one_line(rendered);
        assert_eq!(line, "unrecognized subcommand 'rendr'");
        assert!(hints.starts_with("tip: a similar subcommand exists: 'render'"));
    }
}
