//! The ANSI writer, replayed into a virtual terminal (vt100): what it draws equals the grid, an unchanged
//! frame writes nothing, a small change writes little.

use std::io::{self, Write};

use bumpwork::term::{
    CUT_FRAME_END, Cell, CellGrid, Color, ColorMode, EncodeOptions, FrameOptions, FrameWriter,
    GlyphSet, Picture, SYNC_BEGIN, SYNC_END, encode, encode_frame,
};

fn frame(previous: Option<&CellGrid>, next: &CellGrid, origin: (u16, u16)) -> Vec<u8> {
    frame_with(
        previous,
        next,
        FrameOptions {
            origin,
            repeat: false,
        },
    )
}

fn frame_with(previous: Option<&CellGrid>, next: &CellGrid, options: FrameOptions) -> Vec<u8> {
    let mut out = Vec::new();
    encode_frame(previous, next, options, &mut out);
    out
}

fn virtual_terminal(rows: u16, cols: u16) -> vt100::Parser {
    let nonzero = |n: u16| std::num::NonZero::new(n).expect("screen size is not zero");
    vt100::Parser::new(nonzero(rows), nonzero(cols), 0)
}

fn from_vt100(color: vt100::Color) -> Color {
    match color {
        vt100::Color::Default => Color::Default,
        vt100::Color::Idx(i) => Color::Indexed(i),
        vt100::Color::Rgb(r, g, b) => Color::Rgb(r, g, b),
    }
}

fn screen_cell(screen: &vt100::Screen, row: u16, col: u16) -> Cell {
    let cell = screen.cell(row, col).expect("cell on screen");
    let glyph = cell.contents().chars().next().unwrap_or(' ');
    Cell {
        glyph,
        fg: from_vt100(cell.fgcolor()),
        bg: from_vt100(cell.bgcolor()),
    }
}

/// Asserts every grid cell looks the same on the virtual screen, placed at `origin`.
fn assert_screen_shows(screen: &vt100::Screen, grid: &CellGrid, origin: (u16, u16)) {
    for y in 0..grid.rows() {
        for x in 0..grid.cols() {
            let shown = screen_cell(screen, origin.1 + y as u16, origin.0 + x as u16);
            let wanted = grid.get(x, y);
            assert!(
                shown.looks_same(wanted),
                "cell {x},{y}: screen {shown:?}, grid {wanted:?}"
            );
        }
    }
}

/// A smooth-shaded disc, so neighbouring cells share colours as in a real frame.
fn shaded_picture(width: usize, height: usize, phase: f32) -> Vec<[u8; 3]> {
    let mut pixels = Vec::with_capacity(width * height);
    for y in 0..height {
        for x in 0..width {
            let (u, v) = (
                (x as f32 + 0.5) / width as f32 - 0.5,
                (y as f32 + 0.5) / height as f32 - 0.5,
            );
            let r2 = (u * u + v * v) * 4.0;
            let lit = if r2 < 1.0 {
                (1.0 - r2).sqrt() * (0.6 + 0.4 * (u * 9.0 + phase).sin())
            } else {
                0.1
            };
            let shade = (lit.clamp(0.0, 1.0) * 255.0) as u8;
            pixels.push([shade, shade / 2 + 20, 255 - shade]);
        }
    }
    pixels
}

fn encoded(
    width: usize,
    height: usize,
    phase: f32,
    colors: ColorMode,
    glyphs: GlyphSet,
) -> CellGrid {
    let pixels = shaded_picture(width, height, phase);
    encode(
        &Picture::new(&pixels, width, height).unwrap(),
        EncodeOptions::new(colors, glyphs),
    )
}

const ALL_MODES: [ColorMode; 4] = [
    ColorMode::TrueColor,
    ColorMode::Ansi256,
    ColorMode::Ansi16,
    ColorMode::Monochrome,
];

#[test]
fn full_frame_replays_to_the_grid_in_every_mode() {
    for colors in ALL_MODES {
        for glyphs in [GlyphSet::HalfBlock, GlyphSet::Quadrant, GlyphSet::Sextant] {
            let grid = encoded(40, 24, 0.0, colors, glyphs);
            for repeat in [false, true] {
                let origin = (3, 2);
                let bytes = frame_with(None, &grid, FrameOptions { origin, repeat });
                assert!(bytes.starts_with(SYNC_BEGIN) && bytes.ends_with(SYNC_END));
                let mut vt = virtual_terminal(30, 60);
                vt.process(&bytes);
                assert_screen_shows(vt.screen(), &grid, origin);
                // Nothing is drawn outside the grid.
                assert_eq!(screen_cell(vt.screen(), 1, 3), Cell::solid(Color::Default));
                assert_eq!(screen_cell(vt.screen(), 2, 2), Cell::solid(Color::Default));
            }
        }
    }
}

#[test]
fn an_unchanged_frame_writes_nothing() {
    for colors in ALL_MODES {
        let grid = encoded(40, 24, 0.0, colors, GlyphSet::HalfBlock);
        assert!(frame(Some(&grid), &grid, (0, 0)).is_empty(), "{colors:?}");
    }
}

#[test]
fn one_changed_cell_writes_a_few_bytes_and_replays_to_the_new_grid() {
    let old = encoded(40, 24, 0.0, ColorMode::TrueColor, GlyphSet::HalfBlock);
    let mut new = old.clone();
    new.set(
        17,
        5,
        Cell {
            glyph: '▀',
            fg: Color::Rgb(1, 2, 3),
            bg: Color::Rgb(200, 201, 202),
        },
    );
    let diff = frame(Some(&old), &new, (0, 0));
    // sync (8) + move (7) + two truecolor colours (≤ 38) + glyph (3) + reset (3) + sync (8)
    assert!(
        diff.len() <= 67,
        "{} bytes: {:?}",
        diff.len(),
        String::from_utf8_lossy(&diff)
    );
    let mut vt = virtual_terminal(12, 40);
    vt.process(&frame(None, &old, (0, 0)));
    vt.process(&diff);
    assert_screen_shows(vt.screen(), &new, (0, 0));
}

#[test]
fn diffs_between_random_grids_replay_exactly() {
    let mut seed = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let glyphs = [' ', '█', '▀', '▄', '▌', '▚', '▟', '\u{1FB0A}'];
    let random_cell = |change: u64| {
        let colour = |v: u64| match v % 4 {
            0 => Color::Default,
            1 => Color::Indexed((v >> 8) as u8 % 4),
            2 => Color::Indexed(8 + (v >> 8) as u8 % 8),
            _ => Color::Rgb((v >> 8) as u8 % 2 * 255, 0, (v >> 16) as u8 % 2 * 255),
        };
        Cell {
            glyph: glyphs[(change % 8) as usize],
            fg: colour(change >> 3),
            bg: colour(change >> 24),
        }
    };
    for round in 0..200 {
        // The grid's right edge is the screen's when round is even: exercises the pending wrap.
        let (cols, rows) = (12usize, 6usize);
        let screen_cols = if round % 2 == 0 { 12 } else { 15 };
        let mut old = CellGrid::new(cols, rows);
        let mut new = CellGrid::new(cols, rows);
        for y in 0..rows {
            for x in 0..cols {
                let cell = random_cell(next());
                old.set(x, y, cell);
                new.set(
                    x,
                    y,
                    if next() % 3 == 0 {
                        random_cell(next())
                    } else {
                        cell
                    },
                );
            }
        }
        let options = FrameOptions {
            origin: (screen_cols - cols as u16, 1),
            repeat: round % 4 < 2,
        };
        let mut vt = virtual_terminal(rows as u16 + 2, screen_cols);
        vt.process(&frame_with(None, &old, options));
        assert_screen_shows(vt.screen(), &old, options.origin);
        vt.process(&frame_with(Some(&old), &new, options));
        assert_screen_shows(vt.screen(), &new, options.origin);
    }
}

#[test]
fn a_small_motion_writes_far_less_than_a_full_frame() {
    let old = encoded(80, 48, 0.0, ColorMode::Ansi256, GlyphSet::HalfBlock);
    let new = encoded(80, 48, 0.05, ColorMode::Ansi256, GlyphSet::HalfBlock);
    let full = frame(None, &new, (0, 0));
    let diff = frame(Some(&old), &new, (0, 0));
    // The stripes move across most of the picture; only the cells whose colour or dither changed
    // are written again.
    assert!(
        diff.len() * 5 < full.len() * 3,
        "diff {} full {}",
        diff.len(),
        full.len()
    );
    let mut vt = virtual_terminal(24, 80);
    vt.process(&frame(None, &old, (0, 0)));
    vt.process(&diff);
    assert_screen_shows(vt.screen(), &new, (0, 0));
}

#[test]
fn solid_cells_cost_one_byte_once_the_colour_is_set() {
    let mut grid = CellGrid::new(10, 1);
    for x in 0..10 {
        grid.set(x, 0, Cell::solid(Color::Indexed(200)));
    }
    let bytes = frame(None, &grid, (0, 0));
    let text = String::from_utf8(bytes).unwrap();
    assert_eq!(
        text,
        "\x1b[?2026h\x1b[H\x1b[48;5;200m          \x1b[m\x1b[?2026l"
    );
}

#[test]
fn runs_of_identical_solid_cells_are_repeated_as_spaces_when_allowed() {
    let mut grid = CellGrid::new(14, 1);
    for x in 0..14 {
        let cell = match x {
            0..10 => Cell {
                glyph: '█',
                fg: Color::Indexed(1),
                bg: Color::Indexed(2),
            },
            // Runs of other glyphs are drawn out (tmux would not repeat them), here as '▀' over the
            // red background the pen already has.
            _ => Cell {
                glyph: '▄',
                fg: Color::Indexed(1),
                bg: Color::Indexed(2),
            },
        };
        grid.set(x, 0, cell);
    }
    let options = FrameOptions {
        origin: (0, 0),
        repeat: true,
    };
    let text = String::from_utf8(frame_with(None, &grid, options)).unwrap();
    assert_eq!(
        text,
        "\x1b[?2026h\x1b[H\x1b[41m \x1b[9b\x1b[32m▀▀▀▀\x1b[m\x1b[?2026l"
    );
    let mut vt = virtual_terminal(2, 14);
    vt.process(text.as_bytes());
    assert_screen_shows(vt.screen(), &grid, (0, 0));
}

struct DeadTerminal;

impl Write for DeadTerminal {
    fn write(&mut self, _: &[u8]) -> io::Result<usize> {
        Err(io::Error::from_raw_os_error(5)) // EIO, as after SIGHUP
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

#[test]
fn frame_writer_sends_diffs_and_recovers_from_a_failed_write() {
    let a = encoded(20, 10, 0.0, ColorMode::TrueColor, GlyphSet::HalfBlock);
    let b = encoded(20, 10, 0.3, ColorMode::TrueColor, GlyphSet::HalfBlock);
    let mut writer = FrameWriter::new((0, 0));
    let mut screen = Vec::new();
    let full = writer.draw(&mut screen, &a).unwrap();
    assert_eq!(full, screen.len());
    assert_eq!(writer.draw(&mut screen, &a).unwrap(), 0);
    assert!(writer.draw(&mut DeadTerminal, &b).is_err());
    // After the failed write the screen is unknown: the next frame is drawn in full.
    let mut after = Vec::new();
    writer.draw(&mut after, &b).unwrap();
    assert_eq!(after, frame(None, &b, (0, 0)));
}

#[test]
fn a_frame_cut_at_a_row_shows_the_rows_before_and_the_next_frame_sends_the_rest() {
    let a = encoded(20, 10, 0.0, ColorMode::TrueColor, GlyphSet::HalfBlock);
    let b = encoded(20, 10, 0.3, ColorMode::TrueColor, GlyphSet::HalfBlock);
    let mut terminal = virtual_terminal(10, 20);
    let mut writer = FrameWriter::new((0, 0));
    let mut bytes = Vec::new();
    writer.draw(&mut bytes, &a).unwrap();
    terminal.process(&bytes);
    bytes.clear();
    let whole = writer.draw(&mut bytes, &b).unwrap();
    let points = writer.cut_points().to_vec();
    assert!(points.len() >= 4, "{} rows change", points.len());
    assert!(
        points
            .windows(2)
            .all(|w| w[0].0 < w[1].0 && w[0].1 < w[1].1)
    );
    let (at, row) = points[points.len() / 2];
    let mut cut = bytes[..at].to_vec();
    cut.extend_from_slice(CUT_FRAME_END);
    terminal.process(&cut);
    let mut expected = a.clone();
    expected.copy_rows_from(&b, 0);
    expected.copy_rows_from(&a, row);
    assert_screen_shows(terminal.screen(), &expected, (0, 0));
    writer.cut_before_row(row);
    bytes.clear();
    let rest = writer.draw(&mut bytes, &b).unwrap();
    terminal.process(&bytes);
    assert_screen_shows(terminal.screen(), &b, (0, 0));
    // The rows from the cut on, with a fresh cursor move and colours: nothing before the cut.
    assert!(
        rest <= whole - at + 64,
        "the rest ({rest} B) resends rows already drawn (whole {whole} B, cut at {at})"
    );
}
