//! Making untrusted text (file names, file contents, error messages) safe to put on a terminal.

use std::borrow::Cow;
use std::fmt::Write;

/// `text` with every character that could steer the terminal replaced by a visible escape: C0 controls
/// (so ESC, which starts every escape sequence, BEL, CR, LF and TAB too: split lines before sanitising),
/// DEL, C1 controls (U+0080–U+009F, which some terminals treat as CSI/OSC) and the bidirectional
/// overrides that can make shown text read differently from what it is. Borrows when nothing needs it.
pub fn sanitize(text: &str) -> Cow<'_, str> {
    let Some(first) = text.find(is_unsafe) else {
        return Cow::Borrowed(text);
    };
    let mut clean = String::with_capacity(text.len() + 8);
    clean.push_str(&text[..first]);
    for c in text[first..].chars() {
        if is_unsafe(c) {
            push_escape(c, &mut clean);
        } else {
            clean.push(c);
        }
    }
    Cow::Owned(clean)
}

fn is_unsafe(c: char) -> bool {
    c.is_control() || is_bidi_control(c)
}

fn is_bidi_control(c: char) -> bool {
    matches!(c, '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
}

fn push_escape(c: char, out: &mut String) {
    match c {
        '\n' => out.push_str("\\n"),
        '\r' => out.push_str("\\r"),
        '\t' => out.push_str("\\t"),
        '\u{1b}' => out.push_str("\\e"),
        c if (c as u32) < 0x80 => {
            let _ = write!(out, "\\x{:02x}", c as u32);
        }
        c => {
            let _ = write!(out, "\\u{{{:x}}}", c as u32);
        }
    }
}
