//! Lexer: source text to tokens with byte spans. Comments (`#`, `//`) and whitespace are skipped.

use super::error::{PatternError, Span};

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tok {
    Number(f64),
    Ident,
    // keywords
    Param,
    In,
    Let,
    If,
    Then,
    Else,
    And,
    Or,
    Not,
    True,
    False,
    // punctuation
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    Percent,
    LParen,
    RParen,
    Comma,
    Semicolon,
    Assign,
    DotDot,
    Lt,
    Le,
    Gt,
    Ge,
    EqEq,
    Ne,
    Eof,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Token {
    pub tok: Tok,
    pub span: Span,
}

/// Splits `source` into tokens, ending with `Tok::Eof`.
pub fn lex(source: &str, origin: &str) -> Result<Vec<Token>, PatternError> {
    let mut lexer = Lexer {
        src: source,
        bytes: source.as_bytes(),
        pos: 0,
    };
    let mut tokens = Vec::new();
    loop {
        lexer.skip_blanks_and_comments();
        let start = lexer.pos;
        let tok = lexer
            .next_token()
            .map_err(|message| PatternError::at(source, origin, start, message))?;
        tokens.push(Token {
            tok,
            span: Span::new(start, lexer.pos),
        });
        if tok == Tok::Eof {
            return Ok(tokens);
        }
    }
}

struct Lexer<'a> {
    src: &'a str,
    bytes: &'a [u8],
    pos: usize,
}

impl Lexer<'_> {
    fn peek(&self, ahead: usize) -> u8 {
        self.bytes.get(self.pos + ahead).copied().unwrap_or(0)
    }

    fn skip_blanks_and_comments(&mut self) {
        loop {
            match (self.peek(0), self.peek(1)) {
                (b' ' | b'\t' | b'\r' | b'\n', _) => self.pos += 1,
                (b'#', _) | (b'/', b'/') => {
                    while self.pos < self.bytes.len() && self.bytes[self.pos] != b'\n' {
                        self.pos += 1;
                    }
                }
                _ => return,
            }
        }
    }

    fn next_token(&mut self) -> Result<Tok, String> {
        if self.pos >= self.bytes.len() {
            return Ok(Tok::Eof);
        }
        let c = self.bytes[self.pos];
        if c.is_ascii_digit() || (c == b'.' && self.peek(1).is_ascii_digit()) {
            return self.number();
        }
        if c.is_ascii_alphabetic() || c == b'_' {
            return Ok(self.word());
        }
        self.punctuation()
    }

    fn number(&mut self) -> Result<Tok, String> {
        let start = self.pos;
        self.eat_digits();
        // `0..1` is a range, not the number `0.` followed by `.1`.
        if self.peek(0) == b'.' && self.peek(1) != b'.' {
            self.pos += 1;
            self.eat_digits();
        }
        if matches!(self.peek(0), b'e' | b'E') {
            let sign = usize::from(matches!(self.peek(1), b'+' | b'-'));
            if self.peek(1 + sign).is_ascii_digit() {
                self.pos += 1 + sign;
                self.eat_digits();
            }
        }
        let text = &self.src[start..self.pos];
        match text.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(Tok::Number(value)),
            _ => Err(format!("number `{text}` is out of range")),
        }
    }

    fn eat_digits(&mut self) {
        while self.peek(0).is_ascii_digit() {
            self.pos += 1;
        }
    }

    fn word(&mut self) -> Tok {
        let start = self.pos;
        while self.peek(0).is_ascii_alphanumeric() || self.peek(0) == b'_' {
            self.pos += 1;
        }
        match &self.src[start..self.pos] {
            "param" => Tok::Param,
            "in" => Tok::In,
            "let" => Tok::Let,
            "if" => Tok::If,
            "then" => Tok::Then,
            "else" => Tok::Else,
            "and" => Tok::And,
            "or" => Tok::Or,
            "not" => Tok::Not,
            "true" => Tok::True,
            "false" => Tok::False,
            _ => Tok::Ident,
        }
    }

    fn punctuation(&mut self) -> Result<Tok, String> {
        let two = (self.peek(0), self.peek(1));
        let (tok, len) = match two {
            (b'.', b'.') => (Tok::DotDot, 2),
            (b'<', b'=') => (Tok::Le, 2),
            (b'>', b'=') => (Tok::Ge, 2),
            (b'=', b'=') => (Tok::EqEq, 2),
            (b'!', b'=') => (Tok::Ne, 2),
            (b'&', b'&') => (Tok::And, 2),
            (b'|', b'|') => (Tok::Or, 2),
            (b'+', _) => (Tok::Plus, 1),
            (b'-', _) => (Tok::Minus, 1),
            (b'*', _) => (Tok::Star, 1),
            (b'/', _) => (Tok::Slash, 1),
            (b'^', _) => (Tok::Caret, 1),
            (b'%', _) => (Tok::Percent, 1),
            (b'(', _) => (Tok::LParen, 1),
            (b')', _) => (Tok::RParen, 1),
            (b',', _) => (Tok::Comma, 1),
            (b';', _) => (Tok::Semicolon, 1),
            (b'=', _) => (Tok::Assign, 1),
            (b'<', _) => (Tok::Lt, 1),
            (b'>', _) => (Tok::Gt, 1),
            (b'!', _) => (Tok::Not, 1),
            _ => return Err(self.unexpected_character()),
        };
        self.pos += len;
        Ok(tok)
    }

    fn unexpected_character(&self) -> String {
        let c = self.src[self.pos..].chars().next().unwrap_or('?');
        format!("unexpected character `{c}`: expected a number, a name, an operator or a comment")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<Tok> {
        lex(src, "t").unwrap().into_iter().map(|t| t.tok).collect()
    }

    #[test]
    fn range_is_not_a_decimal_point() {
        assert_eq!(
            kinds("0..1.5"),
            vec![Tok::Number(0.0), Tok::DotDot, Tok::Number(1.5), Tok::Eof]
        );
    }

    #[test]
    fn numbers_with_exponents_and_leading_dot() {
        assert_eq!(
            kinds("1e3 .5 2E-2"),
            vec![
                Tok::Number(1000.0),
                Tok::Number(0.5),
                Tok::Number(0.02),
                Tok::Eof
            ]
        );
    }

    #[test]
    fn comments_are_skipped() {
        assert_eq!(
            kinds("a # one\n// two\nb"),
            vec![Tok::Ident, Tok::Ident, Tok::Eof]
        );
    }

    #[test]
    fn operators_and_keywords() {
        assert_eq!(
            kinds("<= != == % ^ and not"),
            vec![
                Tok::Le,
                Tok::Ne,
                Tok::EqEq,
                Tok::Percent,
                Tok::Caret,
                Tok::And,
                Tok::Not,
                Tok::Eof
            ]
        );
    }

    #[test]
    fn unexpected_character_has_a_place() {
        let e = lex("a = 1\n  b @", "f.pat").unwrap_err();
        assert_eq!((e.line, e.column), (2, 5));
    }

    #[test]
    fn huge_number_is_an_error() {
        assert!(lex("1e999", "f").is_err());
    }
}
