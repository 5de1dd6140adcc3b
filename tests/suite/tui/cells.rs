//! The cell encoding seen through ratatui: a framebuffer with known pixels gives the expected
//! cells in a `TestBackend`, in each colour mode.

use bumpwork::raster::Framebuffer;
use bumpwork::term::{ColorMode, EncodeOptions, GlyphSet, Picture, encode};
use glam::Vec3;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::style::Color;

const RED: Vec3 = Vec3::new(1.0, 0.0, 0.0);
const BLUE: Vec3 = Vec3::new(0.0, 0.0, 1.0);
const WHITE: Vec3 = Vec3::ONE;
const BLACK: Vec3 = Vec3::ZERO;

/// A 2×4 framebuffer: column 0 is red over blue, then white over black; column 1 is all white.
fn framebuffer() -> Framebuffer {
    let mut fb = Framebuffer::new(2, 4, BLACK);
    let pixels = [[RED, WHITE], [BLUE, WHITE], [WHITE, WHITE], [BLACK, WHITE]];
    for (y, row) in pixels.iter().enumerate() {
        for (x, &c) in row.iter().enumerate() {
            fb.color_mut()[y * 2 + x] = c;
        }
    }
    fb
}

/// The 2×2 cells of the framebuffer in `colors`, as ratatui shows them: (symbol, fg, bg).
fn cells(colors: ColorMode) -> Vec<(String, Color, Color)> {
    let fb = framebuffer();
    let srgb = fb.to_srgb8();
    let picture = Picture::new(&srgb, 2, 4).unwrap();
    let grid = encode(&picture, EncodeOptions::new(colors, GlyphSet::HalfBlock));
    assert_eq!((grid.cols(), grid.rows()), (2, 2));
    let mut terminal = Terminal::new(TestBackend::new(2, 2)).unwrap();
    terminal
        .draw(|frame| frame.render_widget(&grid, frame.area()))
        .unwrap();
    let buffer = terminal.backend().buffer();
    [(0, 0), (0, 1), (1, 0), (1, 1)]
        .map(|(x, y)| {
            let cell = &buffer[(x, y)];
            (cell.symbol().to_string(), cell.fg, cell.bg)
        })
        .to_vec()
}

/// A cell that shows one colour everywhere, whichever equivalent glyph was chosen.
fn solid(cell: &(String, Color, Color)) -> Option<Color> {
    match cell.0.as_str() {
        " " => Some(cell.2),
        "█" => Some(cell.1),
        "▀" | "▄" if cell.1 == cell.2 => Some(cell.1),
        _ => None,
    }
}

#[test]
fn truecolor_cells_carry_both_pixels_exactly() {
    let cells = cells(ColorMode::TrueColor);
    assert_eq!(
        cells[0],
        ("▀".into(), Color::Rgb(255, 0, 0), Color::Rgb(0, 0, 255))
    );
    assert_eq!(
        cells[1],
        ("▀".into(), Color::Rgb(255, 255, 255), Color::Rgb(0, 0, 0))
    );
    assert_eq!(solid(&cells[2]), Some(Color::Rgb(255, 255, 255)));
    assert_eq!(solid(&cells[3]), Some(Color::Rgb(255, 255, 255)));
}

#[test]
fn palette_colours_map_to_their_own_index_in_256_colours() {
    let cells = cells(ColorMode::Ansi256);
    // The cube corners: 16 + 36r + 6g + b.
    assert_eq!(
        cells[0],
        ("▀".into(), Color::Indexed(196), Color::Indexed(21))
    );
    assert_eq!(
        cells[1],
        ("▀".into(), Color::Indexed(231), Color::Indexed(16))
    );
    assert_eq!(solid(&cells[2]), Some(Color::Indexed(231)));
}

#[test]
fn palette_colours_map_to_their_own_index_in_16_colours() {
    let cells = cells(ColorMode::Ansi16);
    // Bright red (9) exists exactly; pure blue is nearest the bright blue (12) or blue (4).
    assert_eq!(cells[0].0, "▀");
    assert_eq!(cells[0].1, Color::Indexed(9));
    assert!(
        matches!(cells[0].2, Color::Indexed(4 | 12)),
        "{:?}",
        cells[0]
    );
    assert_eq!(
        cells[1],
        ("▀".into(), Color::Indexed(15), Color::Indexed(0))
    );
}

#[test]
fn monochrome_cells_light_the_bright_pixels_in_default_colours() {
    let cells = cells(ColorMode::Monochrome);
    // White over black: the upper half lit; all white: the full block.
    assert_eq!(cells[1], ("▀".into(), Color::Reset, Color::Reset));
    assert_eq!(cells[2], ("█".into(), Color::Reset, Color::Reset));
    assert_eq!(cells[3], ("█".into(), Color::Reset, Color::Reset));
}
