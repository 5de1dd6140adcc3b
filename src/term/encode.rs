//! Picture → cell grid: cuts the picture into cells of the chosen glyph set and colours each cell.

use super::cell::{Cell, CellGrid};
use super::color::Color;
use super::color_mode::ColorMode;
use super::dither::threshold_u8;
use super::glyphs::GlyphSet;
use super::picture::Picture;
use super::quantize::{Palette, monochrome_lit, quantize};
use super::split::best_split;

/// How to encode a picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EncodeOptions {
    pub colors: ColorMode,
    pub glyphs: GlyphSet,
}

/// Pixels outside the picture (the partial last row or column of cells) count as black when splitting.
const PADDING: [u8; 3] = [0, 0, 0];

/// The cells showing `picture`: `ceil(width / cell width) × ceil(height / cell height)` of them.
pub fn encode(picture: &Picture, options: EncodeOptions) -> CellGrid {
    let (cell_w, cell_h) = options.glyphs.cell_pixels();
    let cols = picture.width().div_ceil(cell_w);
    let rows = picture.height().div_ceil(cell_h);
    let mut grid = CellGrid::new(cols, rows);
    for row in 0..rows {
        for col in 0..cols {
            let cell = encode_cell(picture, options, col, row);
            grid.set(col, row, cell.canonical());
        }
    }
    grid
}

fn encode_cell(picture: &Picture, options: EncodeOptions, col: usize, row: usize) -> Cell {
    match (options.colors, options.glyphs) {
        (ColorMode::Monochrome, glyphs) => monochrome_cell(picture, glyphs, col, row),
        (colors, GlyphSet::HalfBlock) => half_block_cell(picture, colors, col, row),
        (colors, glyphs) => two_colour_cell(picture, colors, glyphs, col, row),
    }
}

/// `▀` with the top pixel as fg and the bottom one as bg, each dithered at its own position. A missing
/// bottom pixel (odd height) shows the terminal's own background.
fn half_block_cell(picture: &Picture, colors: ColorMode, col: usize, row: usize) -> Cell {
    let (x, top_y) = (col, 2 * row);
    let colorize = |y: usize| {
        picture
            .pixel(x, y)
            .map(|p| to_color(p, colors, threshold_u8(x, y)))
    };
    let fg = colorize(top_y).unwrap_or(Color::Default);
    let bg = colorize(top_y + 1).unwrap_or(Color::Default);
    Cell {
        glyph: '▀', fg, bg
    }
}

fn two_colour_cell(
    picture: &Picture,
    colors: ColorMode,
    glyphs: GlyphSet,
    col: usize,
    row: usize,
) -> Cell {
    let (pixels, count) = cell_pixels(picture, glyphs, col, row);
    let split = best_split(&pixels[..count]);
    // Both means share the cell's threshold: the dither pattern runs at cell resolution here.
    let threshold = threshold_u8(col, row);
    Cell {
        glyph: glyphs.glyph(split.mask),
        fg: to_color(split.fg, colors, threshold),
        bg: to_color(split.bg, colors, threshold),
    }
}

/// Each sub-pixel lit or not by its dithered luma; lit sub-pixels are drawn in the default foreground.
fn monochrome_cell(picture: &Picture, glyphs: GlyphSet, col: usize, row: usize) -> Cell {
    let (cell_w, cell_h) = glyphs.cell_pixels();
    let mut mask = 0u8;
    for i in 0..cell_w * cell_h {
        let (x, y) = (col * cell_w + i % cell_w, row * cell_h + i / cell_w);
        let lit = picture
            .pixel(x, y)
            .is_some_and(|p| monochrome_lit(p, threshold_u8(x, y)));
        mask |= (lit as u8) << i;
    }
    Cell {
        glyph: glyphs.glyph(mask),
        fg: Color::Default,
        bg: Color::Default,
    }
}

fn cell_pixels(
    picture: &Picture,
    glyphs: GlyphSet,
    col: usize,
    row: usize,
) -> ([[u8; 3]; 6], usize) {
    let (cell_w, cell_h) = glyphs.cell_pixels();
    let mut pixels = [PADDING; 6];
    for (i, slot) in pixels.iter_mut().enumerate().take(cell_w * cell_h) {
        let (x, y) = (col * cell_w + i % cell_w, row * cell_h + i / cell_w);
        *slot = picture.pixel(x, y).unwrap_or(PADDING);
    }
    (pixels, cell_w * cell_h)
}

fn to_color(rgb: [u8; 3], colors: ColorMode, threshold: u8) -> Color {
    match colors {
        ColorMode::TrueColor => Color::Rgb(rgb[0], rgb[1], rgb[2]),
        ColorMode::Ansi256 => Color::Indexed(quantize(rgb, Palette::Xterm256, threshold)),
        ColorMode::Ansi16 => Color::Indexed(quantize(rgb, Palette::Ansi16, threshold)),
        ColorMode::Monochrome => Color::Default,
    }
}
