//! `PatternError`: every problem in a pattern file, with its place and a rustc-like snippet.

use crate::diagnostic::{Spot, escape_line, shorten_quotes};
use std::fmt;

/// A byte range in the source text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Span {
    pub start: usize,
    pub end: usize,
}

impl Span {
    pub fn new(start: usize, end: usize) -> Span {
        Span { start, end }
    }

    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span::new(self.start.min(other.start), self.end.max(other.end))
    }
}

/// An error in a pattern file. Displays as
/// `file:line:column: message`, then the source line and a caret under the spot.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PatternError {
    /// File name (or other origin) as given to `compile`, escaped for the terminal.
    pub origin: String,
    /// 1-based line; 0 when the error is not about a place in the text (e.g. the file cannot be read).
    pub line: usize,
    /// 1-based column, counted in characters.
    pub column: usize,
    /// What was expected or what is wrong, escaped for the terminal.
    pub message: String,
    /// The offending source line, escaped for the terminal (empty when `line` is 0).
    source_line: String,
    /// Display columns before the caret in `source_line` (escapes widen the text).
    caret_offset: usize,
}

impl PatternError {
    /// An error at byte offset `at` of `source`.
    pub fn at(source: &str, origin: &str, at: usize, message: impl Into<String>) -> PatternError {
        let spot = Spot::at(source, at);
        PatternError {
            origin: escape_line(origin),
            line: spot.line,
            column: spot.column,
            message: escape_line(&shorten_quotes(&message.into())),
            source_line: spot.shown,
            caret_offset: spot.caret,
        }
    }

    /// An error not tied to a place in the text (unreadable file).
    pub fn whole_file(origin: &str, message: impl Into<String>) -> PatternError {
        PatternError {
            origin: escape_line(origin),
            line: 0,
            column: 0,
            message: escape_line(&shorten_quotes(&message.into())),
            source_line: String::new(),
            caret_offset: 0,
        }
    }
}

impl fmt::Display for PatternError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            return write!(f, "{}: {}", self.origin, self.message);
        }
        let number = self.line.to_string();
        let gutter = " ".repeat(number.len());
        writeln!(
            f,
            "{}:{}:{}: {}",
            self.origin, self.line, self.column, self.message
        )?;
        writeln!(f, "{gutter} |")?;
        writeln!(f, "{number} | {}", self.source_line)?;
        write!(f, "{gutter} | {}^", " ".repeat(self.caret_offset))
    }
}

impl std::error::Error for PatternError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn displays_place_line_and_caret() {
        let e = PatternError::at(
            "let a = 1\nheight = b + 1\n",
            "p.pat",
            19,
            "unknown name `b`",
        );
        assert_eq!((e.line, e.column), (2, 10));
        let text = e.to_string();
        assert!(text.starts_with("p.pat:2:10: unknown name `b`\n"));
        assert!(
            text.ends_with("2 | height = b + 1\n  |          ^"),
            "{text}"
        );
    }

    #[test]
    fn long_lines_are_cut_around_the_error() {
        let source = format!("height = {}u{}", "(".repeat(5000), ")".repeat(5000));
        let e = PatternError::at(&source, "f", 5009, "here");
        assert_eq!(e.column, 5010);
        let text = e.to_string();
        assert!(text.len() < 400, "{text}");
        let lines: Vec<&str> = text.lines().collect();
        let caret = lines[3].chars().position(|c| c == '^').unwrap();
        assert_eq!(lines[2].chars().nth(caret), Some('u'));
    }

    #[test]
    fn control_characters_are_escaped_and_caret_follows() {
        let e = PatternError::at("a\u{1b}[31m b", "x\u{7}.pat", 7, "oops \u{1b}");
        let text = e.to_string();
        assert!(
            !text.chars().any(|c| c.is_control() && c != '\n'),
            "{text:?}"
        );
        let lines: Vec<&str> = text.lines().collect();
        let caret = lines[3].find('^').unwrap();
        assert_eq!(&lines[2][caret..caret + 1], "b");
    }
}
