//! Key press to finished frame in the workbench at 200×60 cells (key map → state → render → encode
//! → diff write into memory), median and p95; bytes per frame for a full redraw, an orbit step and
//! an idle frame; and chafa's bytes for the same picture at the same size, measured in the same run.
//! Then the picture's quality per colour mode: the first frame and the settled (refined) picture
//! against the 64-sample area average, the time to settle, and chafa's picture of that average.
//! Run: `cargo bench --bench tui_latency`.

use bumpwork::measure::Timing;
use bumpwork::raster::Framebuffer;
use bumpwork::term::cielab::{chroma_and_hue, delta_e};
use bumpwork::term::{
    ColorChoice, ColorMode, EncodeOptions, FrameOptions, GlyphSet, Picture, encode, encode_frame,
};
use bumpwork::tui::{App, Screen, WorkbenchOptions, render_frame};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use glam::Vec3;
use std::process::Command;
use std::time::Instant;

const COLS: u16 = 200;
const ROWS: u16 = 60;
const SCENE: &str = "sphere-on-plane-dimples";
const RUNS: usize = 41;

fn app() -> App {
    app_of(SCENE)
}

fn app_of(scene: &str) -> App {
    let options = WorkbenchOptions {
        scenes: vec![scene.into()],
        colors: ColorChoice::Fixed(ColorMode::TrueColor),
        ..WorkbenchOptions::default()
    };
    App::new(&options, ColorMode::TrueColor).expect("built-in scene")
}

/// Presses `code` and draws: what the event loop does for one key.
fn press_and_draw(app: &mut App, screen: &mut Screen, code: KeyCode, out: &mut Vec<u8>) -> usize {
    app.key(&KeyEvent::new(code, KeyModifiers::NONE));
    out.clear();
    screen.draw(app, out).expect("writing to memory")
}

fn main() {
    let mut app = app();
    let mut screen = Screen::new(COLS, ROWS);
    let mut out = Vec::new();
    println!("workbench, {SCENE}, {COLS}x{ROWS} cells, truecolor half blocks, {RUNS} runs");

    let mut full_bytes = 0;
    let full = Timing::measure(2, RUNS, || {
        screen.invalidate(&mut app);
        out.clear();
        full_bytes = screen.draw(&mut app, &mut out).unwrap();
    });
    let mut orbit_bytes = Vec::new();
    let orbit = Timing::measure(2, RUNS, || {
        orbit_bytes.push(press_and_draw(
            &mut app,
            &mut screen,
            KeyCode::Char('l'),
            &mut out,
        ));
    });
    orbit_bytes.sort();
    let mut idle_bytes = 0;
    let idle = Timing::measure(2, RUNS, || {
        out.clear();
        idle_bytes = screen.draw(&mut app, &mut out).unwrap();
    });
    let ms = |t: &Timing| {
        format!(
            "median {:.2} ms, p95 {:.2} ms",
            t.median.as_secs_f64() * 1e3,
            t.p95.as_secs_f64() * 1e3
        )
    };
    println!("full redraw   {:<32} {full_bytes:>8} B", ms(&full));
    println!(
        "orbit step    {:<32} {:>8} B (median; {}–{})",
        ms(&orbit),
        orbit_bytes[orbit_bytes.len() / 2],
        orbit_bytes[0],
        orbit_bytes[orbit_bytes.len() - 1]
    );
    println!("idle          {:<32} {idle_bytes:>8} B", ms(&idle));
    compare_with_chafa(&app);
    picture_quality();
}

/// chafa's half-block picture of the image at `path`, stretched to `cells`, in `colours` (its
/// `--colors` name).
fn run_chafa(
    path: &std::path::Path,
    (cols, rows): (usize, usize),
    colours: &str,
) -> std::io::Result<std::process::Output> {
    Command::new("chafa")
        .args(["--symbols", "half", "--colors", colours, "-f", "symbols"])
        .args([
            "--animate",
            "off",
            "--stretch",
            "--size",
            &format!("{cols}x{rows}"),
        ])
        .arg(path)
        .output()
}

/// The picture alone (no status line), ours as a full frame and chafa's, from the same pixels.
fn compare_with_chafa(app: &App) {
    let (cols, rows) = (COLS as usize, ROWS as usize - 1);
    let (width, height) = GlyphSet::HalfBlock.picture_size(cols, rows);
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    render_frame(&app.view(), width as u32, height as u32, &mut framebuffer);
    let pixels = framebuffer.to_srgb8();
    let picture = Picture::new(&pixels, width, height).unwrap();
    let grid = encode(
        &picture,
        EncodeOptions::new(ColorMode::TrueColor, GlyphSet::HalfBlock),
    );
    let mut ours = Vec::new();
    encode_frame(None, &grid, FrameOptions::default(), &mut ours);
    let temp = tempfile::tempdir().expect("a temporary directory");
    let path = temp.path().join("picture.png");
    bumpwork::export::write_png(&framebuffer, &path).expect("temp PNG");
    let start = Instant::now();
    let chafa = run_chafa(&path, (cols, rows), "full");
    let elapsed = start.elapsed();
    println!("\nsame {width}x{height} picture, {cols}x{rows} cells, full frame:");
    println!("bumpwork      {:>8} B", ours.len());
    match chafa {
        Ok(o) if o.status.success() => println!(
            "chafa         {:>8} B ({:.1} ms; --symbols half --colors full) → bumpwork is {:.0}% of chafa",
            o.stdout.len(),
            elapsed.as_secs_f64() * 1e3,
            100.0 * ours.len() as f64 / o.stdout.len() as f64
        ),
        Ok(o) => println!(
            "chafa failed: {}",
            String::from_utf8_lossy(&o.stderr).trim()
        ),
        Err(e) => println!("chafa not run ({e}); install it to compare"),
    }
}

/// Cells of the picture-quality comparison: the 160 × 50 picture rows plus the status
/// line.
const QUALITY_COLS: u16 = 160;
const QUALITY_ROWS: u16 = 51;
/// Samples per sub-pixel side of the reference: 8 × 8, box-averaged in linear light.
const REFERENCE_GRID: usize = 8;

/// The sub-pixels a terminal shows after `bytes`, read back through a terminal emulator (vt100):
/// half blocks (`▀` foreground on top, background below, and the other three glyphs).
fn shown_sub_pixels(bytes: &[u8], cols: usize, rows: usize) -> Vec<[u8; 3]> {
    let side = |n: usize| std::num::NonZero::new(n as u16).expect("a screen of at least one cell");
    let mut parser = vt100::Parser::new(side(rows + 1), side(cols), 0);
    parser.process(bytes);
    let screen = parser.screen();
    let rgb = |colour: vt100::Color, default: [u8; 3]| match colour {
        vt100::Color::Rgb(r, g, b) => [r, g, b],
        vt100::Color::Idx(i) => bumpwork::term::palette::xterm256_rgb(i),
        vt100::Color::Default => default,
    };
    let mut pixels = vec![[0; 3]; cols * rows * 2];
    for row in 0..rows {
        for col in 0..cols {
            let Some(cell) = screen.cell(row as u16, col as u16) else {
                continue;
            };
            let (fg, bg) = (rgb(cell.fgcolor(), [229; 3]), rgb(cell.bgcolor(), [0; 3]));
            let (top, bottom) = match cell.contents().chars().next() {
                Some('▀') => (fg, bg),
                Some('▄') => (bg, fg),
                Some('█') => (fg, fg),
                _ => (bg, bg),
            };
            pixels[(2 * row) * cols + col] = top;
            pixels[(2 * row + 1) * cols + col] = bottom;
        }
    }
    pixels
}

/// Mean CIE76 colour difference (ΔE*ab, D65) between two pictures of 8-bit sRGB: about 2.3 is
/// a difference just seen side by side.
fn mean_delta_e(a: &[[u8; 3]], b: &[[u8; 3]]) -> f64 {
    let total: f64 = a.iter().zip(b).map(|(p, q)| delta_e(*p, *q)).sum();
    total / a.len() as f64
}

/// `pixels` (`size`) averaged over 2×2 blocks in linear light: a dithered picture as the eye sees
/// it from a little further off.
fn blurred(pixels: &[[u8; 3]], (width, height): (usize, usize)) -> Vec<[u8; 3]> {
    let linear = |v: u8| bumpwork::texture::srgb_to_linear(f32::from(v) / 255.0);
    (0..(width / 2) * (height / 2))
        .map(|i| {
            let (x, y) = (2 * (i % (width / 2)), 2 * (i / (width / 2)));
            let block =
                [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(dx, dy)| pixels[(y + dy) * width + x + dx]);
            std::array::from_fn(|c| {
                let mean = block.iter().map(|p| linear(p[c])).sum::<f32>() / 4.0;
                bumpwork::raster::linear_to_srgb8(mean)
            })
        })
        .collect()
}

/// PSNR and mean ΔE of `shown` against `reference`, sub-pixel by sub-pixel and over 2×2 blocks,
/// and how well 4×4 blocks keep the reference's hue.
fn fidelity(shown: &[[u8; 3]], reference: &[[u8; 3]], size: (usize, usize)) -> String {
    let (a, b) = (blurred(shown, size), blurred(reference, size));
    let half = (size.0 / 2, size.1 / 2);
    let (hue_error, chroma_kept) = hue_kept(&blurred(&a, half), &blurred(&b, half));
    format!(
        "{:.1} dB, ΔE {:.2}; 2×2 {:.1} dB, ΔE {:.2}; 4×4 hue off {hue_error:.0}°, chroma {:.0} %",
        psnr(shown, reference),
        mean_delta_e(shown, reference),
        psnr(&a, &b),
        mean_delta_e(&a, &b),
        chroma_kept * 100.0
    )
}

/// Over the blocks whose reference colour has a hue (C*ab ≥ 10): the mean hue angle error, and
/// the shown chroma as a fraction of the reference's.
fn hue_kept(shown: &[[u8; 3]], reference: &[[u8; 3]]) -> (f64, f64) {
    let (mut angle, mut chroma, mut reference_chroma, mut count) = (0.0, 0.0, 0.0, 0);
    for (p, q) in shown.iter().zip(reference) {
        let ((cp, hp), (cq, hq)) = (chroma_and_hue(*p), chroma_and_hue(*q));
        if cq >= 10.0 {
            angle += ((hp - hq + 180.0).rem_euclid(360.0) - 180.0).abs();
            chroma += cp;
            reference_chroma += cq;
            count += 1;
        }
    }
    (
        angle / count.max(1) as f64,
        chroma / reference_chroma.max(1e-9),
    )
}

fn psnr(a: &[[u8; 3]], b: &[[u8; 3]]) -> f64 {
    let squared: f64 = a
        .iter()
        .zip(b)
        .flat_map(|(p, q)| (0..3).map(move |i| (f64::from(p[i]) - f64::from(q[i])).powi(2)))
        .sum();
    let mse = squared / (a.len() * 3) as f64;
    10.0 * (255.0f64.powi(2) / mse.max(1e-9)).log10()
}

/// The view's sub-pixels averaged from `REFERENCE_GRID`² samples each, as 8-bit sRGB.
fn reference_picture(app: &App, width: usize, height: usize) -> Vec<[u8; 3]> {
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let (w, h) = (width * REFERENCE_GRID, height * REFERENCE_GRID);
    render_frame(&app.view(), w as u32, h as u32, &mut framebuffer);
    let colour = framebuffer.color();
    let per = (REFERENCE_GRID * REFERENCE_GRID) as f32;
    (0..width * height)
        .map(|i| {
            let (x, y) = (i % width, i / width);
            let sum: Vec3 = (0..REFERENCE_GRID * REFERENCE_GRID)
                .map(|k| {
                    let (dx, dy) = (k % REFERENCE_GRID, k / REFERENCE_GRID);
                    colour[(y * REFERENCE_GRID + dy) * w + x * REFERENCE_GRID + dx]
                })
                .sum();
            (sum / per)
                .to_array()
                .map(bumpwork::raster::linear_to_srgb8)
        })
        .collect()
}

/// With `BUMPWORK_SAVE_PICTURES=DIR`, writes `pixels` (sRGB, `size`) as `DIR/NAME.png`, to look at.
fn save_picture(pixels: &[[u8; 3]], size: (usize, usize), name: &str) {
    let Some(dir) = std::env::var_os("BUMPWORK_SAVE_PICTURES") else {
        return;
    };
    let mut framebuffer = Framebuffer::new(size.0 as u32, size.1 as u32, Vec3::ZERO);
    for (pixel, rgb) in framebuffer.color_mut().iter_mut().zip(pixels) {
        *pixel =
            Vec3::from_array(rgb.map(|v| bumpwork::texture::srgb_to_linear(f32::from(v) / 255.0)));
    }
    let path = std::path::Path::new(&dir).join(format!("{name}.png"));
    bumpwork::export::write_png(&framebuffer, &path).expect("writing the picture");
}

/// chafa's picture of the reference still in `colours` (its `--colors` name), read back.
fn chafa_sub_pixels(
    reference: &[[u8; 3]],
    size: (usize, usize),
    colours: &str,
) -> Option<Vec<[u8; 3]>> {
    let (width, height) = size;
    let (cols, rows) = (width, height / 2);
    let mut framebuffer = Framebuffer::new(width as u32, height as u32, Vec3::ZERO);
    for (pixel, rgb) in framebuffer.color_mut().iter_mut().zip(reference) {
        *pixel =
            Vec3::from_array(rgb.map(|v| bumpwork::texture::srgb_to_linear(f32::from(v) / 255.0)));
    }
    let temp = tempfile::tempdir().ok()?;
    let path = temp.path().join("picture.png");
    bumpwork::export::write_png(&framebuffer, &path).ok()?;
    let output = run_chafa(&path, (cols, rows), colours);
    let output = output.ok().filter(|o| o.status.success())?;
    // chafa ends lines with LF alone; a terminal's line discipline adds the carriage return.
    let lines = String::from_utf8_lossy(&output.stdout).replace('\n', "\r\n");
    let shown = shown_sub_pixels(lines.as_bytes(), cols, rows);
    save_picture(&shown, size, &format!("chafa-{colours}"));
    save_picture(reference, size, "reference");
    Some(shown)
}

/// From a change to the settled picture: the first frame's and the settled picture's PSNR against
/// the 64-sample area average, the time to settle, the bytes written on the way, and chafa's
/// PSNR given the reference itself, per colour mode.
fn picture_quality() {
    for scene in [SCENE, "textured-sphere"] {
        picture_quality_of(scene);
    }
}

fn picture_quality_of(scene: &str) {
    let (cols, rows) = (QUALITY_COLS as usize, QUALITY_ROWS as usize - 1);
    let size = GlyphSet::HalfBlock.picture_size(cols, rows);
    println!(
        "\npicture quality, {scene}, {cols}x{rows} cells of half blocks, against the {}-sample area average:",
        REFERENCE_GRID * REFERENCE_GRID
    );
    let mut app = app_of(scene);
    let reference = reference_picture(&app, size.0, size.1);
    for (mode, chafa_name) in [
        (ColorMode::TrueColor, "full"),
        (ColorMode::Ansi256, "256"),
        (ColorMode::Ansi16, "16"),
    ] {
        app.set_colors(mode);
        let mut settle_times = Vec::new();
        let mut result = (0.0, String::new(), 0);
        for _ in 0..5 {
            let mut screen = Screen::new(QUALITY_COLS, QUALITY_ROWS);
            let mut bytes = Vec::new();
            app.invalidate();
            let start = Instant::now();
            screen.draw(&mut app, &mut bytes).unwrap();
            let first = psnr(&shown_sub_pixels(&bytes, cols, rows), &reference);
            while screen.refining(&app) {
                screen.refine(&mut app, &mut bytes).unwrap();
            }
            settle_times.push(start.elapsed());
            let shown = shown_sub_pixels(&bytes, cols, rows);
            save_picture(&shown, size, &format!("{scene}-{mode:?}"));
            result = (first, fidelity(&shown, &reference, size), bytes.len());
        }
        settle_times.sort();
        let chafa = match chafa_sub_pixels(&reference, size, chafa_name) {
            Some(pixels) => fidelity(&pixels, &reference, size),
            None => "not run (apt-get install chafa)".into(),
        };
        println!(
            "{:<10} first frame {:.1} dB, settled {} in {:.0} ms (median of 5; {:.0}–{:.0}), {} B written\n{:<10} chafa --colors {chafa_name}: {chafa}",
            format!("{mode:?}"),
            result.0,
            result.1,
            settle_times[2].as_secs_f64() * 1e3,
            settle_times[0].as_secs_f64() * 1e3,
            settle_times[4].as_secs_f64() * 1e3,
            result.2,
            "",
        );
    }
    app.set_colors(ColorMode::TrueColor);
    slow_link_refinement(&mut app, &reference, size);
}

/// Refinement as a slow link gets it (the settled picture alone after the first, only its cells
/// that move visibly): the settled picture's fidelity and its bytes beside the first frame's.
fn slow_link_refinement(app: &mut App, reference: &[[u8; 3]], size: (usize, usize)) {
    let (cols, rows) = (QUALITY_COLS as usize, QUALITY_ROWS as usize - 1);
    let mut screen = Screen::new(QUALITY_COLS, QUALITY_ROWS);
    screen.send_settled_only(true);
    let mut bytes = Vec::new();
    app.invalidate();
    screen.draw(app, &mut bytes).unwrap();
    let first = bytes.len();
    let mut frames = 1;
    while screen.refining(app) {
        frames += usize::from(screen.refine(app, &mut bytes).unwrap() > 0);
    }
    let shown = shown_sub_pixels(&bytes, cols, rows);
    println!(
        "{:<10} over a slow link: settled {}; first frame {first} B, then {} B in {} frame(s) ({:.0} % of the first)",
        "TrueColor",
        fidelity(&shown, reference, size),
        bytes.len() - first,
        frames - 1,
        100.0 * (bytes.len() - first) as f64 / first as f64
    );
}
