//! Real pixels for terminals that show them: the kitty graphics protocol, sixel and iTerm2's
//! inline images; which one a terminal speaks (`detect`), and tmux's passthrough for them.
//! Only the picture's own bytes go into these sequences, never text from a file.

mod detect;
pub mod iterm2;
pub mod kitty;
pub mod sixel;

pub use crate::palette::MAX_COLOURS as SIXEL_MAX_COLOURS;
pub use detect::{GraphicsFound, Replies, decide, query_terminal};

/// A way of sending pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, strum::VariantArray, strum::IntoStaticStr)]
#[strum(serialize_all = "lowercase")]
pub enum Protocol {
    Kitty,
    Iterm2,
    Sixel,
}

impl Protocol {
    /// In the order `auto` prefers them: exact colours first (the order of the enum).
    pub const ALL: &'static [Protocol] = <Protocol as strum::VariantArray>::VARIANTS;

    pub fn name(self) -> &'static str {
        self.into()
    }

    /// Whether the terminal scales the picture to the cells it is placed over (so a smaller
    /// picture can stand in while the view moves).
    pub fn scales(self) -> bool {
        !matches!(self, Protocol::Sixel)
    }

    /// The escape sequences that show `rgb` (`width` × `height` pixels, 3 bytes each) from the
    /// cursor over `cols` × `rows` cells, each sequence on its own (for tmux to wrap one by one).
    pub fn encode(self, rgb: &[u8], size: (u32, u32), cells: (u16, u16)) -> Vec<Vec<u8>> {
        let ((width, height), (cols, rows)) = (size, cells);
        match self {
            Protocol::Kitty => kitty::image(rgb, width, height, cols, rows),
            Protocol::Sixel => vec![sixel::image(rgb, width, height)],
            Protocol::Iterm2 => vec![iterm2::image(rgb, width, height, cols, rows)],
        }
    }
}

/// `--graphics`: how the workbench picks its picture.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GraphicsChoice {
    /// Pixels if the terminal answers for a protocol, else blocks.
    #[default]
    Auto,
    Blocks,
    Only(Protocol),
}

impl GraphicsChoice {
    pub const NAMES: [&'static str; 5] = ["auto", "kitty", "sixel", "iterm2", "blocks"];

    /// A name of `NAMES`, or a message listing them (a command-line value parser).
    pub fn parse(name: &str) -> Result<GraphicsChoice, String> {
        match name {
            "auto" => Ok(GraphicsChoice::Auto),
            "blocks" => Ok(GraphicsChoice::Blocks),
            _ => Protocol::ALL
                .iter()
                .copied()
                .find(|p| p.name() == name)
                .map(GraphicsChoice::Only)
                .ok_or_else(|| {
                    format!(
                        "unknown graphics '{}'; the choices are {}",
                        crate::term::sanitize(name),
                        Self::NAMES.join(", ")
                    )
                }),
        }
    }
}

/// `sequence` wrapped for tmux to pass to the terminal outside it: `ESC P tmux; … ESC \` with
/// every ESC inside doubled.
pub fn tmux_passthrough(sequence: &[u8]) -> Vec<u8> {
    let mut out = b"\x1bPtmux;".to_vec();
    for &byte in sequence {
        if byte == 0x1b {
            out.push(0x1b);
        }
        out.push(byte);
    }
    out.extend_from_slice(b"\x1b\\");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_choice_name_parses_and_every_protocol_has_one() {
        for name in GraphicsChoice::NAMES {
            assert!(GraphicsChoice::parse(name).is_ok(), "{name}");
        }
        for &protocol in Protocol::ALL {
            assert!(GraphicsChoice::NAMES.contains(&protocol.name()));
            assert_eq!(
                GraphicsChoice::parse(protocol.name()),
                Ok(GraphicsChoice::Only(protocol))
            );
        }
        assert_eq!(GraphicsChoice::NAMES.len(), Protocol::ALL.len() + 2);
        assert!(GraphicsChoice::parse("pixels").is_err());
    }

    #[test]
    fn tmux_passthrough_doubles_every_escape() {
        let wrapped = tmux_passthrough(b"\x1b_Gm=0;AA\x1b\\");
        assert_eq!(
            wrapped,
            b"\x1bPtmux;\x1b\x1b_Gm=0;AA\x1b\x1b\\\x1b\\".to_vec()
        );
    }
}
