//! Picture → cell grid: cuts the picture into cells of the chosen glyph set and colours each cell.

use super::cell::{Cell, CellGrid};
use super::color::Color;
use super::color_mode::ColorMode;
use super::dither::threshold_u8;
use super::glyphs::GlyphSet;
use super::picture::Picture;
use super::quantize::{Palette, Quantizer, monochrome_lit};
use super::split::best_split;

/// How to encode a picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EncodeOptions {
    pub colors: ColorMode,
    pub glyphs: GlyphSet,
    /// Ordered dithering in the palette and monochrome modes: a truer average colour for more colour
    /// changes, so more bytes. Off, each colour takes its nearest palette entry.
    pub dither: bool,
}

impl EncodeOptions {
    /// `colors` in `glyphs`, dithered.
    pub fn new(colors: ColorMode, glyphs: GlyphSet) -> Self {
        EncodeOptions {
            colors,
            glyphs,
            dither: true,
        }
    }
}

/// Pixels outside the picture (the partial last row or column of cells) count as black when splitting.
const PADDING: [u8; 3] = [0, 0, 0];

/// The threshold that rounds to the nearest entry: what "no dithering" means.
const NO_DITHER: u8 = 128;

/// The cells showing `picture`: `ceil(width / cell width) × ceil(height / cell height)` of them.
pub fn encode(picture: &Picture, options: EncodeOptions) -> CellGrid {
    let (cell_w, cell_h) = options.glyphs.cell_pixels();
    let cols = picture.width().div_ceil(cell_w);
    let rows = picture.height().div_ceil(cell_h);
    let mut grid = CellGrid::new(cols, rows);
    let mut encoder = CellEncoder::new(picture, options);
    for row in 0..rows {
        for col in 0..cols {
            grid.set(col, row, encoder.cell(col, row).canonical());
        }
    }
    grid
}

struct CellEncoder<'a> {
    picture: &'a Picture<'a>,
    options: EncodeOptions,
    quantizer: Option<Quantizer>,
}

impl<'a> CellEncoder<'a> {
    fn new(picture: &'a Picture<'a>, options: EncodeOptions) -> Self {
        let quantizer = match options.colors {
            ColorMode::Ansi256 => Some(Quantizer::new(Palette::Xterm256)),
            ColorMode::Ansi16 => Some(Quantizer::new(Palette::Ansi16)),
            ColorMode::TrueColor | ColorMode::Monochrome => None,
        };
        CellEncoder {
            picture,
            options,
            quantizer,
        }
    }

    fn cell(&mut self, col: usize, row: usize) -> Cell {
        match (self.options.colors, self.options.glyphs) {
            (ColorMode::Monochrome, _) => self.monochrome_cell(col, row),
            (_, GlyphSet::HalfBlock) => self.half_block_cell(col, row),
            _ => self.two_colour_cell(col, row),
        }
    }

    fn threshold(&self, x: usize, y: usize) -> u8 {
        if self.options.dither {
            threshold_u8(x, y)
        } else {
            NO_DITHER
        }
    }

    /// `▀` with the top pixel as fg and the bottom one as bg, each dithered at its own position. A missing
    /// bottom pixel (odd height) shows the terminal's own background.
    fn half_block_cell(&mut self, col: usize, row: usize) -> Cell {
        let mut colorize = |y: usize| match self.picture.pixel(col, y) {
            Some(p) => self.palette_color(p, self.threshold(col, y)),
            None => Color::Default,
        };
        let fg = colorize(2 * row);
        let bg = colorize(2 * row + 1);
        Cell {
            glyph: '▀', fg, bg
        }
    }

    fn two_colour_cell(&mut self, col: usize, row: usize) -> Cell {
        let (pixels, count) = self.cell_pixels(col, row);
        let split = best_split(&pixels[..count]);
        // Both means share the cell's threshold: the dither pattern runs at cell resolution here.
        let threshold = self.threshold(col, row);
        Cell {
            glyph: self.options.glyphs.glyph(split.mask),
            fg: self.palette_color(split.fg, threshold),
            bg: self.palette_color(split.bg, threshold),
        }
    }

    /// Each sub-pixel lit or not by its dithered luma; lit sub-pixels are drawn in the default foreground.
    fn monochrome_cell(&self, col: usize, row: usize) -> Cell {
        let glyphs = self.options.glyphs;
        let (cell_w, cell_h) = glyphs.cell_pixels();
        let mut mask = 0u8;
        for i in 0..cell_w * cell_h {
            let (x, y) = (col * cell_w + i % cell_w, row * cell_h + i / cell_w);
            let lit = self
                .picture
                .pixel(x, y)
                .is_some_and(|p| monochrome_lit(p, self.threshold(x, y)));
            mask |= (lit as u8) << i;
        }
        Cell {
            glyph: glyphs.glyph(mask),
            fg: Color::Default,
            bg: Color::Default,
        }
    }

    fn cell_pixels(&self, col: usize, row: usize) -> ([[u8; 3]; 6], usize) {
        let (cell_w, cell_h) = self.options.glyphs.cell_pixels();
        let mut pixels = [PADDING; 6];
        for (i, slot) in pixels.iter_mut().enumerate().take(cell_w * cell_h) {
            let (x, y) = (col * cell_w + i % cell_w, row * cell_h + i / cell_w);
            *slot = self.picture.pixel(x, y).unwrap_or(PADDING);
        }
        (pixels, cell_w * cell_h)
    }

    fn palette_color(&mut self, rgb: [u8; 3], threshold: u8) -> Color {
        match &mut self.quantizer {
            Some(quantizer) => Color::Indexed(quantizer.quantize(rgb, threshold)),
            None if self.options.colors == ColorMode::TrueColor => {
                Color::Rgb(rgb[0], rgb[1], rgb[2])
            }
            None => Color::Default,
        }
    }
}
