//! SGR (colour) escape sequences: the shortest sequence that moves the terminal's pen to the colours a
//! cell needs, leaving a colour parameter out when the pen already has it.

use super::color::Color;

/// The colours the terminal is currently drawing with; `None` where unknown (so it must be set).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pen {
    pub fg: Option<Color>,
    pub bg: Option<Color>,
}

/// What a glyph needs from the pen: `None` where that side does not show (a space's fg, a `█`'s bg).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Need {
    pub fg: Option<Color>,
    pub bg: Option<Color>,
}

#[derive(Clone, Copy)]
enum Side {
    Fg,
    Bg,
}

impl Pen {
    /// The colour changes `need` asks of this pen.
    fn changes(self, need: Need) -> (Option<Color>, Option<Color>) {
        let differs = |want: Option<Color>, have: Option<Color>| want.filter(|w| have != Some(*w));
        (differs(need.fg, self.fg), differs(need.bg, self.bg))
    }

    /// Bytes of the SGR sequence [`Pen::apply`] would write.
    pub fn cost(self, need: Need) -> usize {
        match self.changes(need) {
            (None, None) => 0,
            (Some(Color::Default), Some(Color::Default)) => RESET.len(),
            (fg, bg) => {
                let params = fg.map_or(0, |c| param_len(c, Side::Fg))
                    + bg.map_or(0, |c| param_len(c, Side::Bg));
                let separator = (fg.is_some() && bg.is_some()) as usize;
                3 + params + separator
            }
        }
    }

    /// Writes the SGR sequence that gives the pen what `need` asks, and updates the pen.
    pub fn apply(&mut self, need: Need, out: &mut Vec<u8>) {
        match self.changes(need) {
            (None, None) => return,
            (Some(Color::Default), Some(Color::Default)) => out.extend_from_slice(RESET),
            (fg, bg) => {
                out.extend_from_slice(b"\x1b[");
                if let Some(c) = fg {
                    push_param(c, Side::Fg, out);
                }
                if fg.is_some() && bg.is_some() {
                    out.push(b';');
                }
                if let Some(c) = bg {
                    push_param(c, Side::Bg, out);
                }
                out.push(b'm');
            }
        }
        self.fg = need.fg.or(self.fg);
        self.bg = need.bg.or(self.bg);
    }
}

/// Resets both colours (and all other attributes) to the terminal's defaults.
pub const RESET: &[u8] = b"\x1b[m";

fn param_len(color: Color, side: Side) -> usize {
    match color {
        Color::Default => 2,
        Color::Indexed(0..=7) => 2,
        // aixterm bright codes: 90–97 fg, 100–107 bg.
        Color::Indexed(8..=15) => 2 + matches!(side, Side::Bg) as usize,
        Color::Indexed(i) => 5 + digits(i),
        Color::Rgb(r, g, b) => 7 + digits(r) + digits(g) + digits(b),
    }
}

fn push_param(color: Color, side: Side, out: &mut Vec<u8>) {
    let (base, bright, extended) = match side {
        Side::Fg => (30u8, 90u8, b"38" as &[u8]),
        Side::Bg => (40, 100, b"48" as &[u8]),
    };
    match color {
        Color::Default => push_u8(base + 9, out),
        Color::Indexed(i @ 0..=7) => push_u8(base + i, out),
        Color::Indexed(i @ 8..=15) => push_u8(bright + i - 8, out),
        Color::Indexed(i) => {
            out.extend_from_slice(extended);
            out.extend_from_slice(b";5;");
            push_u8(i, out);
        }
        Color::Rgb(r, g, b) => {
            out.extend_from_slice(extended);
            out.extend_from_slice(b";2;");
            for (k, v) in [r, g, b].into_iter().enumerate() {
                if k > 0 {
                    out.push(b';');
                }
                push_u8(v, out);
            }
        }
    }
}

fn digits(v: u8) -> usize {
    1 + (v >= 10) as usize + (v >= 100) as usize
}

/// Appends `v` in decimal.
pub fn push_u8(v: u8, out: &mut Vec<u8>) {
    push_decimal(v as u32, out);
}

/// Appends `v` in decimal without allocating.
pub fn push_decimal(v: u32, out: &mut Vec<u8>) {
    let mut digits = [0u8; 10];
    let mut n = v;
    let mut len = 0;
    loop {
        digits[len] = b'0' + (n % 10) as u8;
        len += 1;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend(digits[..len].iter().rev());
}

#[cfg(test)]
mod tests {
    use super::*;

    fn emitted(pen: Pen, need: Need) -> (String, usize) {
        let mut out = Vec::new();
        let mut pen2 = pen;
        pen2.apply(need, &mut out);
        (String::from_utf8(out).unwrap(), pen.cost(need))
    }

    #[test]
    fn cost_matches_emitted_length() {
        let colours = [
            Color::Default,
            Color::Indexed(3),
            Color::Indexed(12),
            Color::Indexed(200),
            Color::Rgb(0, 10, 255),
        ];
        for &f in &colours {
            for &b in &colours {
                for pen in [
                    Pen::default(),
                    Pen {
                        fg: Some(f),
                        bg: None,
                    },
                    Pen {
                        fg: Some(b),
                        bg: Some(f),
                    },
                ] {
                    for need in [
                        Need {
                            fg: Some(f),
                            bg: Some(b),
                        },
                        Need {
                            fg: None,
                            bg: Some(b),
                        },
                    ] {
                        let (s, cost) = emitted(pen, need);
                        assert_eq!(s.len(), cost, "{s:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn shortest_forms() {
        let need = |fg, bg| Need { fg, bg };
        let unknown = Pen::default();
        assert_eq!(
            emitted(
                unknown,
                need(Some(Color::Indexed(1)), Some(Color::Indexed(9)))
            )
            .0,
            "\x1b[31;101m"
        );
        assert_eq!(
            emitted(unknown, need(Some(Color::Default), Some(Color::Default))).0,
            "\x1b[m"
        );
        let red_on_blue = Pen {
            fg: Some(Color::Rgb(255, 0, 0)),
            bg: Some(Color::Indexed(4)),
        };
        assert_eq!(
            emitted(
                red_on_blue,
                need(Some(Color::Rgb(255, 0, 0)), Some(Color::Indexed(4)))
            )
            .0,
            ""
        );
        assert_eq!(
            emitted(red_on_blue, need(None, Some(Color::Indexed(100)))).0,
            "\x1b[48;5;100m"
        );
        assert_eq!(
            emitted(
                unknown,
                need(Some(Color::Rgb(1, 2, 3)), Some(Color::Rgb(4, 5, 6)))
            )
            .0,
            "\x1b[38;2;1;2;3;48;2;4;5;6m"
        );
    }
}
