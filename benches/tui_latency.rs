//! Key press to finished frame in the workbench at 200×60 cells (key map → state → render → encode
//! → diff write into memory), median and p95; bytes per frame for a full redraw, an orbit step and
//! an idle frame; and chafa's bytes for the same picture at the same size, measured in the same run.
//! Run: `cargo bench --bench tui_latency`.

use bumpwork::measure::Timing;
use bumpwork::raster::Framebuffer;
use bumpwork::term::{
    ColorChoice, ColorMode, EncodeOptions, FrameOptions, GlyphSet, Picture, encode, encode_frame,
};
use bumpwork::tui::{App, Screen, View, WorkbenchOptions, keymap, render_frame};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use glam::Vec3;
use std::process::Command;
use std::time::Instant;

const COLS: u16 = 200;
const ROWS: u16 = 60;
const SCENE: &str = "sphere-on-plane-dimples";
const RUNS: usize = 41;

fn app() -> App {
    let options = WorkbenchOptions {
        scenes: vec![SCENE.into()],
        colors: ColorChoice::Fixed(ColorMode::TrueColor),
        ..WorkbenchOptions::default()
    };
    App::new(&options, ColorMode::TrueColor).expect("built-in scene")
}

/// Presses `code` and draws: what the event loop does for one key.
fn press_and_draw(app: &mut App, screen: &mut Screen, code: KeyCode, out: &mut Vec<u8>) -> usize {
    let key = KeyEvent::new(code, KeyModifiers::NONE);
    if let Some(action) = keymap::action_for(&key) {
        app.apply(action);
    }
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
}

/// The picture alone (no status line), ours as a full frame and chafa's, from the same pixels.
fn compare_with_chafa(app: &App) {
    let (cols, rows) = (COLS as usize, ROWS as usize - 1);
    let (width, height) = GlyphSet::HalfBlock.picture_size(cols, rows);
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    render_frame(
        &View::of(app),
        width as u32,
        height as u32,
        &mut framebuffer,
    );
    let pixels = framebuffer.to_srgb8();
    let picture = Picture::new(&pixels, width, height).unwrap();
    let grid = encode(
        &picture,
        EncodeOptions::new(ColorMode::TrueColor, GlyphSet::HalfBlock),
    );
    let mut ours = Vec::new();
    encode_frame(None, &grid, FrameOptions::default(), &mut ours);
    let path = std::env::temp_dir().join(format!("bumpwork-tui-bench-{}.png", std::process::id()));
    bumpwork::export::write_png(&framebuffer, &path).expect("temp PNG");
    let start = Instant::now();
    let chafa = Command::new("chafa")
        .args(["--symbols", "half", "--colors", "full", "-f", "symbols"])
        .args([
            "--animate",
            "off",
            "--stretch",
            "--size",
            &format!("{cols}x{rows}"),
        ])
        .arg(&path)
        .output();
    let elapsed = start.elapsed();
    let _ = std::fs::remove_file(&path);
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
