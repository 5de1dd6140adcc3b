//! Draws the workbench as a terminal would show it, settled, into a PNG: every cell 8×16 pixels,
//! half blocks as two colours, text in the labels' 5×7 font. The README's picture of the
//! workbench is made with
//! `cargo run --release --example workbench_picture -- docs/workbench.png sphere-on-plane-dimples`.

use bumpwork::label_font::{GLYPH_HEIGHT, GLYPH_WIDTH, glyph};
use bumpwork::term::{Cell, Color, ColorChoice, ColorMode};
use bumpwork::tui::{App, Screen, WorkbenchOptions};
use std::io::BufWriter;

const COLS: u16 = 100;
const ROWS: u16 = 30;
const CELL_W: u32 = 8;
const CELL_H: u32 = 16;

fn main() {
    let mut args = std::env::args().skip(1);
    let output = args
        .next()
        .expect("usage: workbench_picture OUT.png [SCENE]");
    let scene = args
        .next()
        .unwrap_or_else(|| "sphere-on-plane-dimples".into());
    let options = WorkbenchOptions {
        scenes: vec![scene],
        watch: false,
        colors: ColorChoice::Fixed(ColorMode::TrueColor),
        ..WorkbenchOptions::default()
    };
    let mut app = App::new(&options, ColorMode::TrueColor).expect("the scene loads");
    let mut screen = Screen::new(COLS, ROWS);
    let mut sink = Vec::new();
    screen.draw(&mut app, &mut sink).unwrap();
    while screen.refining(&app) {
        screen.refine(&mut app, &mut sink).unwrap();
    }
    let grid = screen.compose(&app);
    let (width, height) = (COLS as u32 * CELL_W, ROWS as u32 * CELL_H);
    let mut pixels = vec![0u8; (width * height * 3) as usize];
    for row in 0..ROWS as usize {
        for (col, cell) in grid.row(row).iter().enumerate() {
            paint(
                cell,
                col as u32 * CELL_W,
                row as u32 * CELL_H,
                width,
                &mut pixels,
            );
        }
    }
    let file = std::fs::File::create(&output).expect("the output can be written");
    let mut encoder = png::Encoder::new(BufWriter::new(file), width, height);
    encoder.set_color(png::ColorType::Rgb);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(&pixels).unwrap();
}

fn rgb(color: Color, default: [u8; 3]) -> [u8; 3] {
    match color {
        Color::Rgb(r, g, b) => [r, g, b],
        Color::Indexed(i) => bumpwork::term::palette::xterm256_rgb(i),
        Color::Default => default,
    }
}

/// One cell at (`x`, `y`): an upper half block as its two colours, anything else as its glyph
/// in the font over the background.
fn paint(cell: &Cell, x: u32, y: u32, width: u32, pixels: &mut [u8]) {
    let fg = rgb(cell.fg, [230, 230, 230]);
    let bg = rgb(cell.bg, [16, 16, 16]);
    let bits = glyph(cell.glyph);
    for dy in 0..CELL_H {
        for dx in 0..CELL_W {
            let on = match cell.glyph {
                '▀' => dy < CELL_H / 2,
                '█' => true,
                _ => {
                    let (gx, gy) = (dx.wrapping_sub(1), dy.wrapping_sub(4));
                    gx < GLYPH_WIDTH && gy < GLYPH_HEIGHT && bits[gy as usize] >> (4 - gx) & 1 == 1
                }
            };
            let at = (((y + dy) * width + x + dx) * 3) as usize;
            pixels[at..at + 3].copy_from_slice(if on { &fg } else { &bg });
        }
    }
}
