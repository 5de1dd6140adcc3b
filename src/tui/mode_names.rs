//! The short names the status line and messages give the picture's glyphs or graphics
//! protocol and the colour mode.

use crate::term::graphics::Protocol;
use crate::term::{ColorMode, GlyphSet};

/// The glyphs or the graphics protocol the picture is drawn in.
pub fn picture_name(graphics: Option<Protocol>, glyphs: GlyphSet) -> &'static str {
    match graphics {
        Some(protocol) => protocol.name(),
        None => glyphs_name(glyphs),
    }
}

fn glyphs_name(glyphs: GlyphSet) -> &'static str {
    match glyphs {
        GlyphSet::HalfBlock => "half",
        GlyphSet::Quadrant => "quad",
        GlyphSet::Sextant => "sextant",
    }
}

pub fn colors_name(colors: ColorMode) -> &'static str {
    match colors {
        ColorMode::TrueColor => "truecolor",
        ColorMode::Ansi256 => "256",
        ColorMode::Ansi16 => "16",
        ColorMode::Monochrome => "mono",
    }
}
