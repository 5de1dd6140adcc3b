//! The colour of one side (foreground or background) of a terminal cell.

/// A terminal colour as the encoders produce it and the writers emit it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Color {
    /// 24-bit sRGB, for truecolor terminals.
    Rgb(u8, u8, u8),
    /// An index into the terminal's palette: 0..16 are the themed ANSI colours, 16..256 the xterm cube and greys.
    Indexed(u8),
    /// Whatever the terminal's default foreground or background is (they differ from each other).
    Default,
}

impl Color {
    /// True for colours that look the same whether used as foreground or background.
    /// `Default` is not one: the default foreground and default background are different colours.
    pub fn is_concrete(self) -> bool {
        !matches!(self, Color::Default)
    }
}

impl From<Color> for ratatui::style::Color {
    fn from(color: Color) -> Self {
        match color {
            Color::Rgb(r, g, b) => ratatui::style::Color::Rgb(r, g, b),
            Color::Indexed(i) => ratatui::style::Color::Indexed(i),
            Color::Default => ratatui::style::Color::Reset,
        }
    }
}
