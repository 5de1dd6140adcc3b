//! Encoding pictures into cells: known cells in every colour mode, the two-colour split, quantisation
//! and dithering.

use bumpwork::term::palette::{ANSI16, xterm256_rgb};
use bumpwork::term::{
    Cell, CellGrid, Color, ColorMode, EncodeOptions, GlyphSet, Palette, Picture, best_split,
    encode, quantize, split_error,
};
use ratatui::Terminal;
use ratatui::backend::TestBackend;

fn options(colors: ColorMode, glyphs: GlyphSet) -> EncodeOptions {
    EncodeOptions::new(colors, glyphs)
}

const RED: [u8; 3] = [255, 0, 0];
const BLUE: [u8; 3] = [0, 0, 255];
const WHITE: [u8; 3] = [255, 255, 255];
const BLACK: [u8; 3] = [0, 0, 0];

/// 2×3 pixels: red/blue, blue/white, then a lone black/white row (odd height).
fn known_picture() -> Vec<[u8; 3]> {
    vec![RED, BLUE, BLUE, WHITE, BLACK, WHITE]
}

/// The colours a drawn cell shows at its top and bottom half.
fn halves(cell: Cell) -> (Color, Color) {
    match cell.glyph {
        '▀' => (cell.fg, cell.bg),
        '▄' => (cell.bg, cell.fg),
        ' ' => (cell.bg, cell.bg),
        '█' => (cell.fg, cell.fg),
        other => panic!("not a half-block cell: {other:?}"),
    }
}

fn draw_with_ratatui(
    grid: &CellGrid,
) -> Vec<Vec<(String, ratatui::style::Color, ratatui::style::Color)>> {
    let mut terminal =
        Terminal::new(TestBackend::new(grid.cols() as u16, grid.rows() as u16)).unwrap();
    terminal
        .draw(|frame| frame.render_widget(grid, frame.area()))
        .unwrap();
    let buffer = terminal.backend().buffer();
    (0..grid.rows() as u16)
        .map(|y| {
            (0..grid.cols() as u16)
                .map(|x| {
                    let cell = &buffer[(x, y)];
                    (cell.symbol().to_string(), cell.fg, cell.bg)
                })
                .collect()
        })
        .collect()
}

fn halves_of_ratatui(
    symbol: &str,
    fg: ratatui::style::Color,
    bg: ratatui::style::Color,
) -> (Color, Color) {
    let back = |c: ratatui::style::Color| match c {
        ratatui::style::Color::Rgb(r, g, b) => Color::Rgb(r, g, b),
        ratatui::style::Color::Indexed(i) => Color::Indexed(i),
        ratatui::style::Color::Reset => Color::Default,
        other => panic!("unexpected ratatui colour {other:?}"),
    };
    halves(Cell {
        glyph: symbol.chars().next().unwrap(),
        fg: back(fg),
        bg: back(bg),
    })
}

#[test]
fn half_blocks_show_each_pixel_in_every_colour_mode_through_ratatui() {
    let pixels = known_picture();
    let picture = Picture::new(&pixels, 2, 3).unwrap();
    let expected = |colors: ColorMode, rgb: [u8; 3]| match colors {
        ColorMode::TrueColor => Color::Rgb(rgb[0], rgb[1], rgb[2]),
        // Pure red, blue, white and black are exact entries of both palettes: no dither can move them.
        ColorMode::Ansi256 => Color::Indexed(match rgb {
            RED => 196,
            BLUE => 21,
            WHITE => 231,
            _ => 16,
        }),
        _ => Color::Indexed(match rgb {
            RED => 9,
            BLUE => 4,
            WHITE => 15,
            _ => 0,
        }),
    };
    for colors in [ColorMode::TrueColor, ColorMode::Ansi256, ColorMode::Ansi16] {
        let grid = encode(&picture, options(colors, GlyphSet::HalfBlock));
        assert_eq!((grid.cols(), grid.rows()), (2, 2));
        let drawn = draw_with_ratatui(&grid);
        for x in 0..2 {
            for row in 0..2 {
                let (symbol, fg, bg) = &drawn[row][x];
                let (top, bottom) = halves_of_ratatui(symbol, *fg, *bg);
                assert_eq!(
                    top,
                    expected(colors, pixels[2 * row * 2 + x]),
                    "{colors:?} cell {x},{row} top"
                );
                let bottom_expected = if row == 1 {
                    Color::Default // odd height: the missing pixel shows the terminal background
                } else {
                    expected(colors, pixels[(2 * row + 1) * 2 + x])
                };
                assert_eq!(bottom, bottom_expected, "{colors:?} cell {x},{row} bottom");
            }
        }
    }
}

#[test]
fn pure_blue_in_sixteen_colours_is_the_ansi_blue_that_is_nearest() {
    // xterm's ANSI blue is (0,0,238), nearer to pure blue than bright blue (92,92,255).
    assert_eq!(quantize(BLUE, Palette::Ansi16, 128), 4);
}

#[test]
fn monochrome_lights_bright_pixels_in_default_colours() {
    let pixels = vec![WHITE, BLACK, BLACK, WHITE];
    let picture = Picture::new(&pixels, 2, 2).unwrap();
    for glyphs in [GlyphSet::HalfBlock, GlyphSet::Quadrant] {
        let grid = encode(&picture, options(ColorMode::Monochrome, glyphs));
        let expected: Vec<char> = match glyphs {
            GlyphSet::HalfBlock => vec!['▀', '▄'],
            _ => vec!['▚'],
        };
        let got: Vec<char> = grid.row(0).iter().map(|c| c.glyph).collect();
        assert_eq!(got, expected, "{glyphs:?}");
        assert!(
            grid.row(0)
                .iter()
                .all(|c| c.fg == Color::Default && c.bg == Color::Default)
        );
    }
}

/// The picture of one cell, `glyphs`-sized, with `a` where `mask` has a bit and `b` elsewhere.
fn two_colour_cell(glyphs: GlyphSet, mask: u8, a: [u8; 3], b: [u8; 3]) -> Vec<[u8; 3]> {
    (0..glyphs.pixel_count())
        .map(|i| if mask & (1 << i) != 0 { a } else { b })
        .collect()
}

/// The colours a cell shows at each sub-pixel.
fn decode(cell: Cell, glyphs: GlyphSet) -> Vec<Color> {
    let mask = glyphs
        .mask(cell.glyph)
        .unwrap_or_else(|| panic!("{:?} not in {glyphs:?}", cell.glyph));
    (0..glyphs.pixel_count())
        .map(|i| {
            if mask & (1 << i) != 0 {
                cell.fg
            } else {
                cell.bg
            }
        })
        .collect()
}

fn rgb(p: [u8; 3]) -> Color {
    Color::Rgb(p[0], p[1], p[2])
}

#[test]
fn two_colour_patterns_reproduce_exactly() {
    for glyphs in [GlyphSet::Quadrant, GlyphSet::Sextant] {
        let (w, h) = glyphs.cell_pixels();
        for mask in 0..(1u8 << glyphs.pixel_count()) {
            let pixels = two_colour_cell(glyphs, mask, [200, 30, 40], [10, 90, 250]);
            let grid = encode(
                &Picture::new(&pixels, w, h).unwrap(),
                options(ColorMode::TrueColor, glyphs),
            );
            let shown = decode(grid.get(0, 0), glyphs);
            let wanted: Vec<Color> = pixels.iter().map(|&p| rgb(p)).collect();
            assert_eq!(shown, wanted, "{glyphs:?} mask {mask:06b}");
        }
    }
}

/// A small deterministic generator, so failures reproduce.
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn rgb(&mut self) -> [u8; 3] {
        let v = self.next();
        [v as u8, (v >> 8) as u8, (v >> 16) as u8]
    }
}

#[test]
fn chosen_split_has_the_least_error_of_all_splits() {
    let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
    for n in [2usize, 4, 6] {
        for _ in 0..2000 {
            let pixels: Vec<[u8; 3]> = (0..n).map(|_| rng.rgb()).collect();
            let chosen = split_error(&pixels, best_split(&pixels).mask);
            for mask in 0..(1u16 << n) as u8 {
                let other = split_error(&pixels, mask);
                assert!(
                    chosen <= other + 1e-6,
                    "{pixels:?}: chosen {chosen} > mask {mask:b} {other}"
                );
            }
        }
    }
}

#[test]
fn palette_colours_map_to_themselves() {
    for (index, &colour) in ANSI16.iter().enumerate() {
        for threshold in [2, 128, 254] {
            assert_eq!(quantize(colour, Palette::Ansi16, threshold), index as u8);
        }
    }
    for index in 16..=255u8 {
        for threshold in [2, 128, 254] {
            assert_eq!(
                quantize(xterm256_rgb(index), Palette::Xterm256, threshold),
                index
            );
        }
    }
}

/// The mean sRGB value shown for a flat `size × size` picture of `colour`.
fn dithered_mean(colour: [u8; 3], colors: ColorMode, size: usize) -> [f64; 3] {
    let pixels = vec![colour; size * size];
    let grid = encode(
        &Picture::new(&pixels, size, size).unwrap(),
        options(colors, GlyphSet::HalfBlock),
    );
    let mut sum = [0f64; 3];
    for y in 0..grid.rows() {
        for &cell in grid.row(y) {
            let (top, bottom) = halves(cell);
            for side in [top, bottom] {
                let Color::Indexed(i) = side else {
                    panic!("{side:?} is not a palette colour")
                };
                let shown = xterm256_rgb(i);
                (0..3).for_each(|c| sum[c] += shown[c] as f64);
            }
        }
    }
    sum.map(|s| s / (size * size) as f64)
}

#[test]
fn dithered_flat_grey_averages_to_the_grey() {
    for (grey, colors, tolerance) in [
        (128u8, ColorMode::Ansi16, 3.0),
        (180, ColorMode::Ansi16, 3.0),
        (60, ColorMode::Ansi16, 3.0),
        // Within half a step of the grey ramp (10 apart): a grey this near an entry shows flat.
        (100, ColorMode::Ansi256, 5.0),
        (115, ColorMode::Ansi256, 5.0),
        // Between two entries, it mixes them to its own value.
        (103, ColorMode::Ansi256, 1.5),
    ] {
        let mean = dithered_mean([grey; 3], colors, 32);
        for m in mean {
            assert!(
                (m - grey as f64).abs() <= tolerance,
                "{colors:?} grey {grey}: mean {mean:?}"
            );
        }
    }
}

#[test]
fn dithered_grey_mixes_more_than_one_palette_entry() {
    let pixels = vec![[180u8; 3]; 16 * 16];
    let grid = encode(
        &Picture::new(&pixels, 16, 16).unwrap(),
        options(ColorMode::Ansi16, GlyphSet::HalfBlock),
    );
    let mut seen: Vec<Color> = (0..grid.rows())
        .flat_map(|y| grid.row(y).iter().map(|&c| halves(c).0))
        .collect();
    seen.sort_by_key(|c| format!("{c:?}"));
    seen.dedup();
    assert!(seen.len() >= 2, "{seen:?}");
}

#[test]
fn grid_size_rounds_partial_cells_up() {
    let pixels = vec![WHITE; 5 * 7];
    let picture = Picture::new(&pixels, 5, 7).unwrap();
    for (glyphs, size) in [
        (GlyphSet::HalfBlock, (5, 4)),
        (GlyphSet::Quadrant, (3, 4)),
        (GlyphSet::Sextant, (3, 3)),
    ] {
        let grid = encode(&picture, options(ColorMode::TrueColor, glyphs));
        assert_eq!((grid.cols(), grid.rows()), size, "{glyphs:?}");
    }
    assert!(Picture::new(&pixels, 5, 6).is_err());
}

#[test]
fn sextant_glyphs_take_one_cell_each_in_ratatui() {
    let mut grid = CellGrid::new(6, 1);
    for x in 0..6 {
        let glyph = GlyphSet::Sextant.glyph(1 + 10 * x as u8);
        grid.set(
            x,
            0,
            Cell {
                glyph,
                fg: Color::Indexed(1),
                bg: Color::Indexed(4),
            },
        );
    }
    let drawn = draw_with_ratatui(&grid);
    for (x, (symbol, _, _)) in drawn[0].iter().enumerate() {
        assert_eq!(
            symbol.chars().next(),
            Some(grid.get(x, 0).glyph),
            "cell {x}"
        );
    }
}
