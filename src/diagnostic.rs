//! Messages about user files: `file:line:column: what was expected` with the line and a caret, with any
//! control characters from the file escaped so nothing from a file reaches the terminal raw.

/// The one sanitiser for text from files: see `term::sanitize`.
pub use crate::term::sanitize;

/// A place in a source text, as a message shows it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Spot {
    /// 1-based line.
    pub line: usize,
    /// 1-based column, counted in characters.
    pub column: usize,
    /// The line around the spot, escaped (see `snippet`).
    pub shown: String,
    /// Display columns before the caret in `shown` (escapes widen the text).
    pub caret: usize,
}

impl Spot {
    /// The spot at byte `offset` of `source` (clamped to the text and to a character boundary).
    pub fn at(source: &str, offset: usize) -> Spot {
        let offset = floor_char_boundary(source, offset.min(source.len()));
        let line_start = source[..offset].rfind('\n').map_or(0, |i| i + 1);
        let line_end = source[offset..]
            .find('\n')
            .map_or(source.len(), |i| offset + i);
        let before = &source[line_start..offset];
        let (shown, caret) = snippet(before, &source[offset..line_end]);
        Spot {
            line: source[..line_start].matches('\n').count() + 1,
            column: before.chars().count() + 1,
            shown,
            caret,
        }
    }
}

/// Renders `file:line:column: message`, the offending line (a window of it when it is long) and a
/// caret under the spot.
pub fn render(file: &str, source: &str, offset: usize, message: &str) -> String {
    render_at(file, &Spot::at(source, offset), message)
}

/// `render` for a spot already found.
pub fn render_at(file: &str, spot: &Spot, message: &str) -> String {
    let Spot {
        line,
        column,
        shown,
        caret,
    } = spot;
    let gutter = line.to_string().len();
    format!(
        "{file}:{line}:{column}: {message}\n{pad} |\n{line} | {shown}\n{pad} | {space}^",
        file = sanitize(file),
        message = sanitize(&shorten_quotes(message)),
        pad = " ".repeat(gutter),
        space = " ".repeat(*caret),
    )
}

/// Characters of context shown on each side of the spot in a long line.
const CONTEXT: usize = 60;

/// The escaped source line around a spot (`before` and `after` it on its line; long lines are
/// cut to `CONTEXT` characters each side, marked with `…`) and the caret's display column in it.
fn snippet(before: &str, after: &str) -> (String, usize) {
    let before: Vec<char> = before.chars().collect();
    let after = after.trim_end_matches('\r');
    let mut left: String = before[before.len().saturating_sub(CONTEXT)..]
        .iter()
        .collect();
    if before.len() > CONTEXT {
        left.insert(0, '…');
    }
    let mut right: String = after.chars().take(CONTEXT).collect();
    if after.chars().nth(CONTEXT).is_some() {
        right.push('…');
    }
    let left = escape_line(&left);
    let caret = left.chars().count();
    (left + &escape_line(&right), caret)
}

/// Text the user gave (a command-line value, an environment variable), safe to show and cut to
/// `CONTEXT` characters, marked with `…`: a message that quotes a 100 000-character argument
/// whole is no help.
pub fn shown_input(text: &str) -> String {
    let mut shown: String = text.chars().take(CONTEXT).collect();
    if text.chars().nth(CONTEXT).is_some() {
        shown.push('…');
    }
    sanitize(&shown).into_owned()
}

/// `message` with every quoted part (between backticks or double quotes) longer than `CONTEXT`
/// characters cut to that and marked with `…`: a message quotes what it found, and what it found
/// may be a 900 000-digit number.
pub fn shorten_quotes(message: &str) -> String {
    let mut shown = String::with_capacity(message.len().min(4 * CONTEXT));
    let mut quote: Option<(char, usize)> = None;
    for c in message.chars() {
        match quote {
            Some((open, _)) if c == open => {
                quote = None;
                shown.push(c);
            }
            Some((open, length)) => {
                if length < CONTEXT {
                    shown.push(c);
                } else if length == CONTEXT {
                    shown.push('…');
                }
                quote = Some((open, length + 1));
            }
            None => {
                if c == '`' || c == '"' {
                    quote = Some((c, 0));
                }
                shown.push(c);
            }
        }
    }
    shown
}

/// A line of a file made safe to show: control characters (and bidi overrides, which reorder what
/// a terminal shows) escaped, tabs as one space so a caret below stays aligned.
pub fn escape_line(text: &str) -> String {
    sanitize(&text.replace('\t', " ")).into_owned()
}

/// Each line of `text` sanitised, line breaks kept: for messages of several lines (diagnostics
/// with a caret) on their last way to the terminal.
pub fn sanitize_lines(text: &str) -> String {
    text.split('\n')
        .map(|line| sanitize(line))
        .collect::<Vec<_>>()
        .join("\n")
}

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_quotes_in_messages_are_cut() {
        let digits = "1".repeat(900_000);
        let message = format!("number `{digits}` is too large; found \"{digits}\"");
        let shown = shorten_quotes(&message);
        assert!(shown.len() < 200, "{} bytes", shown.len());
        let cut = format!("`{}…`", "1".repeat(CONTEXT));
        assert!(shown.starts_with(&format!("number {cut} is too large; found \"")));
        assert_eq!(
            shorten_quotes("expected `,`, found \"x\""),
            "expected `,`, found \"x\""
        );
    }

    #[test]
    fn escapes_terminal_controls() {
        assert_eq!(sanitize("a\x1b[31mb\x07\n"), "a\\e[31mb\\x07\\n");
        assert_eq!(sanitize("\u{9b}x"), "\\u{9b}x");
        assert!(matches!(
            sanitize("plain ünïcode"),
            std::borrow::Cow::Borrowed(_)
        ));
    }

    #[test]
    fn points_at_the_right_column() {
        let src = "a = 1\nradius = -1\n";
        let offset = src.find("-1").unwrap();
        let spot = Spot::at(src, offset);
        assert_eq!((spot.line, spot.column), (2, 10));
        let message = render("s.toml", src, offset, "expected a positive number");
        assert!(
            message.starts_with("s.toml:2:10: expected a positive number"),
            "{message}"
        );
        let caret_line = message.lines().last().unwrap();
        let code_line = message.lines().nth(2).unwrap();
        assert_eq!(caret_line.find('^'), code_line.find("-1"));
    }

    #[test]
    fn shows_a_window_of_a_long_line_with_the_caret_on_the_spot() {
        let src = format!(
            "key = \"{}\x1b]0;x\x07{}\"",
            "a".repeat(5000),
            "b".repeat(5000)
        );
        let offset = src.find('\x1b').unwrap();
        let message = render("s.toml", &src, offset, "bad");
        assert!(message.len() < 400, "{} bytes", message.len());
        assert!(!message.contains('\x1b') && !message.contains('\x07'));
        let code_line = message.lines().nth(2).unwrap();
        let caret_line = message.lines().last().unwrap();
        let caret = caret_line.chars().position(|c| c == '^').unwrap();
        let shown: String = code_line.chars().skip(caret).take(2).collect();
        assert_eq!(shown, "\\e");
    }

    #[test]
    fn sanitize_lines_keeps_line_breaks_only() {
        assert_eq!(sanitize_lines("a\x1b[2J\nb\rc"), "a\\e[2J\nb\\rc");
    }
}
