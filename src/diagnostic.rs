//! Messages about user files: `file:line:column: what was expected` with the line and a caret, with any
//! control characters from the file escaped so nothing from a file reaches the terminal raw.

/// The one sanitiser for text from files: see `term::sanitize`.
pub use crate::term::sanitize;

/// The 1-based line and column (in characters) of a byte offset.
pub fn line_column(source: &str, offset: usize) -> (usize, usize) {
    let offset = floor_char_boundary(source, offset.min(source.len()));
    let before = &source[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, source[line_start..offset].chars().count() + 1)
}

/// Renders `file:line:column: message`, the offending line and a caret under the spot.
pub fn render(file: &str, source: &str, offset: usize, message: &str) -> String {
    let (line, column) = line_column(source, offset);
    let text = source.lines().nth(line - 1).unwrap_or("");
    let gutter = line.to_string().len();
    let shown: String = text
        .chars()
        .map(|c| if c == '\t' { ' ' } else { c })
        .collect();
    format!(
        "{file}:{line}:{column}: {message}\n{pad} |\n{line} | {code}\n{pad} | {caret:>column$}",
        file = sanitize(file),
        message = sanitize(message),
        pad = " ".repeat(gutter),
        code = sanitize(&shown),
        caret = "^",
    )
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
        assert_eq!(line_column(src, offset), (2, 10));
        let message = render("s.toml", src, offset, "expected a positive number");
        assert!(
            message.starts_with("s.toml:2:10: expected a positive number"),
            "{message}"
        );
        let caret_line = message.lines().last().unwrap();
        let code_line = message.lines().nth(2).unwrap();
        assert_eq!(caret_line.find('^'), code_line.find("-1"));
    }
}
